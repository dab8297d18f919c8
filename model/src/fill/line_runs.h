// How a cut-out pose's lines are cut into what shows and what is hidden, shared by the
// painting (paint_layers.cpp) and Apply Pose (cut_out_bake.cpp) so that both decide the same.
#pragma once

#include <finbook/model/fill/fill_render.h>

#include <QImage>
#include <QTransform>

#include <functional>
#include <optional>
#include <vector>

namespace finbook::model::line_runs {

// A segment of a posed line, the layer it is drawn on (paintLayers), and whether it is part
// of an arc that joins the line across a cut (cutOutSeam).
struct Segment {
    StrokePoint a, b;
    std::size_t layer;
    bool seam = false;
};

// Whether a point of a line shows, or why it is hidden: under a piece drawn over it, or laid
// inside one fill (MergedLines).
enum class Hidden { No, Covered, Merged };

// A stretch of a line that shows, or that is hidden, as a polyline of two points or more.
struct Run {
    std::vector<StrokePoint> points;
    Hidden hidden = Hidden::No;
    bool shows() const { return hidden == Hidden::No; }
};

// A segment, whole or in part, and whether it shows.
struct Piece {
    Segment segment;
    Hidden hidden = Hidden::No;
};
std::vector<Piece> piecesOf(const std::vector<Segment> &segments);

// Whether the point p of a segment is hidden (for one reason).
using Hides = std::function<bool(const Segment &segment, QPointF p)>;

// `pieces` with each one that shows cut where `hides` changes (looked at every 2 px along it,
// found by bisection between two looks that differ), the hidden parts marked `kind`. Cut for one
// reason after another, each reason decides the same on the same segments whatever came before: the
// painting cuts only for MergedLines, Apply Pose for it and then for the pieces drawn over a line.
std::vector<Piece> cutWhere(const std::vector<Piece> &pieces, const Hides &hides, Hidden kind);

// The pieces joined into runs of one kind, in order: each run ends where the next begins, so
// together they are the whole line.
std::vector<Run> runsOf(const std::vector<Piece> &pieces);

// `runs` with the covered ones shorter than `shortest` (px) shown, and runs of one kind that
// follow each other joined (each begins where the one before ends). Merged runs stay hidden
// however short: the painting cuts them so too, and each side of them is of one fill.
std::vector<Run> withoutSlivers(std::vector<Run> runs, double shortest);

// A hidden run shorter than this (px, and than half the pen) shows: a cover's edge that grazes a
// line, often at a joint where the line ends, splits off a stub that the regions join to the
// wrong line, opening the loop the line closed (a body losing its fill after Apply Pose).
constexpr double kShortestHiddenRun = 1.0;

// Whether two pieces' motions differ (the joint between them turned; a thousandth of a px in
// the shift, a millionth in the turn, is none).
bool movedApart(const QTransform &a, const QTransform &b);

// Which fill the given items show at a point (the last holding it; −1 none), as a raster of a
// px per canvas px (coarser beyond kMostPixels), so that each answer is one read.
class FillRaster {
public:
    FillRaster() = default;
    explicit FillRaster(const std::vector<const FillItem *> &items);
    int at(QPointF p) const;

private:
    static constexpr double kMostPixels = 4.0e6;
    QImage m_image; // fill + 1 per px
    QPointF m_origin;
    double m_scale = 1.0;
};

// Lines a cut-out pose laid inside one fill. A line of a piece that moved rigidly that at rest
// bounded a fill, with that fill on one side and no fill on the other (the edge of an arm whose
// body is of the same colour, or the body's edge next to the arm), but that the pose laid
// where the picture shows that fill all round it (the arm turned in over its body, the body's
// edge over the arm's socket): it would show as a stub ending at the joint, a line across one
// area of one colour that the drawing never had. Both the picture and Apply Pose leave such a
// line out where it lies so, as the rest drawing showed no line between the arm and its body.
class MergedLines {
public:
    // `layers`: the pose's painted layers with their fills (their strokes are not read);
    // `rest`: the object's fills at rest (fillList of it without its pose). Neither is kept.
    MergedLines(const StrokeGroup &group, const std::vector<PaintLayer> &layers,
                const std::vector<FillItem> &rest);
    // Whether the point p of a line `width` px wide drawn on `layer` lies so: the picture
    // shows one fill all round it (half its width and a px away), and at rest that fill lay
    // on one side of it and no fill on the other, or it is on a seam's arc (which stands for
    // the outline there).
    bool hides(std::size_t layer, QPointF p, double width, bool seam) const;
    // Whether any line can lie so (a cut piece moved rigidly against the roots' one, and the
    // object has fills).
    bool any() const { return m_any; }

private:
    FillRaster m_shown, m_rest;                    // what the pose shows, and the fills at rest
    std::vector<std::optional<QTransform>> m_back; // per layer: posed → rest, where rigid
    std::vector<QRectF> m_near;                    // the cut pieces' and sockets' bounds
    bool m_any = false;
};

} // namespace finbook::model::line_runs
