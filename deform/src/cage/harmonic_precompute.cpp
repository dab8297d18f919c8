#include "harmonic_internal.h"

#include <finbook/geometry/cage/cage_polygon.h>

#include <algorithm>
#include <exception>
#include <thread>

namespace finbook::deform {
namespace {

using detail::cageError;

// Below this many vertices the locator takes well under a millisecond to build: a thread's
// start and hand-over (milliseconds on a busy machine) would cost more.
constexpr Eigen::Index kParallelLocatorVertices = 3000;

Expected<geometry::CageMesh, DeformError> meshFor(const Eigen::MatrixX2d &corners,
                                                  const CageOptions &options)
{
    if (auto error = geometry::checkCage(corners))
        return unexpected(cageError(DeformErrorCode::InvalidCage, error->message));
    const long target = std::clamp(options.targetVertices, 3L, kMaxCageVertices);
    const double maxEdge =
        options.maxEdge > 0.0 ? options.maxEdge : geometry::cageEdgeLength(corners, target);
    const double vertices = geometry::cageVertexEstimate(corners, maxEdge);
    if (!(vertices <= double(kMaxCageVertices)) ||
        vertices * double(corners.rows()) > double(kMaxCageCoordinates))
        return unexpected(cageError(DeformErrorCode::TooLarge,
                                    "The cage's mesh would be too fine for its " +
                                        std::to_string(corners.rows()) +
                                        " corners; use a coarser mesh or fewer corners."));
    auto mesh = geometry::meshCage(corners, maxEdge);
    if (!mesh)
        return unexpected(cageError(DeformErrorCode::MeshingFailed, mesh.error().message));
    return std::move(*mesh);
}

CagePrecomputeResult precompute(const Eigen::MatrixX2d &corners, const CageOptions &options,
                                const std::function<bool()> &cancelled)
{
    const auto stop = [&cancelled] { return cancelled && cancelled(); };
    const auto cancelledError = [] {
        return unexpected(cageError(DeformErrorCode::Cancelled, "precompute was cancelled"));
    };
    auto mesh = meshFor(corners, options);
    if (!mesh)
        return unexpected(mesh.error());
    if (stop())
        return cancelledError();
    auto d = std::make_shared<CagePrecompute>();
    d->restCorners = corners;
    d->mesh = std::move(*mesh);
    d->extent = (corners.colwise().maxCoeff() - corners.colwise().minCoeff()).norm();
    detail::VertexAdjacency adjacency = detail::vertexAdjacency(d->mesh.V.rows(), d->mesh.F);
    detail::Dissection dissection =
        detail::nestedDissection(d->mesh.V, adjacency, d->mesh.boundaryCount);
    detail::renumberInterior(d->mesh, adjacency, dissection.order);
    // Point location only needs the mesh: on large meshes it is built beside the assembly.
    std::exception_ptr locatorFailure;
    std::thread locatorThread;
    if (d->mesh.V.rows() >= kParallelLocatorVertices) {
        locatorThread = std::thread([&] {
            try {
                d->locator.emplace(d->mesh.V, d->mesh.F);
            } catch (...) {
                locatorFailure = std::current_exception();
            }
        });
    } else {
        d->locator.emplace(d->mesh.V, d->mesh.F);
    }
    const auto finish = [&] {
        if (locatorThread.joinable())
            locatorThread.join();
        if (locatorFailure)
            std::rethrow_exception(locatorFailure);
    };
    const detail::HarmonicSystem system =
        detail::assembleHarmonicSystem(d->mesh, adjacency, std::move(dissection.tree), d->W);
    d->negativeEdgeWeights = system.negativeWeights;
    if (stop()) {
        finish();
        return cancelledError();
    }
    const auto error = detail::solveHarmonicSystem(system, d->W, d->relativeResidual, cancelled);
    finish();
    if (error)
        return unexpected(*error);
    d->minCoordinate = d->W.size() > 0 ? d->W.minCoeff() : 0.0;
    return std::shared_ptr<const CagePrecompute>(std::move(d));
}

} // namespace

CagePrecomputeResult cagePrecompute(const Eigen::MatrixX2d &corners, const CageOptions &options,
                                    std::function<bool()> cancelled)
{
    try {
        return precompute(corners, options, cancelled);
    } catch (const std::bad_alloc &) {
        return unexpected(cageError(DeformErrorCode::TooLarge,
                                    "There is not enough memory for the cage's coordinates."));
    }
}

} // namespace finbook::deform
