// Inflated solids as one glTF 2.0 binary file (.glb), the 3D export's second format: what
// Blender, three.js and every game engine read without a material file beside it.
#pragma once

#include <finbook/geometry/inflate/inflated_solid.h>

#include <string>
#include <vector>

namespace finbook::geometry {

// One object of the file: a node and its mesh, named `name` (UTF-8, any text), drawn in a
// flat colour given as sRGB components in [0, 1] with an opacity (below 1: alpha blending).
// A textured solid (InflatedSolid::textured) with `png` (a PNG file's bytes) is drawn in that
// picture instead: the image embedded in the file, its alpha blended.
struct GlbObject {
    std::string name;
    InflatedSolid solid;
    double red = 0.0, green = 0.0, blue = 0.0;
    double opacity = 1.0;
    std::string png;
    bool textured() const { return solid.textured() && !png.empty(); }
};

// The bytes of a .glb file: the 12-byte header ("glTF", version 2, total length), a JSON chunk
// (asset, one scene of one node per object, meshes, materials, accessors, buffer views, one
// buffer) padded with spaces, and a BIN chunk padded with zeros, both to 4 bytes. Per object
// the buffer holds its positions and unit normals (float32 VEC3, positions with their min and
// max) and its triangles (uint32 indices, counter-clockwise seen from outside), each view
// 4-byte aligned; a textured object's texture coordinates too (float32 VEC2, TEXCOORD_0), its
// PNG as an image of the buffer, sampled linearly and clamped at its edges. Coordinates as
// InflatedSolid's: y up, +z towards the viewer, one unit per canvas pixel. Colours become linear
// baseColorFactor values, as glTF defines them; an object with no triangles is left out. Empty if
// the solids hold more than a glTF file can address (over 4 GiB).
std::string glbBytes(const std::vector<GlbObject> &objects);

} // namespace finbook::geometry
