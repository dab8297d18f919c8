// Drag events that continue the pose on screen (arapSolveFrom): the previous pose moved by
// step 1's answer to the handles' move and by the last event's momentum, or after a jump the
// cold start where it is much better.
#include "arap_solver.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace finbook::deform::detail {
namespace {

// A warm event whose handles moved further than this fraction of the object size since the
// start (a jump: undo, redo, a fast flick, not a mouse move of a drag) also tries the cold
// start, and takes it where its energy is below kColdShare of the warm start's. Undoing a
// drag to the pins' rest so shows the rest pose at once (the cold start is exact there), as
// before the drag. A mouse move during a 30-event drag of the quality bench's bend moves the
// far pins about 2.6 % of the width; on its 3-event drags (about 25 % per event) taking the
// cold start whenever its energy was lower left the 20k-vertex poses further from the optimum
// than the warm start did (median 2.6× against 1.4×): its energy falls more slowly after.
constexpr double kJump = 0.05;
constexpr double kColdShare = 0.5;

// How far the handles moved since `start` (the largest move).
double handlesMove(const ArapPrecompute &d, const Eigen::MatrixX2d &start, const Workspace &w)
{
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size();
    double move = 0.0;
    for (Eigen::Index c = 0; c < handles; ++c) {
        const int v = d.order(nf + c);
        move = std::max(move,
                        squaredMagnitude(w.positions(nf + c) - Complex(start(v, 0), start(v, 1))));
    }
    return std::sqrt(move);
}

// The first iterate of a warm event: the start moved by step 1's answer to how far the handles
// moved since it (step 1 is linear in the handles), so a pin's jump spreads over the shape as
// a similarity field instead of tearing the triangles next to the pin.
std::optional<DeformError> warmStart(const ArapPrecompute &d, const Eigen::MatrixX2d &start,
                                     Workspace &w, ArapSolveReport &report)
{
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size();
    auto q = w.positions.segment(nf, handles);
    auto &targets = w.handleTargets;
    targets = q;
    for (Eigen::Index c = 0; c < handles; ++c) {
        const int v = d.order(nf + c);
        q(c) -= Complex(start(v, 0), start(v, 1));
    }
    const int *order = d.order.data();
    const double *x = start.col(0).data(), *y = start.col(1).data();
    Complex *out = w.positions.data();
    auto error = similarityStep(d, w, report, false);
    w.handleMove = q;
    q = targets;
    if (error)
        return error;
    for (Eigen::Index k = 0; k < nf; ++k)
        out[k] += Complex(x[order[k]], y[order[k]]);
    return std::nullopt;
}

// Momentum: the previous event's passes moved its start by c (toward the optimum, which
// the few passes of an event never reach: the pose lags behind the pins). In a steady drag
// the next event needs about the same, so its start takes β·c on top of step 1's answer,
// β the handles' move this time along the last one's, over the last one's (at most
// kMaxMomentum; none for a reversed drag), kept only where it lowers the energy. With the
// lag carried forward instead of built up again, on the 8 slowest 20k-vertex drawings of the
// quality bench 30 events of its bend ended at 1.002–1.12× the converged energy (a tree
// sketch 1.52×) with an 8 ms budget, where plain warm events left 1.11–2.96× at 4 ms and
// 1.007–1.52× at 12 ms. Keeping the acceleration's history across events instead helped
// less and diverged on thin sketches (15× at 4 ms) unless each pass paid a second
// rotation fit to check it.
constexpr double kMaxMomentum = 1.5;
// Acceleration: a bend turns the pins along an arc, so the correction each event needs grows
// from one event to the next, and on a thin drawing whose passes barely shrink the long
// rotation error the pose lagged further behind (a 20k-vertex quickdraw tree ended its
// 30-event drag at 1.51× the converged energy, and 10 events with the pins held still
// brought it only to 1.18×). The start also takes kAcceleration·β times the change of the
// correction since the event before, kept only where it lowers the energy below the
// momentum's: the tree ended at 1.24×, the quality bench's 20k median stayed 1.0003×; 0.5
// ended at 1.20× but jerked (a vertex's second difference across events up to 1.4× the
// plain drag's), 1.0 at 1.25× and jerked 4×, and without the energy check 0.4 took several
// drawings from 1.03× to 1.13×. A larger momentum gain instead (1.5–2× the correction) ran
// away unchecked and, checked, jerked 7–10× (taken and refused on alternate events).
constexpr double kAcceleration = 0.4;

void addMomentum(const ArapPrecompute &d, Workspace &w)
{
    const Eigen::Index nf = d.freeCount;
    const double last = w.lastMove.squaredNorm();
    if (w.lastMove.size() != w.handleMove.size() || w.lastCorrection.size() != nf || !(last > 0.0))
        return;
    const double beta = std::clamp(w.lastMove.dot(w.handleMove).real() / last, 0.0, kMaxMomentum);
    if (!(beta > 0.0))
        return;
    auto free = w.positions.head(nf);
    const double plain = fitRotations(d, w.positions, w.rotations, true);
    free += beta * w.lastCorrection;
    const double momentum = fitRotations(d, w.positions, w.rotations, true);
    if (!(momentum < plain)) {
        free = w.warmPlain;
        return;
    }
    if (w.olderCorrection.size() == nf) {
        const double gamma = kAcceleration * beta;
        w.correctionChange = w.lastCorrection - w.olderCorrection;
        free += gamma * w.correctionChange;
        if (!(fitRotations(d, w.positions, w.rotations, true) < momentum))
            free -= gamma * w.correctionChange;
    }
}

} // namespace

