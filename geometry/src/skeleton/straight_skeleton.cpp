#include "straight_skeleton.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Straight_skeleton_builder_2.h>

#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace finbook::geometry::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Skeleton2 = CGAL::Straight_skeleton_2<Kernel>;
using Traits = CGAL::Straight_skeleton_builder_traits_2<Kernel>;

struct StopBuilding : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Polls the cancel callback on every processed event and bounds the number of events: the
// builder catches what a visitor throws and returns a null skeleton, so this is how a long
// or runaway construction (CGAL#7138) stops early.
struct Visitor : CGAL::Dummy_straight_skeleton_builder_2_visitor<Skeleton2> {
    const CancelCallback *cancelled = nullptr;
    long budget = 0;
    mutable long events = 0;
    mutable bool wasCancelled = false;

    void tick() const
    {
        if (++events > budget)
            throw StopBuilding("event budget exceeded");
        if (*cancelled && (*cancelled)()) {
            wasCancelled = true;
            throw StopBuilding("cancelled");
        }
    }
    void on_edge_event_processed(const Vertex_const_handle &, const Vertex_const_handle &,
                                 const Vertex_const_handle &) const
    {
        tick();
    }
    void on_split_event_processed(const Vertex_const_handle &, const Vertex_const_handle &,
                                  const Vertex_const_handle &) const
    {
        tick();
    }
    void on_pseudo_split_event_processed(const Vertex_const_handle &, const Vertex_const_handle &,
                                         const Vertex_const_handle &,
                                         const Vertex_const_handle &) const
    {
        tick();
    }
};

using Builder = CGAL::Straight_skeleton_builder_2<Traits, Skeleton2, Visitor>;

std::vector<Kernel::Point_2> toPoints(const Eigen::MatrixX2d &ring)
{
    std::vector<Kernel::Point_2> points;
    points.reserve(std::size_t(ring.rows()));
    for (Eigen::Index i = 0; i < ring.rows(); ++i)
        points.emplace_back(ring(i, 0), ring(i, 1));
    return points;
}

} // namespace

StraightSkeletonStatus appendStraightSkeleton(const Polygon &polygon, int polygonIndex,
                                              const CancelCallback &cancelled, DenseGraph &graph)
{
    Visitor visitor;
    visitor.cancelled = &cancelled;
    visitor.budget = 8 * regionVertexCount(Region{polygon}) + 64;
    Builder builder(boost::none, Traits(), visitor);
    const std::vector<Kernel::Point_2> outer = toPoints(polygon.outer);
    builder.enter_contour(outer.begin(), outer.end());
    for (const Eigen::MatrixX2d &hole : polygon.holes) {
        const std::vector<Kernel::Point_2> points = toPoints(hole);
        builder.enter_contour(points.begin(), points.end());
    }
    const auto skeleton = builder.construct_skeleton();
    if (visitor.wasCancelled)
        return StraightSkeletonStatus::Cancelled;
    if (!skeleton)
        return StraightSkeletonStatus::Failed;

    std::unordered_map<int, int> node; // CGAL vertex id → graph node
    auto nodeOf = [&](const Skeleton2::Vertex_const_handle &v) {
        const auto [it, inserted] = node.try_emplace(v->id(), -1);
        if (inserted) {
            const Eigen::Vector2d p(CGAL::to_double(v->point().x()),
                                    CGAL::to_double(v->point().y()));
            it->second = graph.addNode(p, CGAL::to_double(v->time()), 0.0, polygonIndex);
        }
        return it->second;
    };
    for (auto h = skeleton->halfedges_begin(); h != skeleton->halfedges_end(); ++h) {
        // One halfedge of each twin pair; only bisectors between two skeleton vertices:
        // those touching a contour vertex are the peripheral edges.
        if (!h->is_bisector() || h->id() > h->opposite()->id())
            continue;
        const auto a = h->opposite()->vertex(), b = h->vertex();
        if (!a->is_skeleton() || !b->is_skeleton())
            continue;
        if (!std::isfinite(CGAL::to_double(a->time())) ||
            !std::isfinite(CGAL::to_double(b->time())))
            continue;
        graph.addEdge(nodeOf(a), nodeOf(b));
    }
    // A convex blob whose skeleton is a single vertex has no bisector between skeleton
    // vertices: keep its deepest vertex as the one node.
    if (node.empty()) {
        Skeleton2::Vertex_const_handle deepest;
        bool found = false;
        for (auto v = skeleton->vertices_begin(); v != skeleton->vertices_end(); ++v) {
            if (v->is_skeleton() && (!found || v->time() > deepest->time())) {
                deepest = v;
                found = true;
            }
        }
        if (!found)
            return StraightSkeletonStatus::Failed;
        nodeOf(deepest);
    }
    return StraightSkeletonStatus::Ok;
}

} // namespace finbook::geometry::detail
