// The vector eraser on one stroke: the parts the eraser did not pass over, as new strokes
// with the stroke's colour, width and pressure (geometry/erase/polyline_erase.h does the
// geometry). A thick line goes where the eraser touches its drawn edge, not only its middle.
#pragma once

#include <finbook/geometry/erase/polyline_erase.h>
#include <finbook/model/types.h>

#include <QPointF>

#include <optional>
#include <vector>

namespace finbook::model {

// Pieces shorter than this (canvas px) are slivers the eyes read as dots: they go too.
constexpr double kMinPieceLength = 0.5;

// The pen sample at `at` along `points` (position and pressure interpolated; a place at a
// segment's end is that point exactly).
StrokePoint pointAlong(const std::vector<StrokePoint> &points, const geometry::PolylinePlace &at);

// What is left of `stroke` after a disc of `radius` (canvas px) swept along `rub` (one point
// is a single dab): std::nullopt when the eraser missed it, an empty list when it all goes,
// else the pieces in drawing order (a cut in the middle gives two). Cut ends are interpolated
// (position and pressure) where the drawn line meets the eraser's edge.
std::optional<std::vector<StrokeDataPtr>> cutStroke(const StrokeData &stroke,
                                                    const std::vector<QPointF> &rub, double radius);

class Document;

// Replaces stroke `strokeId` with `pieces` (cutStroke's) in its place, pushing one command per
// stroke onto the document's undo stack (open a macro around it for one step). The pieces are
// the same line: the fills that named the stroke among their bounding strokes name every
// piece instead, so a region the cut leaves closed keeps its fill and no neighbour's fill
// takes the pieces for a line cutting through it. Returns the pieces' ids.
std::vector<Id> pushStrokeCut(Document *doc, Id strokeId, const std::vector<StrokeDataPtr> &pieces);

} // namespace finbook::model
