// Planning in-betweens: given two key frames and t values, the frames between them. Pure: it
// reads the keys and returns values; poses are solved later (inbetween_solve.h or the
// DeformController) and ids are assigned by InsertInbetweensCommand.
#pragma once

#include <finbook/model/inbetween/rig_interpolation.h>
#include <finbook/model/inbetween/spacing.h>

#include <QString>

#include <memory>
#include <vector>

namespace finbook::model {

struct DrawingFit; // inbetween/between_drawings.h

// Per position in the keys' object lists: the fit of the first key's object onto the second
// key's (Between Drawings), where the two show different drawings; null elsewhere.
using DrawingFits = std::vector<std::shared_ptr<const DrawingFit>>;

struct InbetweenOptions {
    Spacing spacing;
    TargetPath path = TargetPath::Arc;
};

// What happens to one object of the keys in the in-betweens.
enum class ObjectFate {
    Interpolated,   // same drawing and rig rest definition in both keys: targets interpolated
    HeldNoRig,      // same drawing in both keys, no rig: the first key's object is held
    HeldRigDiffers, // same drawing, rigs of another kind or rest definition: first key's held
    FirstKeyOnly,   // only in the first key (or drawn differently): shown while t < 0.5
    SecondKeyOnly,  // only in the second key (or drawn differently): shown while t >= 0.5
    Fitted, // drawn differently in each key, the first fitted onto the second (Between Drawings)
};

struct InbetweenObjectReport {
    QString name;         // the object's name in the key it comes from (the first if both)
    int firstIndex = -1;  // position in the first key's objects, -1 if not there
    int secondIndex = -1; // position in the second key's objects, -1 if not there
    ObjectFate fate = ObjectFate::HeldNoRig;
    RigKind rig = RigKind::None; // the first key's rig kind (the second's for SecondKeyOnly)
};

struct InbetweenPlan {
    std::vector<double> times;                  // t of each frame, as given
    std::vector<Frame> frames;                  // one per t; ids are the keys' (not yet new)
    std::vector<InbetweenObjectReport> objects; // first key's objects, then second-only ones
    int interpolatedCount() const;
};

// Objects are matched by position in the frame. A pair with the same drawing (the same shared
// stroke data, in order, and mesh density) is one object: interpolated when both rigs have the
// same rest definition, else held from the first key. Anything else exists in one key only and
// is held there: before the midpoint (t < 0.5) an in-between is built on the first key's object
// list, from it on the second's, so such objects switch over half way like a drawn breakdown.
// Interpolated objects have no pose yet (deformed == nullptr); held ones keep their key's pose.
// Every frame gets the first key's hold. Non-finite t counts as 0.
// With `fits` (DrawingFits), a pair drawn differently that has a fit is one object too
// (ObjectFate::Fitted): each in-between shows betweenDrawing(fit, t), as editable strokes
// with no rig, under the first key's object's id and name.
InbetweenPlan planInbetweens(const Frame &first, const Frame &second,
                             const std::vector<double> &times, TargetPath path = TargetPath::Arc,
                             const DrawingFits &fits = {});

// The pairs of objects the two keys show drawn differently at the same position (both with
// inked lines, neither posed by a swap set): the positions that Between Drawings fits.
std::vector<int> differentDrawings(const Frame &first, const Frame &second);

} // namespace finbook::model
