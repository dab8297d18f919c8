#include "cdt_mesher.h"

#include "cgal_cdt.h"

#include <exception>
#include <vector>

namespace finbook::geometry::detail {
namespace {

using cgal::Cdt;
using cgal::Criteria;
using cgal::K;
using cgal::markDomain;
using cgal::Mesher;

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
