// Thin tips of a shape (issue 21, "thin parts vanish"): the ends of protrusions at most
// kTipWidth of the shape's diagonal wide (tentacle tips, antennae, tines, pen-line ends),
// found on the drawn outline itself, independent of any skeleton. A tip is an outline point
// whose outline, kArmFactor widths along either way, comes back to within one width of itself
// (a hairpin) turning the ring's way (a protrusion, not a slit between two parts); one point
// per hairpin (the farthest out).
#pragma once

#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace finbook::bench {

constexpr double kTipWidth = 0.06; // of the diagonal
constexpr double kArmFactor = 3.0; // arm length along the outline, in widths

// The ring resampled every `spacing` along its length (closed).
inline Eigen::MatrixX2d resampleRing(const Eigen::MatrixX2d &ring, double spacing)
{
    std::vector<Eigen::RowVector2d> out;
    double carry = 0.0;
    for (Eigen::Index i = 0; i < ring.rows(); ++i) {
        const Eigen::RowVector2d a = ring.row(i), b = ring.row((i + 1) % ring.rows());
        const double length = (b - a).norm();
        double t = carry;
        for (; t < length; t += spacing)
            out.push_back(a + (t / length) * (b - a));
        carry = t - length;
    }
    Eigen::MatrixX2d m(Eigen::Index(out.size()), 2);
    for (std::size_t i = 0; i < out.size(); ++i)
        m.row(Eigen::Index(i)) = out[i];
    return m;
}

// Tip points of every ring of `shape` (rings oriented as region.h says).
inline std::vector<Eigen::RowVector2d> thinTips(const geometry::Region &shape)
{
    Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(1e300), hi = -lo;
    for (const Eigen::MatrixX2d &ring : geometry::regionRings(shape)) {
        if (ring.rows() == 0)
            continue;
        lo = lo.cwiseMin(ring.colwise().minCoeff());
        hi = hi.cwiseMax(ring.colwise().maxCoeff());
    }
    const double width = kTipWidth * (hi - lo).norm();
    const double spacing = width / 8.0;
    const int arm = int(std::lround(kArmFactor * width / spacing));
    std::vector<Eigen::RowVector2d> tips;
    if (!(width > 0.0))
        return tips;
    for (const Eigen::MatrixX2d &source : geometry::regionRings(shape)) {
        const Eigen::MatrixX2d ring = resampleRing(source, spacing);
        const int n = int(ring.rows());
        double area = 0.0; // twice the signed area
        for (int i = 0; i < n; ++i) {
            const Eigen::RowVector2d a = ring.row(i), b = ring.row((i + 1) % n);
            area += a.x() * b.y() - b.x() * a.y();
        }
        if (n < 2 * arm + 3)
            continue;
        std::vector<double> reach(std::size_t(n), 0.0); // 0: not a tip candidate
        for (int i = 0; i < n; ++i) {
            const Eigen::RowVector2d a = ring.row((i - arm + n) % n), b = ring.row((i + arm) % n);
            const Eigen::RowVector2d mid = 0.5 * (a + b), p = ring.row(i);
            const double out = (p - mid).norm();
            const Eigen::RowVector2d u = p - a, v = b - p;
            if ((a - b).norm() <= width && out >= 0.7 * kArmFactor * width &&
                (u.x() * v.y() - u.y() * v.x()) * area > 0.0)
                reach[std::size_t(i)] = out;
        }
        // One tip per run of candidates: its farthest point.
        for (int i = 0; i < n; ++i) {
            const double r = reach[std::size_t(i)];
            if (r <= 0.0)
                continue;
            bool best = true;
            for (int k = 1; k <= arm && best; ++k)
                best =
                    reach[std::size_t((i + k) % n)] < r && reach[std::size_t((i - k + n) % n)] <= r;
            if (best)
                tips.push_back(ring.row(i));
        }
    }
    return tips;
}

// Whether a bone (segments parent→joint) comes within `reachFraction` × the tip width of
// the tip: a bone reaches into the protrusion.
inline bool tipReached(const Eigen::RowVector2d &tip, const Eigen::MatrixX2d &from,
                       const Eigen::MatrixX2d &to, double width)
{
    for (Eigen::Index k = 0; k < from.rows(); ++k) {
        const Eigen::RowVector2d a = from.row(k), ab = to.row(k) - from.row(k);
        const double len2 = ab.squaredNorm();
        const double t = len2 > 0.0 ? std::clamp((tip - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
        if ((tip - (a + t * ab)).norm() <= width)
            return true;
    }
    return false;
}

} // namespace finbook::bench
