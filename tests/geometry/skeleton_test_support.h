// Shapes and checks shared by the skeleton tests.
#pragma once

#include "geometry_test_support.h"

#include <finbook/geometry/region.h>
#include <finbook/geometry/skeleton/skeleton.h>

#include <Eigen/Geometry>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace finbook::test {

inline geometry::Region regionOf(const Eigen::MatrixX2d &outer)
{
    return {{outer, {}}};
}

// Axis-aligned w × h rectangle centred at c, turned by `angle` radians (positive area).
inline Eigen::MatrixX2d bar(double w, double h, double angle = 0.0,
                            Eigen::RowVector2d c = {0.0, 0.0})
{
    Eigen::MatrixX2d r = rows({{-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}});
    const Eigen::Matrix2d turn = Eigen::Rotation2Dd(angle).toRotationMatrix();
    return (r * turn.transpose()).rowwise() + c;
}

// A plus sign: four arms of width w reaching `reach` from the centre.
inline Eigen::MatrixX2d plusSign(double w, double reach)
{
    const double a = w / 2, b = reach;
    return rows({{-a, -b},
                 {a, -b},
                 {a, -a},
                 {b, -a},
                 {b, a},
                 {a, a},
                 {a, b},
                 {-a, b},
                 {-a, a},
                 {-b, a},
                 {-b, -a},
                 {-a, -a}});
}

inline bool insideRegion(const geometry::Region &region, const Eigen::RowVector2d &p)
{
    bool in = false;
    for (const Eigen::MatrixX2d &ring : geometry::regionRings(region))
        in ^= insideRing(ring, p);
    return in;
}

// Fraction of the bones' total length inside the region, sampled every `spacing` px; 1 when
// there are no bones.
inline double bonesInside(const geometry::Skeleton &s, const geometry::Region &region,
                          double spacing = 0.25)
{
    double inside = 0.0, total = 0.0;
    for (int j = 0; j < s.jointCount(); ++j) {
        if (s.parent(j) < 0)
            continue;
        const Eigen::RowVector2d a = s.joints.row(s.parent(j)), b = s.joints.row(j);
        const double length = (b - a).norm();
        const int samples = std::max(1, int(std::ceil(length / spacing)));
        for (int k = 0; k < samples; ++k) {
            total += length / samples;
            if (insideRegion(region, a + (k + 0.5) / samples * (b - a)))
                inside += length / samples;
        }
    }
    return total > 0.0 ? inside / total : 1.0;
}

// Index of the polygon of `region` containing p, −1 if none.
inline int pieceOf(const geometry::Region &region, const Eigen::RowVector2d &p)
{
    for (std::size_t k = 0; k < region.size(); ++k) {
        if (insideRegion(geometry::Region{region[k]}, p))
            return int(k);
    }
    return -1;
}

// bonesInside without the bones that join separate pieces (polygons of `pieces`), which the
// animator rig draws across the gap between them; `joining` receives their number.
inline double bonesInsidePieces(const geometry::Skeleton &s, const geometry::Region &region,
                                const geometry::Region &pieces, int &joining, double spacing = 0.25)
{
    geometry::Skeleton own = s;
    joining = 0;
    for (int j = 0; j < s.jointCount(); ++j) {
        if (s.parent(j) < 0 || pieces.size() < 2)
            continue;
        const int a = pieceOf(pieces, s.joints.row(s.parent(j)));
        const int b = pieceOf(pieces, s.joints.row(j));
        if (a != b) {
            own.parent(j) = -1;
            ++joining;
        }
    }
    return bonesInside(own, region, spacing);
}

// The bones as unordered pairs of joint positions: the same skeleton whatever the numbering
// and the root.
inline std::set<std::pair<std::pair<double, double>, std::pair<double, double>>>
boneSet(const geometry::Skeleton &s)
{
    std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> bones;
    for (int j = 0; j < s.jointCount(); ++j) {
        if (s.parent(j) < 0)
            continue;
        std::pair<double, double> a{s.joints(j, 0), s.joints(j, 1)};
        std::pair<double, double> b{s.joints(s.parent(j), 0), s.joints(s.parent(j), 1)};
        bones.insert(a < b ? std::pair{a, b} : std::pair{b, a});
    }
    return bones;
}

inline bool identical(const geometry::Skeleton &a, const geometry::Skeleton &b)
{
    return a.joints == b.joints && a.radius == b.radius && a.parent == b.parent &&
           a.part == b.part && a.root == b.root;
}

inline int countKind(const geometry::Skeleton &s, geometry::JointKind kind)
{
    int n = 0;
    for (geometry::JointKind k : geometry::jointKinds(s))
        n += k == kind ? 1 : 0;
    return n;
}

} // namespace finbook::test
