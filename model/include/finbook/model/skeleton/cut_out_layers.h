// A cut-out pose's layers (DeformedStrokes::pieces, pieceOf, sockets, body and motions: what
// paintLayers draws the limbs over the body with) live only in memory; a file stores the
// posed strokes and the pose. These bring the layers back for a document just read, so a
// reopened file, its export and its thumbnail draw the limbs over the body as the editor did.
#pragma once

#include <finbook/model/types.h>

#include <vector>

namespace finbook::model {

// Whether `group` shows a posed cut-out skeleton without its layers (as read from a file).
bool lacksCutOutLayers(const StrokeGroup &group);

// Whether `solved` (a fresh solve of a group's pose) brings the layers for `stored` (the
// group's pose as read): it has layers and its strokes and picture vertices are the stored ones
// to within kCutOutLayersTolerance px.
constexpr double kCutOutLayersTolerance = 0.01;
bool restoresLayers(const DeformedStrokes &solved, const DeformedStrokes &stored);

// Re-solves each such object of `frames` (one setup per drawing and rest definition) and
// takes the solved pose, layers and all, where restoresLayers says it is the stored one: the
// stored drawing is what the file shows and is never changed here (a pose that no longer
// solves the same, or does not solve, stays as stored, drawn flat).
// `closeGap`: the document's Close gaps. Returns how many objects got their layers back.
int restoreCutOutLayers(std::vector<Frame> &frames, double closeGap);

} // namespace finbook::model
