// The OpenMesh triangle mesh type of an object (one per stroke group).
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace finbook::geometry {

// Points are canvas pixels as Vec3d with z = 0 (double, like the rest of the layer).
// No normals or colours: the mesh is flat and only deformed in the plane. Status flags
// are kept so callers can delete and garbage-collect elements.
struct TriMeshTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
    VertexAttributes(OpenMesh::Attributes::Status);
    FaceAttributes(OpenMesh::Attributes::Status);
    EdgeAttributes(OpenMesh::Attributes::Status);
    HalfedgeAttributes(OpenMesh::Attributes::PrevHalfedge);
};

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<TriMeshTraits>;

} // namespace finbook::geometry
