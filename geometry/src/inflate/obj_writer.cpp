#include <finbook/geometry/inflate/inflated_solid.h>

#include <Eigen/Geometry>

#include <charconv>

namespace finbook::geometry {
namespace {

// Shortest text that reads back to the same number, with no digit grouping and '.' as the
// decimal point whatever locale the stream carries.
template <class Number> void writeNumber(std::ostream &out, Number value)
{
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.write(buffer, result.ptr - buffer);
}

void writeRow(std::ostream &out, const char *tag, const Eigen::RowVector3d &row)
{
    out << tag;
    for (int c = 0; c < 3; ++c) {
        out << ' ';
        writeNumber(out, row(c));
    }
    out << '\n';
}

std::string safeName(const std::string &name)
{
    std::string safe = name.empty() ? std::string("object") : name;
    for (char &c : safe)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            c = '_';
    return safe;
}

} // namespace

bool writeObj(std::ostream &out, const std::vector<ObjObject> &objects,
              const ObjMaterials &materials)
{
    out << "# Finbook inflated drawing: y up, canvas pixels, closed outward-facing solids\n";
    const bool library = !materials.library.empty();
    if (library)
        out << "mtllib " << safeName(materials.library) << '\n';
    long offset = 1; // OBJ indices are 1-based and run on across objects
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const ObjObject &object = objects[o];
        const InflatedSolid &solid = object.solid;
        out << "o " << safeName(object.name) << '\n';
        if (library && o < materials.materials.size() && !materials.materials[o].empty())
            out << "g " << safeName(object.name) << "\nusemtl " << safeName(materials.materials[o])
                << '\n';
        for (Eigen::Index i = 0; i < solid.V.rows(); ++i)
            writeRow(out, "v", solid.V.row(i));
        for (Eigen::Index i = 0; i < solid.N.rows(); ++i)
            writeRow(out, "vn", solid.N.row(i));
        const bool textured = solid.textured();
        for (Eigen::Index i = 0; textured && i < solid.UV.rows(); ++i) {
            out << "vt ";
            writeNumber(out, solid.UV(i, 0));
            out << ' ';
            writeNumber(out, 1.0 - solid.UV(i, 1)); // OBJ's v runs up the image
            out << '\n';
        }
        for (Eigen::Index f = 0; f < solid.F.rows(); ++f) {
            out << 'f';
            for (int c = 0; c < 3; ++c) {
                const long index = offset + solid.F(f, c);
                out << ' ';
                writeNumber(out, index);
                out << '/';
                if (textured)
                    writeNumber(out, index);
                out << '/';
                writeNumber(out, index);
            }
            out << '\n';
        }
        offset += long(solid.V.rows());
    }
    out.flush();
    return bool(out);
}

bool writeMtl(std::ostream &out, const std::vector<MtlMaterial> &materials)
{
    out << "# Finbook materials: flat fill colours, pictures\n";
    for (const MtlMaterial &material : materials) {
        const bool textured = !material.texture.empty();
        const Eigen::RowVector3d colour =
            textured ? Eigen::RowVector3d::Ones()
                     : Eigen::RowVector3d(material.red, material.green, material.blue);
        out << "\nnewmtl " << safeName(material.name) << '\n';
        writeRow(out, "Kd", colour);
        writeRow(out, "Ka", colour);
        writeRow(out, "Ks", Eigen::RowVector3d::Zero());
        out << "d ";
        writeNumber(out, textured ? 1.0 : material.opacity);
        out << "\nillum 1\n";
        if (textured)
            out << "map_Kd " << safeName(material.texture) << "\nmap_d "
                << safeName(material.texture) << '\n';
    }
    out.flush();
    return bool(out);
}

} // namespace finbook::geometry
