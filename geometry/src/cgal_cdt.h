// Internal, CGAL: the constrained Delaunay triangulation and mesher types the geometry layer
// meshes with, and the nesting-depth domain marking. Include only from .cpp files (CGAL
// headers cost seconds per translation unit).
#pragma once

#include <queue>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace finbook::geometry::detail::cgal {

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

// Flood fill over unconstrained edges; every constrained edge crossed adds one nesting level
// (face info). Faces at odd depth are inside (outer rings open depth 1, holes depth 2, islands
// depth 3) and get set_in_domain(true). CGAL 5.5 has no mark_domain_in_triangulation, and
// its mesher without marks refines the whole convex hull.
inline void markDomain(Cdt &cdt)
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

} // namespace finbook::geometry::detail::cgal
