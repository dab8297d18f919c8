#include "dense_graph.h"
#include "skeleton_contour.h"
#include "straight_skeleton.h"

#include <finbook/geometry/skeleton/raw_skeleton.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace finbook::geometry {
namespace {

using namespace detail;

// Edges shorter than this fraction of the local inscribed radius carry no shape.
constexpr double kCollapseFraction = 0.25;
// Side branches whose tip stays within (1 + slack) × the junction's clearance are noise.
constexpr double kSpurSlack = 0.2;
// Coarser, differently jittered outlines tried when CGAL gives up on a polygon.
constexpr int kRetries = 2;

GeometryError failure(GeometryErrorCode code, const char *message)
{
    return GeometryError{code, message};
}

bool isCancelled(const SkeletonOptions &options)
{
    return options.cancelled && options.cancelled();
}

// One joint (all points equal) or one bone along the principal axis of the points: what is
// left of a line, a dot or a scribble without area.
RawSkeleton degenerateSkeleton(const Region &region)
{
    RawSkeleton raw;
    raw.degenerate = true;
    const Eigen::MatrixX2d points = regionPoints(region);
    const Eigen::RowVector2d mean = points.colwise().mean();
    raw.centroid = mean;
    const Eigen::MatrixX2d centred = points.rowwise() - mean;
    const Eigen::Matrix2d covariance = centred.transpose() * centred;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(covariance);
    const Eigen::Vector2d axis = solver.eigenvectors().col(1);
    const Eigen::Vector2d normal = solver.eigenvectors().col(0);
    const Eigen::VectorXd along = centred * axis;
    const Eigen::VectorXd across = centred * normal;
    const double width = across.size() ? 0.5 * (across.maxCoeff() - across.minCoeff()) : 0.0;
    const double lo = along.size() ? along.minCoeff() : 0.0;
    const double hi = along.size() ? along.maxCoeff() : 0.0;
    const double scale = points.size() ? points.cwiseAbs().maxCoeff() : 0.0;
    const bool line = std::isfinite(hi - lo) && hi - lo > 1e-12 * std::max(1.0, scale);
    const int n = line ? 2 : 1;
    raw.nodes.resize(n, 2);
    raw.nodes.row(0) = mean + (line ? lo : 0.0) * axis.transpose();
    if (line)
        raw.nodes.row(1) = mean + hi * axis.transpose();
    raw.radius = Eigen::VectorXd::Constant(n, std::isfinite(width) ? width : 0.0);
    raw.clearance = raw.radius;
    raw.edges.resize(line ? 1 : 0, 2);
    if (line)
        raw.edges.row(0) << 0, 1;
    raw.polygon = Eigen::VectorXi::Zero(n);
    return raw;
}

RawSkeleton toRaw(const DenseGraph &graph, Region contour)
{
    RawSkeleton raw;
    const int n = graph.size();
    raw.nodes.resize(n, 2);
    raw.radius.resize(n);
    raw.clearance.resize(n);
    raw.polygon.resize(n);
    for (int v = 0; v < n; ++v) {
        raw.nodes.row(v) = graph.pos[std::size_t(v)].transpose();
        raw.radius(v) = graph.radius[std::size_t(v)];
        raw.clearance(v) = graph.clearance[std::size_t(v)];
        raw.polygon(v) = graph.polygon[std::size_t(v)];
    }
    std::vector<Eigen::Vector2i> edges;
    for (int v = 0; v < n; ++v) {
        for (int w : graph.adj[std::size_t(v)]) {
            if (w > v)
                edges.emplace_back(v, w);
        }
    }
    raw.edges.resize(Eigen::Index(edges.size()), 2);
    for (std::size_t e = 0; e < edges.size(); ++e)
        raw.edges.row(Eigen::Index(e)) = edges[e].transpose();
    raw.contour = std::move(contour);
    raw.polygonVertices = regionVertexCount(raw.contour);
    return raw;
}

void append(DenseGraph &graph, const DenseGraph &part)
{
    const int offset = graph.size();
    for (int v = 0; v < part.size(); ++v)
        graph.addNode(part.pos[std::size_t(v)], part.radius[std::size_t(v)],
                      part.clearance[std::size_t(v)], part.polygon[std::size_t(v)]);
    for (int v = 0; v < part.size(); ++v) {
        for (int n : part.adj[std::size_t(v)])
            graph.addEdge(offset + v, offset + n);
    }
}

// The cleanup of the raw straight skeleton (raw_skeleton.h), polygon by polygon.
void cleanUp(DenseGraph &graph, const std::vector<ContourIndex> &contours, double erosion)
{
    for (int v = 0; v < graph.size(); ++v) {
        const std::size_t i = std::size_t(v);
        graph.clearance[i] = contours[std::size_t(graph.polygon[i])].distance(graph.pos[i]);
        // The event time is the distance to the supporting lines of the node's wavefront
        // edges; near a reflex corner the corner itself is closer (a palm's junction between
        // two fingers), so the inscribed radius is the smaller of the two.
        graph.radius[i] = std::clamp(graph.radius[i], 0.0, graph.clearance[i]) + erosion;
    }
    collapseShortEdges(graph, kCollapseFraction);
    breakCycles(graph);
    removeSpurs(graph, kSpurSlack);
}

} // namespace

