#include "cdt_mesher.h"

#include <queue>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <exception>
#include <vector>

namespace finbook::geometry::detail {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using VbInfo = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K, VbInfo>;
// Face info holds the nesting depth: odd = inside the region.
using FbInfo = CGAL::Triangulation_face_base_with_info_2<int, K>;
using FbCt = CGAL::Constrained_triangulation_face_base_2<K, FbInfo>;
using FbC = CGAL::Constrained_Delaunay_triangulation_face_base_2<K, FbCt>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K, FbC>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Exact_predicates_tag: should two constraints still cross, CGAL inserts the crossing
// instead of failing.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;

void insertRings(Cdt &cdt, const Region &region)
{
    for (const Eigen::MatrixX2d &ring : regionRings(region)) {
        std::vector<K::Point_2> points;
        points.reserve(std::size_t(ring.rows()));
        for (Eigen::Index i = 0; i < ring.rows(); ++i)
            points.emplace_back(ring(i, 0), ring(i, 1));
        cdt.insert_constraint(points.begin(), points.end(), true);
    }
}

// Flood fill over unconstrained edges; every constrained edge crossed adds one nesting level.
// Faces at odd depth are inside (outer rings open depth 1, holes depth 2, islands depth 3).
void markDomain(Cdt &cdt)
{
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
        f->info() = -1;
    std::queue<Cdt::Face_handle> border;
    border.push(cdt.infinite_face());
    cdt.infinite_face()->info() = 0;
    while (!border.empty()) {
        std::queue<Cdt::Face_handle> level;
        level.push(border.front());
        border.pop();
        while (!level.empty()) {
            const Cdt::Face_handle f = level.front();
            level.pop();
            for (int i = 0; i < 3; ++i) {
                const Cdt::Face_handle n = f->neighbor(i);
                if (n->info() != -1)
                    continue;
                n->info() = f->info() + (cdt.is_constrained({f, i}) ? 1 : 0);
                (cdt.is_constrained({f, i}) ? border : level).push(n);
            }
        }
    }
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
        f->set_in_domain(!cdt.is_infinite(f) && f->info() % 2 == 1);
}

RawMesh extract(Cdt &cdt)
{
    int index = 0;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
        v->info() = -1;
    std::vector<Eigen::Vector3i> faces;
    std::vector<Eigen::Vector2d> points;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (!f->is_in_domain())
            continue;
        Eigen::Vector3i face;
        for (int i = 0; i < 3; ++i) {
            const Cdt::Vertex_handle v = f->vertex(i);
            if (v->info() < 0) {
                v->info() = index++;
                points.emplace_back(v->point().x(), v->point().y());
            }
            face[i] = v->info();
        }
        faces.push_back(face); // CGAL stores finite faces counter-clockwise
    }
    RawMesh mesh;
    mesh.V.resize(Eigen::Index(points.size()), 2);
    for (std::size_t i = 0; i < points.size(); ++i)
        mesh.V.row(Eigen::Index(i)) = points[i].transpose();
    mesh.F.resize(Eigen::Index(faces.size()), 3);
    for (std::size_t i = 0; i < faces.size(); ++i)
        mesh.F.row(Eigen::Index(i)) = faces[i].transpose();
    return mesh;
}

} // namespace

Expected<RawMesh, GeometryError> refineRegion(const Region &region, double maxEdge, long vertexCap)
{
    try {
        Cdt cdt;
        insertRings(cdt, region);
        if (cdt.dimension() < 2)
            return unexpected(GeometryError{GeometryErrorCode::DegenerateRegion,
                                            "The outline is flat: all its points are collinear."});
        markDomain(cdt);
        Mesher mesher(cdt, Criteria(0.125, maxEdge));
        mesher.init(true); // keep our domain marks instead of CGAL's convex-hull default
        while (!mesher.is_refinement_done() && long(cdt.number_of_vertices()) < vertexCap)
            mesher.step_by_step_refine_mesh();
        return extract(cdt);
    } catch (const std::exception &e) {
        return unexpected(
            GeometryError{GeometryErrorCode::TriangulationFailed,
                          std::string("Triangulating the outline failed: ") + e.what()});
    }
}

} // namespace finbook::geometry::detail
