#include <finbook/geometry/import/off_mesh.h>
#include <finbook/geometry/mesh_boundary.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace finbook::geometry {
namespace {

GeometryError offError(GeometryErrorCode code, std::string message)
{
    return GeometryError{code, std::move(message)};
}

// The file's lines without comments and blank lines, with their line numbers.
class Lines {
public:
    explicit Lines(const std::string &text)
        : m_stream(text)
    {}

    bool next(std::istringstream &line)
    {
        std::string raw;
        while (std::getline(m_stream, raw)) {
            ++m_number;
            raw = raw.substr(0, raw.find('#'));
            if (raw.find_first_not_of(" \t\r") == std::string::npos)
                continue;
            line.clear();
            line.str(raw);
            return true;
        }
        return false;
    }
    int number() const { return m_number; }

private:
    std::istringstream m_stream;
    int m_number = 0;
};

GeometryError malformed(const Lines &lines, const std::string &what)
{
    return offError(GeometryErrorCode::MalformedFile, "The OFF file is malformed at line " +
                                                          std::to_string(lines.number()) + ": " +
                                                          what + ".");
}

Expected<std::array<long, 2>, GeometryError> readHeader(Lines &lines)
{
    std::istringstream line;
    std::string keyword;
    if (!lines.next(line) || !(line >> keyword))
        return unexpected(offError(GeometryErrorCode::MalformedFile, "The OFF file is empty."));
    if (keyword != "OFF" && keyword != "COFF" && keyword != "NOFF" && keyword != "CNOFF")
        return unexpected(malformed(lines, "it does not start with OFF"));
    long vertices = 0, faces = 0;
    if (!(line >> vertices) && (!lines.next(line) || !(line >> vertices)))
        return unexpected(malformed(lines, "the vertex and face counts are missing"));
    if (!(line >> faces))
        return unexpected(malformed(lines, "the face count is missing"));
    if (vertices < 0 || faces < 0)
        return unexpected(malformed(lines, "a count is negative"));
    if (vertices > kMaxOffElements || faces > kMaxOffElements)
        return unexpected(offError(GeometryErrorCode::TooManyPoints,
                                   "The OFF file has more than " + std::to_string(kMaxOffElements) +
                                       " vertices or faces."));
    return std::array<long, 2>{vertices, faces};
}

std::optional<GeometryError> readVertices(Lines &lines, Eigen::MatrixX2d &V)
{
    std::istringstream line;
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
        double x = 0.0, y = 0.0;
        // Stream extraction refuses nan, inf and overflowing numbers: what it reads is finite.
        if (!lines.next(line) || !(line >> x >> y))
            return malformed(lines,
                             "vertex " + std::to_string(i) + " is missing or not a finite number");
        if (std::max(std::abs(x), std::abs(y)) > kMaxCoordinate)
            return offError(GeometryErrorCode::CoordinateOutOfRange,
                            "Vertex " + std::to_string(i) + " of the OFF file lies beyond ±1e6.");
        V.row(i) << x, y;
    }
    return std::nullopt;
}

std::optional<GeometryError> readFaces(Lines &lines, long faces, Eigen::Index vertices,
                                       std::vector<Eigen::Vector3i> &triangles)
{
    std::istringstream line;
    for (long f = 0; f < faces; ++f) {
        long k = 0;
        if (!lines.next(line) || !(line >> k))
            return malformed(lines, "face " + std::to_string(f) + " is missing");
        if (k < 3 || k > vertices)
            return malformed(lines, "face " + std::to_string(f) + " has " + std::to_string(k) +
                                        " corners");
        std::vector<int> corner(std::size_t(k), 0);
        for (long c = 0; c < k; ++c) {
            long index = -1;
            if (!(line >> index) || index < 0 || index >= vertices)
                return malformed(lines, "face " + std::to_string(f) +
                                            " refers to a vertex that "
                                            "does not exist");
            corner[std::size_t(c)] = int(index);
        }
        std::vector<int> sorted = corner;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
            return malformed(lines, "face " + std::to_string(f) + " repeats a vertex");
        for (long c = 1; c + 1 < k; ++c) // a fan: OFF polygons are convex by convention
            triangles.emplace_back(corner[0], corner[std::size_t(c)], corner[std::size_t(c + 1)]);
    }
    return std::nullopt;
}

} // namespace

Expected<OffMesh, GeometryError> parseOff(const std::string &text)
{
    Lines lines(text);
    auto counts = readHeader(lines);
    if (!counts)
        return unexpected(counts.error());
    OffMesh mesh;
    mesh.V.resize((*counts)[0], 2);
    if (auto error = readVertices(lines, mesh.V))
        return unexpected(std::move(*error));
    std::vector<Eigen::Vector3i> triangles;
    if (auto error = readFaces(lines, (*counts)[1], mesh.V.rows(), triangles))
        return unexpected(std::move(*error));
    mesh.F.resize(Eigen::Index(triangles.size()), 3);
    double area = 0.0;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        mesh.F.row(Eigen::Index(t)) = triangles[t].transpose();
        const Eigen::Vector2d a = mesh.V.row(triangles[t][0]), b = mesh.V.row(triangles[t][1]),
                              c = mesh.V.row(triangles[t][2]);
        area += (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    }
    if (area < 0.0)
        mesh.F.col(1).swap(mesh.F.col(2));
    mesh.boundaryLoops = boundaryLoops(mesh.F);
    return mesh;
}

Expected<OffMesh, GeometryError> readOff(const std::string &path)
{
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file)
        return unexpected(
            offError(GeometryErrorCode::EmptyInput, "The file " + path + " cannot be read."));
    const std::streamoff size = file.tellg();
    if (size > kMaxOffFileBytes)
        return unexpected(offError(GeometryErrorCode::TooManyPoints,
                                   "The file " + path + " is too large for a 2D mesh."));
    std::string text(std::size_t(std::max<std::streamoff>(size, 0)), '\0');
    file.seekg(0);
    file.read(text.data(), std::streamsize(text.size()));
    return parseOff(text);
}

std::vector<Eigen::MatrixX2d> boundaryRings(const OffMesh &mesh)
{
    std::vector<Eigen::MatrixX2d> rings;
    for (const Eigen::VectorXi &loop : mesh.boundaryLoops) {
        Eigen::MatrixX2d ring(loop.size(), 2);
        for (Eigen::Index i = 0; i < loop.size(); ++i)
            ring.row(i) = mesh.V.row(loop(i));
        rings.push_back(std::move(ring));
    }
    return rings;
}

} // namespace finbook::geometry
