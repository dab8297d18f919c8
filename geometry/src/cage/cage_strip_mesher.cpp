#include "cage_strip_mesher.h"

#include "../cgal_cdt.h"

#include <cmath>
#include <exception>

namespace finbook::geometry::detail {
namespace {

using cgal::Cdt;
using cgal::Criteria;
using cgal::K;
using cgal::Mesher;

// Inserts every listed point once (spatially sorted by CGAL) and returns their handles by id.
std::vector<Cdt::Vertex_handle> insertPoints(Cdt &cdt, const StripInput &input)
{
    std::vector<char> listed(input.points.size(), 0);
    std::vector<std::pair<K::Point_2, int>> items;
    const auto add = [&](int id) {
        if (listed[std::size_t(id)])
            return;
        listed[std::size_t(id)] = 1;
        const Eigen::Vector2d &p = input.points[std::size_t(id)];
        items.emplace_back(K::Point_2(p.x(), p.y()), id);
    };
    for (const int id : input.ring)
        add(id);
    for (const auto &[a, b] : input.front) {
        add(a);
        add(b);
    }
    for (const int id : input.loose)
        add(id);
    cdt.insert(items.begin(), items.end());
    std::vector<Cdt::Vertex_handle> handles(input.points.size());
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
        handles[std::size_t(v->info())] = v;
    return handles;
}

// Whether w lies on the segment ab up to rounding: refinement splits constraints at their
// computed midpoints, which are not exactly on a slanted segment.
bool onSegment(const K::Point_2 &a, const K::Point_2 &b, const K::Point_2 &w)
{
    const double dx = b.x() - a.x(), dy = b.y() - a.y();
    const double length2 = dx * dx + dy * dy;
    const double cross = dx * (w.y() - a.y()) - dy * (w.x() - a.x());
    const double along = dx * (w.x() - a.x()) + dy * (w.y() - a.y());
    return std::abs(cross) <= 1e-9 * length2 && along > 0.0 && along < length2;
}

// The vertices refinement inserted on the constrained segment from va to vb, in order; empty
// when the chain cannot be followed (treated like an unpatchable split by the caller).
std::vector<int> splitChain(const Cdt &cdt, Cdt::Vertex_handle va, Cdt::Vertex_handle vb)
{
    std::vector<int> inner;
    const K::Point_2 &a = va->point(), &b = vb->point();
    Cdt::Vertex_handle previous, current = va;
    while (current != vb) {
        Cdt::Vertex_handle next;
        auto edge = cdt.incident_edges(current), done = edge;
        do {
            if (cdt.is_infinite(edge) || !cdt.is_constrained(*edge))
                continue;
            const Cdt::Face_handle f = edge->first;
            Cdt::Vertex_handle w = f->vertex(Cdt::cw(edge->second));
            if (w == current)
                w = f->vertex(Cdt::ccw(edge->second));
            if (w != previous && (w == vb || onSegment(a, b, w->point())))
                next = w;
        } while (++edge != done && next == Cdt::Vertex_handle());
        if (next == Cdt::Vertex_handle() || inner.size() > 64)
            return {};
        if (next != vb)
            inner.push_back(next->info());
        previous = current;
        current = next;
    }
    return inner;
}

StripMesh extract(Cdt &cdt, const StripInput &input, const std::vector<Cdt::Vertex_handle> &handles)
{
    StripMesh mesh;
    const int known = int(input.points.size());
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        // CGAL leaves the info of vertices refinement adds uninitialised: a vertex is ours
        // only if its id leads back to it.
        const int id = v->info();
        if (id < 0 || id >= known || handles[std::size_t(id)] != Cdt::Vertex_handle(v)) {
            v->info() = known + int(mesh.added.size());
            mesh.added.emplace_back(v->point().x(), v->point().y());
        }
    }
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (f->is_in_domain()) // CGAL stores finite faces counter-clockwise
            mesh.triangles.emplace_back(f->vertex(0)->info(), f->vertex(1)->info(),
                                        f->vertex(2)->info());
    }
    for (std::size_t k = 0; k < input.front.size(); ++k) {
        const auto [a, b] = input.front[k];
        if (!cdt.is_edge(handles[std::size_t(a)], handles[std::size_t(b)]))
            mesh.splits.push_back(
                {k, splitChain(cdt, handles[std::size_t(a)], handles[std::size_t(b)])});
    }
    return mesh;
}

} // namespace

Expected<StripMesh, GeometryError> meshStrip(const StripInput &input, double maxEdge,
                                             long vertexCap)
{
    try {
        Cdt cdt;
        const std::vector<Cdt::Vertex_handle> handles = insertPoints(cdt, input);
        if (cdt.dimension() < 2)
            return unexpected(GeometryError{GeometryErrorCode::TriangulationFailed,
                                            "The cage's points are collinear."});
        for (std::size_t k = 0; k < input.ring.size(); ++k)
            cdt.insert_constraint(handles[std::size_t(input.ring[k])],
                                  handles[std::size_t(input.ring[(k + 1) % input.ring.size()])]);
        for (const auto &[a, b] : input.front)
            cdt.insert_constraint(handles[std::size_t(a)], handles[std::size_t(b)]);
        cgal::markDomain(cdt);
        Mesher mesher(cdt, Criteria(0.125, maxEdge));
        mesher.init(true); // keep our domain marks instead of CGAL's convex-hull default
        while (!mesher.is_refinement_done() && long(cdt.number_of_vertices()) < vertexCap)
            mesher.step_by_step_refine_mesh();
        return extract(cdt, input, handles);
    } catch (const std::exception &e) {
        return unexpected(GeometryError{GeometryErrorCode::TriangulationFailed,
                                        std::string("Triangulating the cage failed: ") + e.what()});
    }
}

} // namespace finbook::geometry::detail
