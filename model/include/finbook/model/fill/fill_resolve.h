// Which region each fill colours now, after whatever happened to the strokes since it was made.
//
// A fill keeps its colour on the face that holds its seed, provided that face is still bounded
// by at least one of the fill's strokes (a seed left behind by a moved outline must not colour
// whatever moved under it); failing that, on the face bounded by most of its strokes (at least
// half of them). A face cut in two by a new stroke keeps the colour on both halves: the faces
// that share one of the cutting strokes with the fill's face and are otherwise bounded only by
// the fill's strokes and the cutting ones inherit it. A region that has gone shows no colour;
// the fill stays in the object, so undoing the edit brings the colour back exactly. Where two
// fills hold their seeds in one face, the one tied best to its strokes has it: first the one
// with fewest strokes that now bound other faces instead (its region's outline moved away),
// then the larger share of strokes in common; on a tie a fill's first region wins against another
// fill's further one (Fill::more), and otherwise the seed lying deeper in the face (so two
// regions made one by erasing the line between them show the larger one's colour, whichever was
// filled last), a later fill winning an exact tie; the other shows nowhere and
// does not spread (a region that vanished under a moved head must not colour the body it left its
// seed in). A fill of several regions (Fill::more) resolves each region so, as if each were
// a fill of its own that comes right after the fill's first.
#pragma once

#include <finbook/model/fill/fill_regions.h>

#include <compare>
#include <functional>
#include <memory>
#include <optional>

