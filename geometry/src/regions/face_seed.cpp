#include "face_seed.h"

#include "stroke_soup.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace finbook::geometry::detail {
namespace {

constexpr int kScanlines = 15;

template <class Fn> void forEachEdge(const Polygon &polygon, Fn &&fn)
{
    const auto ring = [&](const Eigen::MatrixX2d &r) {
        for (Eigen::Index i = 0, n = r.rows(); i < n; ++i)
            fn(Eigen::Vector2d(r.row(i).transpose()),
               Eigen::Vector2d(r.row((i + 1) % n).transpose()));
    };
    ring(polygon.outer);
    for (const Eigen::MatrixX2d &hole : polygon.holes)
        ring(hole);
}

} // namespace

double boundaryDistance(const Polygon &polygon, const Eigen::Vector2d &p)
{
    double best = std::numeric_limits<double>::max();
    forEachEdge(polygon, [&](const Eigen::Vector2d &a, const Eigen::Vector2d &b) {
        best = std::min(best, (closestOnSegment(p, a, b) - p).norm());
    });
    return best;
}

Eigen::Vector2d interiorSeed(const Polygon &polygon)
{
    if (polygon.outer.rows() == 0)
        return Eigen::Vector2d::Zero();
    const double y0 = polygon.outer.col(1).minCoeff(), y1 = polygon.outer.col(1).maxCoeff();
    Eigen::Vector2d best = polygon.outer.row(0).transpose();
    double bestClearance = -1.0;
    std::vector<double> xs;
    for (int k = 0; k < kScanlines; ++k) {
        // Irregular fractions keep scanlines off the (often integer) vertices.
        const double y = y0 + (y1 - y0) * (k + 0.5 + 0.0137 * (k % 3)) / kScanlines;
        xs.clear();
        forEachEdge(polygon, [&](const Eigen::Vector2d &a, const Eigen::Vector2d &b) {
            if ((a.y() > y) != (b.y() > y))
                xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
        });
        std::sort(xs.begin(), xs.end());
        for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
            if (!(xs[i + 1] > xs[i]))
                continue;
            const Eigen::Vector2d mid(0.5 * (xs[i] + xs[i + 1]), y);
            const double clearance = boundaryDistance(polygon, mid);
            if (clearance > bestClearance) {
                bestClearance = clearance;
                best = mid;
            }
        }
    }
    return best;
}

} // namespace finbook::geometry::detail
