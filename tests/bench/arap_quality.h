// Pose quality of the ARAP deformer for finbook-bench arap: energy against a converged
// reference, area change and flipped triangles, per solve mode, on one bend of a mesh.
#pragma once

#include "../deform/drawing_bend.h"

#include <QJsonObject>
#include <QList>
#include <QString>

#include <Eigen/Core>

namespace finbook::bench {

// Pins every vertex in the left 6 % of the x extent at rest and every vertex in the right
// 6 % rotated by `degrees` about the centroid of the left pins (the right end swings round
// the held left end: a bend). Solves it the paper's way (two steps), as a drag event and as
// a stored pose, and a converged reference (tolerance 1e-10 of the size, flip repair off).
// Columns: ratios of the cotangent ARAP energy (arapCotangentEnergy) to the reference's, area
// change in %, flipped triangles (_flips_beyond_reference: those not flipped in the reference;
// _flips_apart_from_reference: those sharing no vertex with a reference flip;
// _flips_over_reference_folds: fold by fold, flips over the reference's), times in ms
// (fastest of several runs), passes run, drag_over_two_step (drag time over the two steps'),
// the stored pose's last relative energy change. drag_* is one cold drag event to the bend's
// targets (arapSolve, Drag: from step 1 or coarse rotations, what every event of a drag
// would be without a warm start); warm_* the last event of the bend reached in 30 events,
// each started from the previous event's pose (arapSolveFrom), warm_ms the median event and
// warm_event_max_ms the slowest; fast_* the same in 3 events.
// With a dumpDirectory, also writes the bend and the reference pose there as text (see dump
// in arap_quality.cpp) for checking against another solver.
QJsonObject measureBend(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, double degrees,
                        const QString &dumpDirectory = {});

// The rows of measureBend over many drawings in one row (bench "arap_quality_summary"): per
// mode (drag, fast, warm, stored) the median and largest energy ratio (and the drawing with
// the largest), the flip columns summed and the median CPU time; the stored pose's passes and
// time (median and largest) and how many converged; the reference's flips and the
// negative-weight edges summed. Rows with an error count in "failed"; rigid bends (null
// ratio) are left out of the ratios.
QJsonObject summariseBends(const QList<QJsonObject> &rows);

} // namespace finbook::bench
