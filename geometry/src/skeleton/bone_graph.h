// Internal: the refinement steps that turn the dense skeleton into bones.
#pragma once

#include "dense_graph.h"
#include "skeleton_contour.h"

#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace finbook::geometry::detail {

// A bone may stray at most this fraction of the local clearance from the skeleton it
// replaces: the rest of the inscribed disk is the margin that keeps it inside the shape.
inline constexpr double kBoundFraction = 0.5;

// Contour lookup by polygon; empty for a degenerate raw skeleton (no inside tests then).
class Contours {
public:
    explicit Contours(const Region &region)
    {
        for (const Polygon &polygon : region)
            m_index.emplace_back(polygon);
    }
    bool segmentInside(int polygon, const Eigen::Vector2d &a, const Eigen::Vector2d &b) const
    {
        return polygon < 0 || std::size_t(polygon) >= m_index.size() ||
               m_index[std::size_t(polygon)].segmentInside(a, b);
    }
    // A new bone a–b (made by a merge or a collapse, not backed by skeleton nodes between its
    // ends) stays within the local width: inside, and at least kBoundFraction of the smaller
    // end clearance away from the outline, the margin the bounded simplification keeps.
    bool boneFits(int polygon, const Eigen::Vector2d &a, double clearanceA,
                  const Eigen::Vector2d &b, double clearanceB) const
    {
        if (polygon < 0 || std::size_t(polygon) >= m_index.size())
            return true;
        const ContourIndex &index = m_index[std::size_t(polygon)];
        return index.segmentInside(a, b) &&
               index.segmentDistance(a, b) >= kBoundFraction * std::min(clearanceA, clearanceB);
    }

private:
    std::vector<ContourIndex> m_index;
};

inline bool isJunction(const DenseGraph &g, int v)
{
    return g.degree(v) >= 3;
}

// The bone graph: every branch (extractBranches) split into bones by bounded Douglas–Peucker
// (a stretch becomes one bone when every node it replaces lies within
// min(tolerance, kBoundFraction × clearance) of it and it crosses no contour edge; otherwise
// it splits at the node exceeding its bound the most). Branch ends and kept nodes are joints.
DenseGraph bonesFromBranches(const DenseGraph &g, double tolerance, const Contours &contours);

// Collapses bones between two non-terminal joints shorter than `length`, shortest first,
// where the merged joint keeps every neighbouring bone fitting (Contours::boneFits).
void collapseShortBones(DenseGraph &g, double length, const Contours &contours);

} // namespace finbook::geometry::detail
