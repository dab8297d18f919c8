#include "planar_map.h"

#include <finbook/geometry/polyline.h>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arr_walk_along_line_point_location.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <unordered_set>

namespace finbook::geometry::detail {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegmentTraits, int>;
using Arrangement = CGAL::Arrangement_2<Traits>;
using Curve = Traits::Curve_2;
using Point = Traits::Point_2;
using FaceHandle = Arrangement::Face_const_handle;
using HalfedgeHandle = Arrangement::Halfedge_const_handle;

Point toPoint(const Eigen::Vector2d &p)
{
    return Point(p.x(), p.y());
}

Eigen::Vector2d toVector(const Point &p)
{
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
}

// A face's boundary without its dangling edges: the halfedges whose other side is another
// face, chained into cycles (outer boundary positive, holes negative).
struct Boundary {
    std::vector<std::vector<HalfedgeHandle>> cycles;
};

bool separates(HalfedgeHandle h)
{
    return h->twin()->face() != h->face();
}

// The next separating halfedge of h's face after h: turn around h's target through the
// dangling edges and bridges (both sides in the face) until a separating one leaves it.
HalfedgeHandle successor(HalfedgeHandle h)
{
    HalfedgeHandle g = h->next();
    while (!separates(g))
        g = g->twin()->next();
    return g;
}

void collect(Arrangement::Ccb_halfedge_const_circulator start, std::vector<HalfedgeHandle> &out)
{
    auto h = start;
    do {
        if (separates(h))
            out.push_back(h);
    } while (++h != start);
}

Boundary boundaryOf(FaceHandle f)
{
    std::vector<HalfedgeHandle> all;
    for (auto o = f->outer_ccbs_begin(); o != f->outer_ccbs_end(); ++o)
        collect(*o, all);
    for (auto i = f->inner_ccbs_begin(); i != f->inner_ccbs_end(); ++i)
        collect(*i, all);
    Boundary boundary;
    std::unordered_set<const void *> seen;
    for (HalfedgeHandle h : all) {
        if (!seen.insert(&*h).second)
            continue;
        std::vector<HalfedgeHandle> cycle{h};
        for (HalfedgeHandle g = successor(h); g != h; g = successor(g)) {
            if (!seen.insert(&*g).second)
                break; // cannot happen on a valid map; never loop forever
            cycle.push_back(g);
        }
        boundary.cycles.push_back(std::move(cycle));
    }
    return boundary;
}

Eigen::MatrixX2d ringOf(const std::vector<HalfedgeHandle> &cycle)
{
    Eigen::MatrixX2d ring(Eigen::Index(cycle.size()), 2);
    for (std::size_t i = 0; i < cycle.size(); ++i)
        ring.row(Eigen::Index(i)) = toVector(cycle[i]->source()->point()).transpose();
    return ring;
}

double ringLength(const Eigen::MatrixX2d &ring)
{
    double l = 0.0;
    for (Eigen::Index i = 0, n = ring.rows(); i < n; ++i)
        l += (ring.row((i + 1) % n) - ring.row(i)).norm();
    return l;
}

MapFace toMapFace(const Boundary &boundary)
{
    MapFace face;
    double bestOuter = 0.0;
    for (const auto &cycle : boundary.cycles) {
        Eigen::MatrixX2d ring = ringOf(cycle);
        const double a = signedArea(ring);
        face.area += a;
        face.perimeter += ringLength(ring);
        for (HalfedgeHandle h : cycle)
            for (int label : h->curve().data())
                if (label >= 0)
                    face.labels.push_back(label);
        if (a > 0.0) {
            // One outer cycle per bounded face; keep the largest should rounding make two.
            if (a > bestOuter) {
                bestOuter = a;
                face.polygon.outer = std::move(ring);
            }
        } else if (a < 0.0) {
            face.polygon.holes.push_back(std::move(ring));
        }
    }
    std::sort(face.labels.begin(), face.labels.end());
    face.labels.erase(std::unique(face.labels.begin(), face.labels.end()), face.labels.end());
    return face;
}

} // namespace

struct PlanarMap::Impl {
    Arrangement arrangement;
};

PlanarMap::PlanarMap()
    : m(std::make_unique<Impl>())
{}
PlanarMap::~PlanarMap() = default;

void PlanarMap::insertAll(const std::vector<LabelledSegment> &segments)
{
    std::vector<Curve> curves;
    curves.reserve(segments.size());
    for (const LabelledSegment &s : segments)
        if (s.a != s.b)
            curves.emplace_back(SegmentTraits::Curve_2(toPoint(s.a), toPoint(s.b)), s.label);
    CGAL::insert(m->arrangement, curves.begin(), curves.end());
}

void PlanarMap::insert(const LabelledSegment &s)
{
    if (s.a != s.b)
        CGAL::insert(m->arrangement,
                     Curve(SegmentTraits::Curve_2(toPoint(s.a), toPoint(s.b)), s.label));
}

bool PlanarMap::inBoundedFace(const Eigen::Vector2d &p) const
{
    CGAL::Arr_walk_along_line_point_location<Arrangement> locator(m->arrangement);
    const auto result = locator.locate(toPoint(p));
    const FaceHandle *face = boost::get<FaceHandle>(&result);
    return face && !(*face)->is_unbounded();
}