Expected<RawSkeleton, GeometryError> rawSkeleton(const Region &region,
                                                 const SkeletonOptions &options)
{
    if (options.targetVertices < 8 || options.targetVertices > options.maxVertices ||
        options.maxVertices > 1000 || !(options.simplifyTolerance >= 0.0) ||
        !std::isfinite(options.simplifyTolerance))
        return unexpected(
            failure(GeometryErrorCode::InvalidOptions, "The skeleton options are out of range."));
    const auto prepared = prepareContour(region, options);
    if (!prepared)
        return unexpected(prepared.error());
    if (prepared->region.empty()) {
        RawSkeleton raw = degenerateSkeleton(region);
        raw.erosion = prepared->erosion;
        raw.tolerance = prepared->tolerance;
        return raw;
    }
    DenseGraph graph;
    std::vector<ContourIndex> contours;
    Region contour;
    for (std::size_t p = 0; p < prepared->region.size(); ++p) {
        Polygon polygon = prepared->region[p];
        StraightSkeletonStatus status = StraightSkeletonStatus::Failed;
        for (int attempt = 0; attempt <= kRetries && polygon.outer.rows() >= 3; ++attempt) {
            if (attempt > 0)
                polygon = retryPolygon(*prepared, p, attempt, options);
            DenseGraph part;
            status = appendStraightSkeleton(polygon, int(contour.size()), options.cancelled, part);
            if (status == StraightSkeletonStatus::Cancelled || isCancelled(options))
                return unexpected(
                    failure(GeometryErrorCode::Cancelled, "The skeleton was cancelled."));
            if (status == StraightSkeletonStatus::Ok) {
                append(graph, part);
                break;
            }
        }
        if (status != StraightSkeletonStatus::Ok)
            continue; // this polygon gets no skeleton; the others still do
        contours.emplace_back(polygon);
        contour.push_back(std::move(polygon));
    }
    if (contour.empty())
        return unexpected(failure(GeometryErrorCode::SkeletonFailed,
                                  "The skeleton could not be built for this outline; "
                                  "simplify the drawing or redraw the part."));
    cleanUp(graph, contours, prepared->erosion);
    if (isCancelled(options))
        return unexpected(failure(GeometryErrorCode::Cancelled, "The skeleton was cancelled."));
    RawSkeleton raw = toRaw(compacted(graph), std::move(contour));
    raw.centroid = regionCentroid(region);
    raw.erosion = prepared->erosion;
    raw.tolerance = prepared->tolerance;
    return raw;
}

} // namespace finbook::geometry
