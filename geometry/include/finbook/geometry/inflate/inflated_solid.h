// The inflated shape as a closed 3D solid, and its OBJ text (issue 27's 3D export, RealSkel's
// own output): the height field on top, its mirror image below the drawing's plane, joined
// along the outline where the height is 0, so the surface is closed and encloses a volume.
#pragma once

#include <finbook/geometry/inflate/inflation.h>

#include <Eigen/Core>

#include <ostream>
#include <string>
#include <vector>

namespace finbook::geometry {

// Right-handed, y up, as OBJ readers (Blender) expect: a canvas point (x, y) with height h
// becomes (x, −y, h) on top and (x, −y, −h) below; units stay canvas px.
//   V  k×3  vertices: the n inflation vertices (top), then one bottom copy of every vertex off
//           the outline (outline vertices are shared by both halves)
//   N  k×3  unit outward normals, per vertex
//   F  2m×3 triangles, counter-clockwise seen from outside: the m top ones, then the m bottom
//   UV k×2  texture coordinates per vertex, or empty (untextured; inflatedSolid leaves it so):
//           [0, 1] across the image, (0, 0) its top-left corner, v down (glTF's convention)
// Promise: every edge is shared by exactly two triangles, once in each direction (closed
// and consistently oriented), and the signed volume is 2 × inflatedVolume(inflation) ≥ 0.
struct InflatedSolid {
    Eigen::MatrixX3d V;
    Eigen::MatrixX3d N;
    Eigen::MatrixX3i F;
    Eigen::MatrixX2d UV;
    bool textured() const { return UV.rows() > 0 && UV.rows() == V.rows(); }
};

InflatedSolid inflatedSolid(const Inflation &inflation);

// Σ det(a, b, c) / 6 over the triangles: the enclosed volume, positive for outward faces.
double signedVolume(const InflatedSolid &solid);

// One object of an OBJ file: its name (an "o" line) and its solid.
struct ObjObject {
    std::string name;
    InflatedSolid solid;
};

// Materials of an OBJ file (all optional). With a library, the file names it ("mtllib"), and
// each object with a material (materials[i] for objects[i], non-empty) is also a group of
// that name ("g") drawn in that material ("usemtl"), as Blender and other readers expect.
struct ObjMaterials {
    std::string library;                // the .mtl file's name, relative to the .obj
    std::vector<std::string> materials; // per object; empty or shorter: no material
};

// Writes Wavefront OBJ text: a comment, then per object "o name", its "v" and "vn" lines and
// its faces as "f a//a b//b c//c" (1-based, positions and normals share indices); a textured
// solid also has a "vt" line per vertex (v up, as OBJ has it) and faces "f a/a/a b/b/b c/c/c".
// Numbers
// are written in the shortest form that reads back exactly, independent of the locale; line
// breaks and other control characters in names become '_'. Returns false if the stream
// failed.
bool writeObj(std::ostream &out, const std::vector<ObjObject> &objects,
              const ObjMaterials &materials = {});

// One material of an MTL file: a flat diffuse colour, components in [0, 1] (as stored, sRGB),
// and its opacity; or a picture (`texture`, a file name relative to the .mtl) that gives the
// colour and, by its alpha, the opacity.
struct MtlMaterial {
    std::string name;
    double red = 0.0, green = 0.0, blue = 0.0;
    double opacity = 1.0;
    std::string texture;
};

// Writes the MTL text for `materials`: per material "newmtl", its diffuse and ambient colour
// ("Kd", "Ka"), no specular highlight, its opacity ("d") and "illum 1"; with a texture, the
// colour white and "map_Kd" and "map_d" naming it. Names as in writeObj.
// Returns false if the stream failed.
bool writeMtl(std::ostream &out, const std::vector<MtlMaterial> &materials);

} // namespace finbook::geometry
