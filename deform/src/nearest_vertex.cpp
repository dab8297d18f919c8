#include <finbook/deform/nearest_vertex.h>

#include <limits>

namespace finbook::deform {

int nearestVertex(const Eigen::MatrixX2d &V, const Eigen::Vector2d &p)
{
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
        const double distance = (V.row(i).transpose() - p).squaredNorm();
        if (distance < bestDistance) { // NaN rows compare false and are skipped
            bestDistance = distance;
            best = static_cast<int>(i);
        }
    }
    return best;
}

} // namespace finbook::deform
