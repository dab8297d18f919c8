#include <finbook/geometry/mesh_quality.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace finbook::geometry {

Eigen::VectorXd triangleSignedAreas(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    Eigen::VectorXd areas(F.rows());
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const Eigen::RowVector2d a = V.row(F(f, 0));
        const Eigen::RowVector2d u = V.row(F(f, 1)) - a;
        const Eigen::RowVector2d w = V.row(F(f, 2)) - a;
        areas(f) = 0.5 * (u.x() * w.y() - u.y() * w.x());
    }
    return areas;
}

double minAngleDegrees(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    double smallest = M_PI;
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const Eigen::RowVector2d p = V.row(F(f, k));
            const Eigen::RowVector2d u = V.row(F(f, (k + 1) % 3)) - p;
            const Eigen::RowVector2d w = V.row(F(f, (k + 2) % 3)) - p;
            // atan2 of cross and dot stays accurate for tiny and near-straight angles.
            const double angle = std::atan2(std::abs(u.x() * w.y() - u.y() * w.x()), u.dot(w));
            smallest = std::min(smallest, angle);
        }
    }
    return smallest * 180.0 / M_PI;
}

int connectedComponents(const Eigen::MatrixX3i &F, Eigen::Index vertexCount,
                        Eigen::VectorXi *faceComponent)
{
    std::vector<int> parent(static_cast<std::size_t>(vertexCount));
    std::iota(parent.begin(), parent.end(), 0);
    const auto root = [&](int i) {
        while (parent[std::size_t(i)] != i)
            i = parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
        return i;
    };
    for (Eigen::Index f = 0; f < F.rows(); ++f)
        for (int k = 1; k < 3; ++k)
            parent[std::size_t(root(F(f, 0)))] = root(F(f, k));
    std::vector<int> label(static_cast<std::size_t>(vertexCount), -1);
    int count = 0;
    if (faceComponent)
        faceComponent->resize(F.rows());
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        int &l = label[std::size_t(root(F(f, 0)))];
        if (l < 0)
            l = count++;
        if (faceComponent)
            (*faceComponent)(f) = l;
    }
    return count;
}

} // namespace finbook::geometry
