// Regions of a drawing: the faces of the planar arrangement of its strokes' centre lines,
// after short gaps between a free stroke end and another stroke have been closed. What a
// paint bucket fills and what the object's shape (object_shape.h) adds to the ink.
//
// Strokes are simplified first (Douglas–Peucker at a tenth of the pen width). A stroke end
// is *free* when no other part of the drawing comes within the two pens' half widths of it;
// an end that does come that close is joined to the nearest point silently (it touches). A
// free end is joined to a point of a stroke or to another free end by a straight closure when
// the closure is at most closeGap long, crosses no stroke and no other closure, runs through
// no region that is already closed, and closes a new face (its two ends are already connected
// through the drawing, or a second closure connects the same two parts, or it completes a
// ring of closures through three or more parts: an outline drawn in several strokes that
// each stop short of the next); closures that continue the end's direction are preferred. Faces
// thinner than a pen width (slivers from overshoots) are merged into their neighbour.
//
// Then open *mouths* are closed, as people read an outline drawn open at a wrist, at the foot
// of a trunk or at a tail as a closed shape. Two free ends still left that lie side by side
// are joined by the chord between them when:
// - facing angle: neither leans away from the other by more than ~110° from the chord (~145°
//   when both ends are one line's: a hand or an arm drawn in one stroke, flaring at the
//   wrist or shoulder), and
//   they do not point at each other head-on (that is a gap, for the gap distance to decide);
//   two separate lines that spread apart (legs, antennae, whiskers hung from a body) are
//   taken only when the face they close holds most of the drawing's ink on its outline (a
//   trunk's two sides under the crown);
// - they are connected through the drawing, or a gap of up to twice the gap distance
//   between free ends connects them;
// - the face the chord closes is a shape the mouth opens, not a sliver or the space between
//   appendages: the mouth no wider than twice the widest circle inside it (the mouth's width
//   against the local width), the face at least 0.4 d² in area, the chord and its gaps at
//   most 30 % of the face's outline, every line around it chained end to end with the
//   mouth's sides, and the face bordering faces closed already along less than half the
//   mouth's width (the space under a body between two legs drawn as lines is no shape);
// - the mouth opens onto nothing of its own: no line chained with its sides within 0.6 of
//   its width beyond it (a circle with a gap is not cut in two across it; a wing may open
//   onto the body it is drawn against);
// - the chord crosses no stroke and no closure and runs through no closed region, as
//   closures do. Narrower mouths first.
#pragma once

#include <finbook/geometry/expected.h>
#include <finbook/geometry/geometry_error.h>
#include <finbook/geometry/region.h>
#include <finbook/geometry/stroke_input.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::geometry {

struct RegionsOptions {
    // Gaps up to this many px between a free stroke end and another stroke (or another free
    // end) are closed. < 0 means automatic: autoCloseGap(strokes). Must not be NaN or above
    // kMaxPenWidth.
    double closeGap = -1.0;
    // Open mouths are closed too (a hand open at the wrist, a trunk open at the bottom): see
    // above. Only with closeGap != 0, which turns every closure off.
    bool closeMouths = true;
};

struct GapClosure {           // a segment added to close a face
    Eigen::Vector2d from, to; // from = the free end
    int fromStroke = -1;      // index into the input strokes
    int toStroke = -1;        // index into the input strokes
    bool mouth = false;       // a mouth's chord, not a gap (may be longer than closeGap)
};

struct Face {        // one bounded face of the arrangement (after gap closing)
    Polygon polygon; // region.h conventions: outer A > 0, holes A < 0 (nested faces are holes)
    std::vector<int> strokes; // indices of the input strokes on its boundary, sorted, unique
    Eigen::Vector2d seed;     // a point strictly inside (not in a hole), far from the boundary
    double area = 0.0;        // polygon area (outer minus holes)
};

struct Regions {
    std::vector<Face> faces; // tiny faces (slivers from overshoots) already merged away
    std::vector<GapClosure> closures;
    int freeEnds = 0;      // free stroke ends found (before closing)
    double closeGap = 0.0; // the gap actually used (px)
};

// The automatic close-gap distance: 6 % of the drawing's bounding-box diagonal, at least four
// and at most forty pen widths (median width of the strokes). 0 for no finite points.
double autoCloseGap(const std::vector<StrokeInput> &strokes);

// Errors as silhouette(): EmptyInput, InvalidWidth, InvalidOptions, CoordinateOutOfRange,
// TooManyPoints (also: more than 20,000 segments after simplification or more than 4,000
// crossings, as scribbled shading makes), ClippingFailed (reported, never thrown).
// Never NaN, never throws. Strokes that reduce to a dot take part in no face.
Expected<Regions, GeometryError> computeRegions(const std::vector<StrokeInput> &strokes,
                                                const RegionsOptions &options = {});

// Index of the innermost face containing (x, y), or -1.
int faceAt(const Regions &regions, double x, double y);

// The share (0..1) of face `face`'s outer outline that runs along gap closures rather than
// strokes: a face bounded mostly by closures (a wedge between an outline and a line beside
// it) is one nobody drew, which Fill All leaves alone. 0 for an index out of range.
double closureShare(const Regions &regions, int face);

} // namespace finbook::geometry
