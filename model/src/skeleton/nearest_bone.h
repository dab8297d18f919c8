// The rest bone of a skeleton nearest a point, for the many parts that may hang from one
// skeleton: a bounding-volume tree over the bones, built once per parent (O(J log J)), then
// searched nearest first, so a query over a drawing's skeleton looks at O(log J) bones instead
// of all J. Private to the model (skeleton_join.cpp).
#pragma once

#include <finbook/model/skeleton/skeleton_rig.h>

#include <cstdint>
#include <vector>

namespace finbook::model::join_detail {

// Fraction along a → b of the point nearest p, and the distance to it.
std::pair<double, double> project(QPointF p, QPointF a, QPointF b);

struct NearestBone {
    int joint = -1; // the bone ending at this joint; -1 when no bone has a finite distance
    double t = 0.0; // where along it (0 = its start joint)
};

// Exactly what a scan of every bone in index order keeping the first strictly nearer one
// gives (the rule anchorOn has always used): the least distance, ties to the lowest index.
class BoneIndex {
public:
    // `rig` must be valid (SkeletonRig::isValid) and outlive the index.
    explicit BoneIndex(const SkeletonRig &rig);
    // `work` grows by the bones and tree nodes looked at (the reader bounds it).
    NearestBone nearest(QPointF p, std::int64_t &work) const;

private:
    struct Node {
        double x0, y0, x1, y1; // bounding box of its bones
        int begin, end;        // its bones: m_bones[begin, end)
        int left = -1, right = -1;
    };
    const SkeletonRig &m_rig;
    std::vector<int> m_bones; // joints with a parent, reordered by the tree
    std::vector<Node> m_nodes;
};

// The nearest bone by scanning them all (small skeletons, and the reference for tests).
NearestBone nearestByScan(const SkeletonRig &rig, QPointF p, std::int64_t &work);

} // namespace finbook::model::join_detail
