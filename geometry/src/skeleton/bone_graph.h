// Internal: the refinement steps that turn the dense skeleton into bones.
#pragma once

#include "dense_graph.h"
#include "skeleton_contour.h"

#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <algorithm>
#include <functional>
#include <vector>

namespace finbook::geometry::detail {

// A bone may stray at most this fraction of the local clearance from the skeleton it
// replaces: the rest of the inscribed disk is the margin that keeps it inside the shape.
inline constexpr double kBoundFraction = 0.5;

// Contour lookup by polygon; empty for a degenerate raw skeleton (no inside tests then).
class Contours {
public:
    // margin: the least distance (px) a new bone keeps from the outline, whatever the width.
    explicit Contours(const Region &region, double margin = 0.0)
        : m_margin(margin)
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
               index.segmentDistance(a, b) >=
                   std::min(std::max(m_margin, kBoundFraction * std::min(clearanceA, clearanceB)),
                            std::min(clearanceA, clearanceB));
    }

private:
    std::vector<ContourIndex> m_index;
    double m_margin = 0.0;
};

inline bool isJunction(const DenseGraph &g, int v)
{
    return g.degree(v) >= 3;
}

// The bone graph: every branch (extractBranches) split into bones by bounded Douglas–Peucker
// (a stretch becomes one bone when every node it replaces lies within
// min(tolerance, kBoundFraction × clearance) of it and it crosses no contour edge; otherwise
// it splits at the node exceeding its bound the most). Branch ends and kept nodes are joints,
// and so are the positions `forced` gives for a branch (indices into branch.nodes).
using ForcedJoints = std::function<std::vector<int>(const Branch &branch)>;
DenseGraph bonesFromBranches(const DenseGraph &g, double tolerance, const Contours &contours,
                             const ForcedJoints &forced = {});

// Collapses bones between two non-terminal joints shorter than `length` or than `relative` ×
// the smaller inscribed radius of their ends, shortest first, where the merged joint keeps
// every neighbouring bone fitting (Contours::boneFits).
void collapseShortBones(DenseGraph &g, double length, double relative, const Contours &contours);

// The `relative` of collapseShortBones for the clean-up by default: a bone shorter than half
// the width at its ends is no bone an animator would turn.
inline constexpr double kTinyBone = 0.5;

} // namespace finbook::geometry::detail
