#include "medial_ball.h"
#include "mesh_outline.h"
#include "outline_grid.h"
#include "split_chords.h"

#include <finbook/geometry/inflate/inflation.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace finbook::geometry {
namespace {

// Lengths below this × the drawing's size count as zero (points on the outline).
constexpr double kRelativeTolerance = 1e-9;

Unexpected<GeometryError> failure(GeometryErrorCode code, std::string message)
{
    return unexpected(GeometryError{code, std::move(message)});
}

double triangleArea(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, Eigen::Index f)
{
    const Eigen::RowVector2d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y()));
}

std::optional<GeometryError> checkInput(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    if (V.rows() == 0 || F.rows() == 0)
        return GeometryError{GeometryErrorCode::EmptyInput,
                             "There is no shape to inflate: the mesh has no triangles."};
    if (!V.allFinite())
        return GeometryError{GeometryErrorCode::NonFiniteInput,
                             "The shape has an invalid (not a number) point and cannot be "
                             "inflated; redraw the object."};
    if (V.cwiseAbs().maxCoeff() > kMaxCoordinate)
        return GeometryError{GeometryErrorCode::CoordinateOutOfRange,
                             "The shape lies too far outside the canvas to be inflated."};
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const auto row = F.row(f);
        if (row.minCoeff() < 0 || row.maxCoeff() >= V.rows())
            return GeometryError{GeometryErrorCode::InvalidIndex,
                                 "The mesh names a vertex it does not have."};
        if (row(0) == row(1) || row(1) == row(2) || row(0) == row(2))
            return GeometryError{GeometryErrorCode::InvalidIndex,
                                 "The mesh has a triangle with a repeated corner."};
        if (!(triangleArea(V, F, f) > 0.0))
            return GeometryError{GeometryErrorCode::DegenerateRegion,
                                 "The shape has a flat or inverted triangle and cannot be "
                                 "inflated; remesh the object."};
    }
    return std::nullopt;
}

// Mean length of the triangles' edges (interior ones counted twice): the mesh's resolution.
double meanEdgeLength(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    double sum = 0.0;
    for (Eigen::Index f = 0; f < F.rows(); ++f)
        for (int k = 0; k < 3; ++k)
            sum += (V.row(F(f, k)) - V.row(F(f, (k + 1) % 3))).norm();
    return sum / double(3 * F.rows());
}

} // namespace

Expected<Inflation, GeometryError> inflateMesh(const Eigen::MatrixX2d &input,
                                               const Eigen::MatrixX3i &inputF,
                                               const InflateOptions &options)
{
    if (!(options.contactAngleDegrees > 0.0 && options.contactAngleDegrees < 180.0))
        return failure(GeometryErrorCode::InvalidOptions,
                       "The inflation's contact angle must lie between 0 and 180 degrees.");
    if (!(options.outlineSmoothing >= 0.0 && options.outlineSmoothing <= 100.0))
        return failure(GeometryErrorCode::InvalidOptions,
                       "The inflation's outline smoothing must lie between 0 and 100.");
    if (auto error = checkInput(input, inputF))
        return unexpected(*error);
    Eigen::MatrixX2d V = input;
    Eigen::MatrixX3i F = inputF;
    inflate_detail::splitOutlineChords(V, F);
    inflate_detail::MeshOutline outline = inflate_detail::meshOutline(V, F);
    if (outline.edgeCount() == 0)
        return failure(GeometryErrorCode::DegenerateRegion,
                       "The mesh has no outline, so it cannot be inflated.");
    // Outline detail below the smoothing length is not shape: it neither turns the normals
    // nor stops a ball (unless across from it).
    const double smoothing = options.outlineSmoothing * meanEdgeLength(input, inputF);
    inflate_detail::smoothOutlineNormals(outline, smoothing);
    const inflate_detail::ContactRule rule{std::cos(options.contactAngleDegrees * M_PI / 180.0),
                                           smoothing};
    const inflate_detail::OutlineGrid grid(outline);
    const double size = (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
    const double tolerance = kRelativeTolerance * std::max(size, 1e-300);

    const Eigen::Index n = V.rows();
    Inflation result;
    result.V = V;
    result.F = F;
    result.height.resize(n);
    result.normal.resize(n, 3);
    result.depth.resize(n);
    result.radius.resize(n);
    result.outline.resize(n);
    std::vector<char> used(std::size_t(n), 0);
    for (Eigen::Index i = 0; i < F.size(); ++i)
        used[std::size_t(F.data()[i])] = 1;
    for (Eigen::Index i = 0; i < n; ++i) {
        const int slot = outline.slot[std::size_t(i)];
        if (!used[std::size_t(i)]) { // not part of the shape: flat, facing the viewer
            result.height(i) = result.depth(i) = result.radius(i) = 0.0;
            result.outline(i) = 0;
            result.normal.row(i) << 0.0, 0.0, 1.0;
            continue;
        }
        const inflate_detail::MedialBall ball =
            inflate_detail::medialBall(outline, grid, V.row(i), slot, tolerance, rule);
        const double r = ball.radius;
        result.depth(i) = ball.depth;
        result.radius(i) = r;
        result.outline(i) = slot >= 0 ? 1 : 0;
        if (slot >= 0 || r <= tolerance) {
            // On the outline (or a corner's tip): zero height, the tangent vertical.
            result.height(i) = 0.0;
            result.normal.row(i) << -ball.direction.x(), -ball.direction.y(), 0.0;
            continue;
        }
        const Eigen::RowVector2d fromCentre = V.row(i) - ball.centre;
        const double h = ball.height;
        result.height(i) = h;
        const Eigen::RowVector3d normal(fromCentre.x(), fromCentre.y(), h);
        const double length = normal.norm();
        if (length > tolerance)
            result.normal.row(i) = normal / length;
        else
            result.normal.row(i) << 0.0, 0.0, 1.0;
    }
    return result;
}

Expected<Inflation, GeometryError> inflateObjectMesh(const ObjectMesh &mesh,
                                                     const InflateOptions &options)
{
    return inflateMesh(mesh.V, mesh.F, options);
}

Expected<Inflation, GeometryError>
inflateRegion(const Region &region, const MeshOptions &meshOptions, const InflateOptions &options)
{
    auto mesh = meshRegion(region, meshOptions);
    if (!mesh)
        return unexpected(mesh.error());
    return inflateObjectMesh(*mesh, options);
}

double inflatedVolume(const Inflation &inflation)
{
    double volume = 0.0;
    for (Eigen::Index f = 0; f < inflation.F.rows(); ++f) {
        const double mean =
            (inflation.height(inflation.F(f, 0)) + inflation.height(inflation.F(f, 1)) +
             inflation.height(inflation.F(f, 2))) /
            3.0;
        volume += triangleArea(inflation.V, inflation.F, f) * mean;
    }
    return volume;
}

} // namespace finbook::geometry
