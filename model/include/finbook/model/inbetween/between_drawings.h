// Between Drawings (issue 50): in-betweens of two different drawings of one object, key A and
// key B, with different strokes, stroke counts, orders and directions.
//
// A's mesh (the one its deformers use) is fitted onto B's lines as rigidly as possible
// (deform/between/rigid_fit.h: ARAP-regularised non-rigid ICP), then the fitted motion is
// interpolated as rigidly as possible (deform/between/arap_interpolation.h: Alexa, Cohen-Or &
// Levin 2000). An in-between at t is A's strokes carried by the motion at t; over the last part
// of the range (BetweenOptions::crossFade) they fade out while B's own drawing fades in over
// them as an object of its own, carried backwards by the same motion (each B point placed by
// affine coordinates in the fitted triangle nearest it, so that at t = 1 it is exactly where B
// drew it): the sequence lands on B's lines and colours. Fills follow as Apply Pose makes them
// follow a pose: each keeps the colour its carried region shows.
#pragma once

#include <finbook/deform/between/rigid_fit.h>
#include <finbook/geometry/erase/polyline_erase.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/inbetween/inbetween_plan.h>
#include <finbook/model/types.h>

#include <QString>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace finbook::deform::between {
struct ArapInterpolation;
}

namespace finbook::model {

// The fit's stiffness for drawings: stiff to relaxed, stopping short of the most relaxed
// stages of rigid_fit.h's default (on ../shared/data they let limbs stretch by 5–40 % to
// follow lines, and fail more fits for stretching; figures in tests/README.md).
inline deform::between::RigidFitOptions drawingFitOptions()
{
    deform::between::RigidFitOptions o;
    o.stiffness = {3e-2, 1e-2, 3e-3};
    return o;
}

struct BetweenOptions {
    // The share of the range at its end over which A's strokes fade out and B's fade in:
    // 0.3 = from t = 0.7. 0 = no cross-fade (B's strokes never shown). Clamped to 0..1.
    double crossFade = 0.3;
    // Turn A's parts about their joints (its automatic skeleton) to B before the fit
    // (rigid_fit.h, the articulated coarse step): limbs B shows turned far are found.
    bool articulated = true;
    // Mesh each of A's closed lines drawn over a larger one (an arm's top over the body) on its
    // own, hinged where the two overlap (DrawingFit::meshed), rather than all of A as one.
    bool layeredParts = true;
    deform::between::RigidFitOptions fit = drawingFitOptions();
};

// A correspondence pin: a point of A's drawing (canvas px, on or inside its shape) and where it
// belongs on B.
struct BetweenPin {
    QPointF onA;
    QPointF onB;
    friend bool operator==(const BetweenPin &, const BetweenPin &) = default;
};

// One of A's closed lines drawn over a larger one (DrawingFit::meshed): its stroke (index into
// DrawingFit::a's strokes), its mesh's triangles (rows of meshed's F), and the fill it shows
// (none: unfilled).
struct LayeredPart {
    std::size_t stroke = 0;
    Eigen::Index firstTriangle = 0, triangles = 0;
    std::optional<Fill> fill;
};

// A point on a line of A: its stroke (index) and its place along the stroke's points.
struct LineAnchor {
    std::size_t stroke = 0;
    geometry::PolylinePlace place;
};

// The fit of A onto B and what the in-betweens need from it. Immutable.
struct DrawingFit {
    StrokeGroup a, b; // the keys as shown (a posed key as its pose would be applied)
    // A's mesh and every A stroke point in it: the mesh its deformers use, or, where A has
    // closed lines drawn over larger ones (an arm's top over the body), the rest of A's lines
    // meshed together and each such line's inside meshed on its own, stacked (the first
    // mesh's vertices and triangles, then each part's), so that the part turns over the other
    // instead of bending the flesh the union of the two would make of them.
    std::shared_ptr<const MeshedObject> meshed;
    // Per part drawn over another, a vertex of the other's mesh and one of the part's, both
    // where the two overlap (rows of meshed's V): the hinge the fit and the motion hold together.
    std::vector<std::array<int, 2>> hinges;
    // The parts drawn over others, topmost (drawn last) first; the rest's mesh is meshed's
    // first restTriangles triangles. An in-between's fills are those its carried faces show:
    // the topmost part's over it (shownFills), else what A shows under the parts (A's faces with
    // the parts' lines left out, underRegions, and the fill each shows, underFills) where the
    // rest's mesh takes it back to.
    std::vector<LayeredPart> parts;
    Eigen::Index restTriangles = 0;
    ObjectRegionsPtr underRegions;
    std::vector<std::optional<Fill>> underFills;
    // The gaps underRegions closes (a body's outline drawn with a gap that an arm's top
    // covered), closed in every in-between by a line of no ink between the two ends as carried.
    std::vector<std::array<LineAnchor, 2>> underClosures;
    // A's faces as shown and the fill each shows: a face on a part shows what A shows where the
    // part's carried mesh takes it back to (a stripe on a sleeve keeps its colour).
    ObjectRegionsPtr shownRegions;
    std::vector<std::optional<Fill>> shownFills;
    std::shared_ptr<const deform::between::RigidFitSource> source;
    std::shared_ptr<const deform::between::RigidFitTarget> target;
    deform::between::RigidFitResult fit;
    std::shared_ptr<const deform::between::ArapInterpolation> motion; // rest → fitted
    // Each B stroke point (stroke after stroke) in the fitted mesh: its triangle and affine
    // coordinates there (they may lie outside it for a point beyond A's shape), for
    // geometry::applyEmbedding with the fitted mesh's vertices.
    geometry::Embedding bInFit;
    std::vector<BetweenPin> pins;          // the correspondence pins it was made with
    deform::between::FitSkeleton skeleton; // A's automatic skeleton (its parts), if any
    double closeGap = -1.0;                // the document's Close gaps the fit was made for
    double seconds = 0.0; // the time the fit took (mesh, precompute, fit, interpolation)
};

// Fits A onto B. Errors are sentences for the user; a fit that fails says where (the region of
// A whose lines found nothing to match in B).
Expected<std::shared_ptr<const DrawingFit>, QString>
fitDrawings(const StrokeGroup &a, const StrokeGroup &b, double closeGap,
            const std::vector<BetweenPin> &pins = {}, const BetweenOptions &options = {});

// The fit again with `pins` instead of previous.pins, started from where `previous` settled
// (rigid_fit.h rigidRefit: a few iterations at the last stiffness), for pins dragged live.
Expected<std::shared_ptr<const DrawingFit>, QString>
refitDrawings(const DrawingFit &previous, const std::vector<BetweenPin> &pins,
              const BetweenOptions &options = {});

// The first key's drawing in the in-between at t (t clamped to 0..1): a copy of A (its name
// and mesh density; no rig, no pose) with its strokes carried to t and its fills as Apply Pose
// would give them (fillsAfterBake); inside the cross-fade its lines' ink fades (its fills
// stay, under the second key's fading in). Ids are
// A's: give them new ones before putting the drawing in a document.
StrokeGroup betweenDrawing(const DrawingFit &fit, double t, const BetweenOptions &options = {});

// Inside the cross-fade, the second key's drawing as it fades in over the first's: B's strokes
// carried backwards to t (its fills following as A's do) (at t = 1 exactly where B drew them), its
// lines' ink and its fills' colours at the fade's share of their alpha. A separate object, so that
// its lines do not cut the first drawing's regions into slivers (nor A's cut B's); nullopt before
// the cross-fade. Ids are B's.
std::optional<StrokeGroup> fadingInDrawing(const DrawingFit &fit, double t,
                                           const BetweenOptions &options = {});

// The fits of the objects the two keys show drawn differently (differentDrawings), in
// inbetween_plan.h's DrawingFits form, and for each pair that could not be fitted its position
// and the reason.
struct KeyFits {
    DrawingFits fits;
    std::vector<std::pair<int, QString>> failures;
};
KeyFits fitKeyDrawings(const Frame &first, const Frame &second, double closeGap,
                       const BetweenOptions &options = {});

// The drawing `group` shows, as editable strokes: itself at rest, or its pose applied (the
// strokes and fills Apply Pose would make; new stroke ids from `newId`).
StrokeGroup shownDrawing(const StrokeGroup &group, double closeGap,
                         const std::function<Id()> &newId);

} // namespace finbook::model