namespace finbook::model {

// For each face, the index of the fill it shows, or -1.
std::vector<int> faceFills(const ObjectRegions &regions, const std::vector<Fill> &fills);

// A fill of `face` in `color`: its seed, its bounding strokes (flat).
Fill fillOfFace(const ObjectRegions &regions, int face, QRgb color);

// The object's fills after the edits the Fill tool makes on `face`; nullopt when nothing would
// change. Filling a face that shows a fill recolours that fill (all its regions); removing
// drops every fill that shows on the face (of a fill of several regions, only the region that
// shows there). New fills are shaded as the object's last fill is.
std::optional<std::vector<Fill>>
fillsWithFace(const ObjectRegions &regions, const std::vector<Fill> &fills, int face, QRgb color);
std::optional<std::vector<Fill>> fillsWithoutFace(const ObjectRegions &regions,
                                                  const std::vector<Fill> &fills, int face);
// Every face that shows no fill gets one in `color` (shaded as the object's last fill), except
// a face whose outline runs mostly along gap closures (geometry::closureShare > 0.5): a wedge
// nobody drew.
std::optional<std::vector<Fill>> fillsWithAllFaces(const ObjectRegions &regions,
                                                   const std::vector<Fill> &fills, QRgb color);

// What a posed object (`group`) shows, painted once for the bakes Apply Pose weighs:
// fillsAfterBake, shownFillAgreement and shownColourSeams each compare a bake with the pose's
// fills as painted (paintLayers), in pictures over the box of those fills and the bake's
// faces. Given a ShownPose they paint the fills (and the inked lines) once per box instead of
// once per call; the forms that take the group make one for the call. Holds `group` by
// reference (it must outlive this); for one thread at a time.
class ShownPose {
public:
    ShownPose(const StrokeGroup &group, double closeGap);
    ~ShownPose();
    ShownPose(const ShownPose &) = delete;
    ShownPose &operator=(const ShownPose &) = delete;
    const StrokeGroup &group() const { return m_group; }
    double closeGap() const { return m_closeGap; }
    struct Painted; // fill_bake.cpp
    Painted &painted() const { return *m_painted; }

private:
    const StrokeGroup &m_group;
    double m_closeGap;
    std::unique_ptr<Painted> m_painted;
};

// The fills of `group` once its pose has become its drawing (`baked`: its posed strokes, ids
// kept, as Apply Pose to Drawing makes them), so that the baked drawing shows exactly what the
// pose showed: each face of the baked drawing gets the fill the pose showed over most of it
// (as painted, paintLayers: a cut-out's layers and round joints included), or none where most
// of it showed none. Each fill is tied to one face (fillOfFace: that face's seed and bounding
// strokes, so no split rule spreads it), keeping its colour, shading and place in the list on
// its largest face; a fill shown on several faces (a limb passing over the body cuts it in
// two) keeps the others as its further regions (Fill::more), each tied to its face the same
// way, so the drawing still has the fills it had. A fill the pose showed nowhere is left out
// (undo brings it back).
std::vector<Fill> fillsAfterBake(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                 double closeGap);
std::vector<Fill> fillsAfterBake(const ShownPose &pose, const std::vector<Stroke> &baked);

// How much of the colour the pose (`group`, posed) showed a baked drawing (`baked`, with the
// fills fillsAfterBake would give it) keeps: of the area the pose shows filled, or the baked
// drawing would fill, the share (0-1) where the baked drawing shows the same fill; first where
// no inked line covers it (what the eye sees), then under the lines too (what erasing a line
// would uncover). Compared in that order: a bake that keeps more of what is seen is better,
// whatever it does under the lines. Pictures of fill indices at up to 1024 px, as
// fillsAfterBake's.
struct FillAgreement {
    double seen = 1.0;
    double underLinesToo = 1.0;
    auto operator<=>(const FillAgreement &) const = default;
    bool atLeast(double share) const { return seen >= share && underLinesToo >= share; }
    bool whole() const { return atLeast(1.0 - 1e-9); } // Apply Pose keeps every colour
};
FillAgreement shownFillAgreement(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                 double closeGap);
FillAgreement shownFillAgreement(const ShownPose &pose, const std::vector<Stroke> &baked);

// The colour of a line of no ink that closes a gap (keptGapClosers): it bounds regions like any
// stroke, and no renderer draws it (render.h draws no stroke of alpha 0).
constexpr QRgb kGapCloserColor = 0x00000000;

// A line of no ink (kGapCloserColor) through `points` (canvas px), `width` wide.
StrokeDataPtr lineOfNoInk(const std::vector<QPointF> &points, double width);
// The pen's usual width: the median width of the inked lines of `strokes` (0.5–64 px), 1
// when there are none. The lines of no ink take it: the automatic Close gaps distance follows
// the median width of all lines, and thinner ones would lower it.
double medianInkWidth(const std::vector<Stroke> &strokes);

// The gaps the pose shows closed that the baked drawing (`baked`, as Apply Pose makes it)
// would leave open: a pose can stretch a gap past the Close gaps distance, or change the
// drawing's size that the automatic distance follows, and the region behind it would open
// and lose its fill. Each such gap gets a closing line of no ink (kGapCloserColor, as
// Harmony's Close Gap tool draws invisible strokes), with new ids from `newId`, to add to the
// baked strokes; it is drawn by no renderer, and erasing it opens the gap. A gap that a line
// of no ink in `baked` already runs across (a cut-out closer) gets none.
//
// A gap counts as closed by the baked drawing when one of its closers ends near both ends of
// the one the pose showed. GapMatch::Near allows two pen widths (the baked regions find their
// own closer; an extra line beside it would only make slivers). GapMatch::Exact allows half a
// pen width: a closer the baked regions start a little further along a line (posed, a rest
// closer runs from where the rest drawing found it) leaves a wedge on the other side that the
// pose showed filled or empty, so the pose's own closer is drawn in; which keeps more of what
// the pose showed depends on the drawing (Apply Pose tries both).
//
// A closer kept as a line of no ink takes its ends' freedom, so the baked regions may then no
// longer make a closer that they made without it (two closers from one free end: a chord across
// a leg's top and, nearly along it, one to a hook's end beside it; kept, the second takes the
// end and the chord is gone). With `rematched`, the closers are matched again against the
// regions with the kept ones in (up to three times, while a closer drawn in ends within half a
// pen of the end of one not drawn in), and all the closers drawn in then go to `*rematched` when
// that is more than the first match drew in (else it is left empty); whether that keeps more of
// what the pose showed depends on the drawing too (Apply Pose tries both).
enum class GapMatch { Near, Exact };
std::vector<Stroke> keptGapClosers(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                   double closeGap, const std::function<Id()> &newId,
                                   GapMatch match = GapMatch::Near,
                                   std::vector<Stroke> *rematched = nullptr);

// Where a face of the baked drawing (`baked`) would take one colour but the pose showed two
// (or a colour and none) on it, say where a limb's cut or a fold left no line between them,
// or where the pose showed a fill that no baked face holds (a gap the pose showed closed and
// the baked lines leave open): lines of no ink (kGapCloserColor, the pen's median width), with
// new ids from `newId`, along the edge between the colours as the pose painted them. Pictures
// of the posed fills and the baked faces (as fillsAfterBake's) are compared, and each part of
// a face (or of no face) that showed another fill, larger than a speck and wider than the pen,
// is outlined where it borders the rest of its face (outside every face: where no inked line
// covers that border). Each line ends a hair past the face's edge, the line's middle or the
// seam it meets. `seams` is empty when no part differs (or the parts' outlines would exceed
// 4,000 points).
struct ShownColourSeams {
    std::vector<Stroke> seams;
    // The same seams without the stretches an inked line covers, ends on the ink's middle:
    // where a line dangles inside a face along the border (a body's outline that a limb hid
    // in part), a seam a hair beside it makes slivers that the regions merge, and may join
    // faces that were apart. Empty when no seam runs under ink.
    std::vector<Stroke> seamsOffInk;
    // Outside every face, the seams also across ink that only a line's edge covers: two lines
    // whose inks overlap but whose middles do not meet (a line's end stopping a little short
    // of another, its free end taken by a gap closer elsewhere) look closed, and the pose
    // showed the colour closed in there, but they bound no region. Where a third of the pen's
    // width would leave an edge of such a part bare, a seam crosses it. Empty when no part lies
    // outside every face or these are the seams.
    std::vector<Stroke> seamsAcrossInk;
    // The gaps the baked regions close, as lines of no ink: gap closing leaves a gap open
    // whose middle lies in a face already closed, so a seam that closes a face could open a
    // region elsewhere; with these added too, it cannot. (They also keep gaps from closing
    // otherwise where that was right, so Apply Pose tries each set of seams with and without
    // them.)
    std::vector<Stroke> keptClosures;
    FillAgreement bakedAgreement; // shownFillAgreement of `baked`, computed on the way
};
// The regions merge a face thinner than the pen into a neighbour (geometry/regions.h), and a
// strip along a line or a face's edge is the pictures' rounding: a part gets a seam only when
// it is `widerThanPen` times wider than the pen (twice its area over its perimeter).
constexpr double kSeamWiderThanPen = 1.25;
ShownColourSeams shownColourSeams(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                  double closeGap, const std::function<Id()> &newId,
                                  double widerThanPen = kSeamWiderThanPen);
ShownColourSeams shownColourSeams(const ShownPose &pose, const std::vector<Stroke> &baked,
                                  const std::function<Id()> &newId,
                                  double widerThanPen = kSeamWiderThanPen);

// A cut-out pose's pieces end their colour where they are cut, where no line is: a limb
// turned over the body shows its fill up to the cut, and the baked lines alone would join the
// limb's region to the body's behind it. Each stretch of a piece's painted outline (its fills
// as paintLayers clips them, sockets included) where the fill shown on its two sides differs,
// that no baked line (`baked`, inked) runs along and no piece above hides, gets a line of no
// ink (kGapCloserColor, the pen's median width), with new ids from `newId`, so that the baked
// regions end where the pieces' colours did. Its ends lie on the middle of the lines it meets;
// one line serves a cut that two outlines (or one, out and back) run along. Apply Pose adds
// these before keptGapClosers. Empty for anything but a cut-out pose with fills.
std::vector<Stroke> cutOutClosers(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                  double closeGap, const std::function<Id()> &newId);

// The face under canvas point p as the object shows now (posed where it is posed), or -1.
int displayedFaceAt(const ObjectRegions &regions, const StrokeGroup &group, QPointF p);

} // namespace finbook::model