// A usable warm start: the mesh's size, finite, within the coordinate range.
bool usableStart(const ArapPrecompute &d, const Eigen::MatrixX2d &start)
{
    return start.rows() == d.rest.size() && start.allFinite() &&
           (start.size() == 0 || start.cwiseAbs().maxCoeff() <= kMaxDeformCoordinate);
}

// The cold event's start (coarse rotations, or step 1) into w.positions.
std::optional<DeformError> coldStart(const ArapPrecompute &d, Workspace &w, ArapSolveReport &report,
                                     bool drag)
{
    if (drag && d.coarseLevel && twoLevelStart(d, w))
        return std::nullopt;
    if (d.triangleCluster.size() > 0) {
        coarseStart(d, w);
        return std::nullopt;
    }
    return similarityStep(d, w, report, false);
}

// The start of a warm event into w.positions, and how many passes follow it: the warm start
// (with momentum when the event continues the last one on this thread) and
// data.warmDragPasses; after a jump (kJump) the warm or the cold start (kColdShare), and the
// cold event's passes less one (the warm start and the comparison cost about that). With a
// two-level start (large meshes), a jump is a cold event: no warm start, no comparison, the cold
// event's passes. Against the comparison above (with the cold event's passes less one), 3-event
// drags of the 55 drawings at ~20k vertices ended at 1.011× the converged energy in the median
// instead of 1.027×, with no worse maximum (1.157×, a fork), and their slowest event took
// 8.2 ms in the median instead of 10.8 ms.
Expected<int, DeformError> warmOrCold(const ArapPrecompute &d, const Eigen::MatrixX2d &start,
                                      Workspace &w, ArapSolveReport &report, bool continued)
{
    const bool jump = d.freeCount > 0 && handlesMove(d, start, w) > kJump * d.objectSize;
    if (jump && d.coarseLevel) {
        w.warmPlain.resize(0); // no momentum from a jump
        w.lastCorrection.resize(0);
        if (auto error = coldStart(d, w, report, true))
            return unexpected(std::move(*error));
        return d.dragPasses;
    }
    if (auto error = warmStart(d, start, w, report))
        return unexpected(std::move(*error));
    auto free = w.positions.head(d.freeCount);
    w.warmPlain = free;
    if (!continued) // a new drag: nothing of the last one's corrections carries over
        w.lastCorrection.resize(0);
    if (!jump) {
        if (continued && d.freeCount > 0)
            addMomentum(d, w);
        return d.warmDragPasses;
    }
    w.warmPlain.resize(0); // no momentum from a jump
    const double warm = fitRotations(d, w.positions, w.rotations, true);
    w.iterate = free;
    if (auto error = coldStart(d, w, report, true))
        return unexpected(std::move(*error));
    if (!(fitRotations(d, w.positions, w.rotations, true) < kColdShare * warm))
        free = w.iterate;
    return std::max(1, d.dragPasses - 1);
}

bool continuesDrag(const ArapPrecompute &d, const Workspace &w, const Eigen::MatrixX2d &start)
{
    return w.dragOwner == &d && w.dragPose.rows() == start.rows() &&
           std::memcmp(w.dragPose.data(), start.data(),
                       sizeof(double) * std::size_t(start.size())) == 0;
}

void rememberDrag(const ArapPrecompute &d, Workspace &w, const Eigen::MatrixX2d &U)
{
    w.dragOwner = &d;
    w.dragPose = U;
    if (w.warmPlain.size() == d.freeCount) { // what this event's passes (and repair) added
        if (w.lastMove.size() > 0 && w.lastCorrection.size() == d.freeCount)
            w.olderCorrection.swap(w.lastCorrection);
        else
            w.olderCorrection.resize(0);
        w.lastCorrection = w.positions.head(d.freeCount) - w.warmPlain;
        w.lastMove = w.handleMove;
    } else {
        w.lastMove.resize(0);
        w.olderCorrection.resize(0);
    }
}

} // namespace finbook::deform::detail