std::optional<PlanarMap::Trial> PlanarMap::trialFace(const std::vector<LabelledSegment> &segments,
                                                     const Eigen::Vector2d &probe,
                                                     double minNeighbourArea) const
{
    Arrangement trial(m->arrangement);
    for (const LabelledSegment &s : segments)
        if (s.a != s.b)
            CGAL::insert(trial, Curve(SegmentTraits::Curve_2(toPoint(s.a), toPoint(s.b)), s.label));
    CGAL::Arr_walk_along_line_point_location<Arrangement> locator(trial);
    const auto result = locator.locate(toPoint(probe));
    const FaceHandle *face = boost::get<FaceHandle>(&result);
    if (!face || (*face)->is_unbounded())
        return std::nullopt;
    const Boundary boundary = boundaryOf(*face);
    Trial out{toMapFace(boundary), 0.0};
    // Bounded before the trial (a face the added segments close as well does not count), and
    // not a speck.
    CGAL::Arr_walk_along_line_point_location<Arrangement> before(m->arrangement);
    std::unordered_map<const void *, double> areas;
    for (const auto &cycle : boundary.cycles)
        for (HalfedgeHandle h : cycle) {
            if (h->twin()->face()->is_unbounded())
                continue;
            const Eigen::Vector2d a = toVector(h->source()->point());
            const Eigen::Vector2d d = toVector(h->target()->point()) - a;
            const double length = d.norm();
            if (!(length > 0.0))
                continue;
            // The face lies left of its halfedges; its neighbour, right.
            const Eigen::Vector2d right(d.y() / length, -d.x() / length);
            const auto where =
                before.locate(toPoint(a + 0.5 * d + std::min(0.01 * length, 0.05) * right));
            const FaceHandle *other = boost::get<FaceHandle>(&where);
            if (!other || (*other)->is_unbounded())
                continue;
            const auto known = areas.find(&**other);
            const double area = known != areas.end()
                                    ? known->second
                                    : areas[&**other] = toMapFace(boundaryOf(*other)).area;
            if (area >= minNeighbourArea)
                out.sharedWithBounded += length;
        }
    if (out.face.polygon.outer.rows() < 3 || !(out.face.area > 0.0))
        return std::nullopt;
    return out;
}

void PlanarMap::forEachContact(const std::function<void(int, int)> &join) const
{
    for (auto e = m->arrangement.edges_begin(); e != m->arrangement.edges_end(); ++e) {
        const auto &data = e->curve().data();
        for (auto it = data.begin(); it != data.end(); ++it)
            join(*data.begin(), *it);
    }
    for (auto v = m->arrangement.vertices_begin(); v != m->arrangement.vertices_end(); ++v) {
        if (v->is_isolated())
            continue;
        const int first = *v->incident_halfedges()->curve().data().begin();
        auto h = v->incident_halfedges();
        const auto start = h;
        do {
            join(first, *h->curve().data().begin());
        } while (++h != start);
    }
}

void PlanarMap::mergeSlivers(double minWidth, double minArea)
{
    Arrangement &arr = m->arrangement;
    for (int pass = 0; pass < 64; ++pass) {
        std::unordered_set<const void *> touched;
        std::vector<Arrangement::Halfedge_handle> doomed;
        for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
            if (f->is_unbounded() || touched.count(&*f))
                continue;
            const Boundary boundary = boundaryOf(f);
            double area = 0.0, perimeter = 0.0;
            std::map<const void *, double> shared;
            for (const auto &cycle : boundary.cycles) {
                const Eigen::MatrixX2d ring = ringOf(cycle);
                area += signedArea(ring);
                perimeter += ringLength(ring);
            }
            if (!(perimeter > 0.0) || (2.0 * area / perimeter >= minWidth && area >= minArea))
                continue;
            FaceHandle best;
            double bestLength = -1.0;
            for (const auto &cycle : boundary.cycles)
                for (HalfedgeHandle h : cycle) {
                    const double l =
                        (toVector(h->target()->point()) - toVector(h->source()->point())).norm();
                    double &sum = shared[&*h->twin()->face()];
                    sum += l;
                    if (sum > bestLength) {
                        bestLength = sum;
                        best = h->twin()->face();
                    }
                }
            if (touched.count(&*best))
                continue;
            touched.insert(&*f);
            touched.insert(&*best);
            for (const auto &cycle : boundary.cycles)
                for (HalfedgeHandle h : cycle)
                    if (h->twin()->face() == best)
                        doomed.push_back(arr.non_const_handle(h));
        }
        if (doomed.empty())
            return;
        for (auto h : doomed)
            arr.remove_edge(h, false, false);
    }
}

std::vector<MapFace> PlanarMap::faces() const
{
    std::vector<MapFace> out;
    for (auto f = m->arrangement.faces_begin(); f != m->arrangement.faces_end(); ++f) {
        if (f->is_unbounded())
            continue;
        MapFace face = toMapFace(boundaryOf(f));
        if (face.polygon.outer.rows() >= 3 && face.area > 0.0)
            out.push_back(std::move(face));
    }
    return out;
}

} // namespace finbook::geometry::detail
