// The hidden parts of lines that an edit uncovers.
//
// Apply Pose keeps a line's part that a cut-out piece covered as a hidden part (kHiddenLineColor:
// drawn by no renderer, bounding no region). An arm raised behind the head is cut at the head's
// outline: its top is hidden under the head's fill and the arm's region is closed by the head's
// outline. When an edit then takes the cover away (the head lassoed and moved off, or deleted),
// the arm would be left open at the top, and lose its fill. Instead, the runs of hidden parts
// that a fill covered before the edit and that no fill covers after it are inked again, in the
// colour of their line's inked parts: the arm shows its whole outline and keeps its fill, as a
// paper arm does when the head above it is lifted off. A run a fill still covers stays hidden,
// and so does every hidden part an edit did not uncover: an edit never changes what it did not
// touch.
#pragma once

#include <finbook/model/types.h>

#include <vector>

namespace finbook::model {

class Document;

// A hidden part that an edit uncovered in part or whole: its pieces in order along it, each
// beginning where the one before ends, the uncovered runs inked and the rest still hidden.
struct UncoveredPart {
    Id part = kNoId;
    std::vector<StrokeDataPtr> pieces;
};

// The hidden parts of `after` (an object's strokes and fills after an edit) with runs that a fill
// the edit took away covered in `before` (the same object before it; a fill every line of which
// the edit moved or removed: the head's, not the arm's that the head's outline also bounded)
// and that no fill covers now: covered before on both sides of the line, a pen width off it
// (a part along a fill's edge was not under it), and after at the line itself (a run inked
// ends on the edge of a fill still over the line). A run shorter than two pen widths
// takes the state of the runs beside it, except that a short run at an end of a part is never
// inked (the end lies on the outline that hid it). Parts that are not in both, or whose points
// changed in number, are left alone.
std::vector<UncoveredPart> uncoveredParts(const StrokeGroup &before, const StrokeGroup &after,
                                          double closeGap);

// uncoveredParts of the object `groupId` now against `before`, pushed onto the undo stack (open
// a macro around it): a part uncovered whole is inked in place (its id kept), one uncovered in
// part is cut into its pieces (pushStrokeCut: fills that named it name every piece). Returns
// whether anything was uncovered.
bool pushUncoveredParts(Document *doc, Id groupId, const StrokeGroup &before);

} // namespace finbook::model
