// Apply Pose of a cut-out pose (fill_render.h, bakedStrokes): the posed lines with the parts a
// piece drawn over them hides cut away, so the baked drawing, whose fills all lie under all its
// strokes, shows what the layered pose showed.
#include "../skeleton/nearest_bone.h"
#include "line_runs.h"

#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>

namespace finbook::model {

namespace {

using line_runs::kShortestHiddenRun;
using line_runs::MergedLines;
using line_runs::Run;
using line_runs::Segment;

// The fills each layer draws over the layers below it, with their bounds for a quick reject.
class Covers {
public:
    explicit Covers(const std::vector<PaintLayer> &layers)
    {
        for (const PaintLayer &layer : layers) {
            std::vector<Cover> covers;
            for (const FillItem &fill : layer.fills)
                covers.push_back({&fill.path, fill.path.boundingRect()});
            m_layers.push_back(std::move(covers));
        }
    }

    // Whether a point of a line drawn on `layer` is under a fill of a layer above it.
    bool hides(std::size_t layer, QPointF p) const
    {
        for (std::size_t above = layer + 1; above < m_layers.size(); ++above)
            for (const Cover &cover : m_layers[above])
                if (cover.bounds.contains(p) && cover.path->contains(p))
                    return true;
        return false;
    }

private:
    struct Cover {
        const QPainterPath *path;
        QRectF bounds;
    };
    std::vector<std::vector<Cover>> m_layers;
};

// Stroke `i`'s posed line as paintLayers paints it: per segment, the layer it is drawn on
// (the piece both ends moved with; across a cut, the arc round the joint on the piece above
// and each end's part on its own piece, or without an arc the deeper piece).
std::vector<Segment> layeredSegments(const StrokeGroup &group, std::size_t i,
                                     const std::vector<StrokePoint> &points)
{
    const DeformedStrokes &posed = *group.deformed;
    const std::vector<std::int16_t> &piece = posed.pieceOf[i];
    const int pieces = int(posed.pieces.size());
    const auto layerOf = [&](int p) { return std::size_t(std::clamp(p + 1, 0, pieces)); };
    std::vector<Segment> segments;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
        const int a = piece[k], b = piece[k + 1];
        if (a == b) {
            segments.push_back({points[k], points[k + 1], layerOf(a)});
            continue;
        }
        const std::optional<CutOutSeam> seam = cutOutSeam(group, i, k);
        if (!seam || seam->arc.empty() || seam->cut >= posed.socketAbove.size()) {
            segments.push_back({points[k], points[k + 1], layerOf(std::max(a, b))});
            continue;
        }
        const std::size_t above = layerOf(posed.socketAbove[seam->cut]);
        segments.push_back({points[k], seam->arc.front(), layerOf(a)});
        for (std::size_t j = 0; j + 1 < seam->arc.size(); ++j)
            segments.push_back({seam->arc[j], seam->arc[j + 1], above, true});
        segments.push_back({seam->arc.back(), points[k + 1], layerOf(b)});
    }
    return segments;
}

} // namespace

std::vector<Stroke> bakedStrokes(const StrokeGroup &group, const std::vector<PaintLayer> &layers,
                                 const DocumentSettings &settings, const std::function<Id()> &newId,
                                 HiddenLines hidden)
{
    const DeformedStrokes *d = group.deformed.get();
    if (!group.isDeformed() || !d || d->pieces.empty() ||
        d->pieceOf.size() != group.strokes.size() || d->strokes.size() != group.strokes.size())
        return posedStrokes(group);
    const Covers covers(layers);
    // The rest fills, for MergedLines: only a piece that moved rigidly can lay a line inside
    // one (as paintLayers, which makes them only then).
    std::vector<FillItem> rest;
    if (std::any_of(d->motions.begin(), d->motions.end(),
                    [](const std::optional<QTransform> &m) { return m.has_value(); })) {
        StrokeGroup still = group;
        still.deformed.reset();
        rest = fillList(still, settings.closeGap);
    }
    const MergedLines merged(group, layers, rest);
    std::vector<Stroke> out;
    out.reserve(group.strokes.size());
    for (std::size_t i = 0; i < group.strokes.size(); ++i) {
        const Stroke &stroke = group.strokes[i];
        if (!stroke.data) {
            out.push_back(stroke);
            continue;
        }
        const std::vector<StrokePoint> &points = displayedPoints(group, i);
        auto data = std::make_shared<StrokeData>(*stroke.data);
        if (d->pieceOf[i].size() != points.size() || points.size() < 2) {
            data->points = points; // no cut to go round or hide at (as posedStrokes)
            out.push_back({stroke.id, std::move(data)});
            continue;
        }
        // The runs join the layered segments, arcs included: one run that shows whole is
        // the line posedStrokes makes. A hidden run kept is a hidden line (kHiddenLineColor:
        // no renderer draws it, no region ends on it), so that the line stays whole and still
        // closes its loop by itself (rest_shade.h inflates the body as the whole body).
        // Hidden: under a piece above, or laid inside one fill (MergedLines), as paintLayers
        // leaves it out.
        const double width = stroke.data->width;
        const auto laidInside = [&](const Segment &s, QPointF p) {
            return merged.hides(s.layer, p, width, s.seam);
        };
        const auto covered = [&](const Segment &s, QPointF p) { return covers.hides(s.layer, p); };
        std::vector<Run> runs = line_runs::withoutSlivers(
            line_runs::runsOf(line_runs::cutWhere(
                line_runs::cutWhere(line_runs::piecesOf(layeredSegments(group, i, points)),
                                    laidInside, line_runs::Hidden::Merged),
                covered, line_runs::Hidden::Covered)),
            std::min(kShortestHiddenRun, 0.5 * width));
        std::erase_if(runs, [hidden](const Run &run) {
            return !run.shows() &&
                   (hidden == HiddenLines::Drop ||
                    std::all_of(run.points.begin(), run.points.end(), [&](const StrokePoint &p) {
                        return p.x == run.points.front().x && p.y == run.points.front().y;
                    }));
        });
        // The stroke's id stays with its first part that shows.
        const auto keeper =
            std::find_if(runs.begin(), runs.end(), [](const Run &run) { return run.shows(); });
        const std::size_t keep = keeper == runs.end() ? 0 : std::size_t(keeper - runs.begin());
        for (std::size_t r = 0; r < runs.size(); ++r) {
            auto part = std::make_shared<StrokeData>(*data);
            part->points = std::move(runs[r].points);
            if (!runs[r].shows())
                part->color = kHiddenLineColor;
            out.push_back({r == keep ? stroke.id : newId(), std::move(part)});
        }
    }
    return out;
}

std::vector<Stroke> bakedStrokes(const StrokeGroup &group, double closeGap,
                                 const std::function<Id()> &newId, HiddenLines hidden)
{
    if (!group.isDeformed() || group.deformed->pieces.empty())
        return posedStrokes(group);
    DocumentSettings settings;
    settings.closeGap = closeGap;
    return bakedStrokes(group, paintLayers(group, settings), settings, newId, hidden);
}

namespace {
// Outline points closer than this (canvas px) to an inked baked line need no closer.
constexpr double kLineReach = 1.5;
// Outline stretches shorter than this (canvas px) are left open: the Close gaps distance
// closes such slits anyway.
constexpr double kShortestCloser = 3.0;
// Outlines are walked in steps of at most this many px.
constexpr double kOutlineStep = 1.0;
// The colours either side of an outline are looked at this far (canvas px) from it, and as
// many times as far, until a point in the piece and one out of it are found.
constexpr double kSideStep = 1.0;
constexpr int kSideSteps = 4;
// A closer ending on a line runs this far (px) past its middle, as gap closing's links do.
constexpr double kHairPast = 0.01;
// The most outline (px, all pieces) that is walked for closers.
constexpr double kLongestOutlines = 2.0e6;
// Past a line's end, outline points this much further than its half width (px) are not on it.
constexpr double kAtEndReach = 0.5;

QPointF nearestOnSegment(QPointF p, const QLineF &segment)
{
    return segment.pointAt(join_detail::project(p, segment.p1(), segment.p2()).first);
}

double distanceToSegment(QPointF p, const QLineF &segment)
{
    return QLineF(p, nearestOnSegment(p, segment)).length();
}

// The inked baked lines' segments, found near a point through a uniform grid (an outline is
// walked px by px, and a drawing has thousands of segments).
class InkIndex {
public:
    struct Hit {
        bool found = false;
        double distance = 0.0;
        QPointF point;          // nearest point on the line's middle
        double halfWidth = 0.0; // of that line
        bool atEnd = false;     // the point is one of the line's two ends
    };

    // Finds lines within `radius` of a point (and no further).
    InkIndex(const std::vector<Stroke> &baked, double radius)
        : m_cell(std::max(radius, 4.0))
    {
        for (const Stroke &s : baked) {
            if (!s.data || qAlpha(s.data->color) == 0 || s.data->points.empty())
                continue;
            const auto &pts = s.data->points;
            const double half =
                0.5 * (std::isfinite(s.data->width) ? std::min(double(s.data->width), 64.0) : 1.0);
            const std::size_t count = pts.size() > 1 ? pts.size() - 1 : 1;
            for (std::size_t k = 0; k < count; ++k) {
                const StrokePoint &a = pts[k], &b = pts[std::min(k + 1, pts.size() - 1)];
                if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) ||
                    !std::isfinite(b.y))
                    continue;
                const QLineF line(QPointF(a.x, a.y), QPointF(b.x, b.y));
                const int index = int(m_segments.size());
                m_segments.push_back({line, half, k == 0, k + 1 == count});
                // The cells within `radius` of the segment, walked along it (a long diagonal
                // line's bounding box would hold millions of cells): points every half cell,
                // each with the cells within radius plus a quarter cell of it.
                const int steps = int(std::ceil(line.length() / (0.5 * m_cell)));
                const double reach = radius + 0.25 * m_cell;
                for (int i = 0; i <= steps; ++i) {
                    const QPointF at = line.pointAt(steps > 0 ? double(i) / steps : 0.0);
                    for (long long y = cellOf(at.y() - reach); y <= cellOf(at.y() + reach); ++y)
                        for (long long x = cellOf(at.x() - reach); x <= cellOf(at.x() + reach);
                             ++x) {
                            std::vector<int> &cell = m_cells[key(x, y)];
                            if (cell.empty() || cell.back() != index)
                                cell.push_back(index);
                        }
                }
            }
        }
    }

    Hit nearest(QPointF p, double within) const
    {
        Hit hit;
        const auto cell = m_cells.find(key(cellOf(p.x()), cellOf(p.y())));
        if (cell == m_cells.end())
            return hit;
        double best = within;
        for (const int index : cell->second) {
            const Segment &s = m_segments[std::size_t(index)];
            const auto [t, distance] = join_detail::project(p, s.line.p1(), s.line.p2());
            if (distance <= best) {
                best = distance;
                hit = {true, distance, s.line.pointAt(t), s.halfWidth,
                       (t <= 0.0 && s.startIsEnd) || (t >= 1.0 && s.endIsEnd) ||
                           s.line.p1() == s.line.p2()};
            }
        }
        return hit;
    }

private:
    struct Segment {
        QLineF line;
        double halfWidth;
        bool startIsEnd, endIsEnd;
    };
    long long cellOf(double v) const { return (long long)std::floor(v / m_cell); }
    static long long key(long long x, long long y) { return x * 1000003LL + y; }

    double m_cell;
    std::vector<Segment> m_segments;
    std::unordered_map<long long, std::vector<int>> m_cells;
};

std::vector<QPointF> densified(const QPolygonF &polygon)
{
    std::vector<QPointF> out;
    for (qsizetype i = 0; i + 1 < polygon.size(); ++i) {
        const QPointF a = polygon[i], b = polygon[i + 1];
        const double length = QLineF(a, b).length();
        const int steps = std::max(1, int(std::ceil(length / kOutlineStep)));
        for (int k = 0; k < steps; ++k)
            out.push_back(a + (b - a) * (double(k) / steps));
    }
    return out;
}
} // namespace

int shownFillAt(const std::vector<PaintLayer> &layers, QPointF p)
{
    for (auto layer = layers.rbegin(); layer != layers.rend(); ++layer)
        for (auto item = layer->fills.rbegin(); item != layer->fills.rend(); ++item)
            if (item->fill >= 0 && item->path.controlPointRect().contains(p) &&
                item->path.contains(p))
                return item->fill;
    return -1;
}

std::vector<Stroke> cutOutClosers(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                  double closeGap, const std::function<Id()> &newId)
{
    if (group.fills.empty() || !group.isDeformed() || group.deformed->pieces.empty())
        return {};
    DocumentSettings settings;
    settings.closeGap = closeGap;
    const std::vector<PaintLayer> layers = paintLayers(group, settings);
    // The pieces' painted outlines (the roots' piece too: a fill that moved with it may show
    // past its lines), with the layer each is painted on.
    std::vector<std::pair<QPolygonF, std::size_t>> outlines;
    std::vector<QPainterPath> painted(layers.size());
    double perimeter = 0.0;
    for (std::size_t l = 0; l < layers.size(); ++l) {
        painted[l].setFillRule(Qt::WindingFill);
        for (const FillItem &fill : layers[l].fills)
            painted[l].addPath(fill.path);
        if (painted[l].isEmpty())
            continue;
        painted[l] = painted[l].simplified();
        for (const QPolygonF &polygon : painted[l].toSubpathPolygons()) {
            outlines.emplace_back(polygon, l);
            for (qsizetype k = 0; k + 1 < polygon.size(); ++k)
                perimeter += QLineF(polygon[k], polygon[k + 1]).length();
        }
    }
    // The outlines are walked px by px: beyond this many (a drawing many thousand px across
    // with hundreds of pieces) the cost would be seconds, and the pose is baked without them.
    if (outlines.empty() || !(perimeter <= kLongestOutlines))
        return {};
    double widest = 1.0;
    for (const Stroke &s : baked)
        if (s.data && qAlpha(s.data->color) != 0 && !s.data->points.empty() &&
            std::isfinite(s.data->width))
            widest = std::max(widest, std::min(double(s.data->width), 64.0));
    // A closer ends on the middle of the inked line it meets (a hair past it), so that the
    // regions join them: they follow the lines' middles, and an end left short of one, or
    // run on beyond it, would be a loose end for gap closing to link elsewhere.
    const double reach = 0.5 * widest + kLineReach + 2.0 * kOutlineStep;
    const InkIndex ink(baked, reach);
    // Whether an inked line runs at p. Past a line's end only its round cap counts: between
    // the ends of two lines (a line a piece above cut in two, dashes along a neck) the baked
    // drawing has a gap, and the colour's edge there needs a closer.
    const auto inked = [&](QPointF p) {
        const InkIndex::Hit hit = ink.nearest(p, reach);
        return hit.found && hit.distance <= hit.halfWidth + kLineReach &&
               (!hit.atEnd || hit.distance <= hit.halfWidth + kAtEndReach);
    };
    const Covers covers(layers);
    // Whether the fill shown changes across the outline at `at` (`before` and `after` its
    // neighbours on it): a piece's edge over a region of its own fill (an arm cut from a body
    // of one colour) ends no colour, and a line there would only split that region.
    const auto colourChanges = [&](const QPainterPath &piece, QPointF before, QPointF at,
                                   QPointF after) {
        const QPointF along = after - before;
        const double length = std::hypot(along.x(), along.y());
        if (!(length > 0.0))
            return true;
        // The nearest points either side that are in the piece and out of it: a jagged edge
        // (a cut's sawtooth) can put both points of one distance on one side.
        const QPointF normal(-along.y() / length, along.x() / length);
        std::optional<QPointF> inside, outside;
        for (int step = 1; step <= kSideSteps && !(inside && outside); ++step)
            for (const double side : {1.0, -1.0}) {
                const QPointF q = at + normal * (side * step * kSideStep);
                (piece.contains(q) ? inside : outside).emplace(q);
            }
        return !inside || !outside || shownFillAt(layers, *inside) != shownFillAt(layers, *outside);
    };
    std::vector<std::pair<QLineF, std::size_t>> closerSegments; // with the closer's index
    const auto ontoInk = [&](QPointF p, std::size_t self) -> std::optional<QPointF> {
        const InkIndex::Hit hit = ink.nearest(p, reach);
        double best = hit.found ? hit.distance : reach;
        std::optional<QPointF> out;
        if (hit.found)
            out = hit.point;
        for (const auto &[seg, closer] : closerSegments) {
            if (closer == self)
                continue;
            const QPointF q = nearestOnSegment(p, seg);
            const double distance = QLineF(p, q).length();
            if (distance < best) {
                best = distance;
                out = q;
            }
        }
        if (out && best > 0.0)
            *out += (*out - p) * (kHairPast / best);
        return out;
    };
    const double penWidth = medianInkWidth(baked);
    std::vector<Stroke> out;
    const auto nearCloser = [&](QPointF p) {
        return std::any_of(closerSegments.begin(), closerSegments.end(), [&](const auto &seg) {
            return distanceToSegment(p, seg.first) <= kLineReach;
        });
    };
    // Per closer, whether its first and last point still end short of any line: next to a
    // hidden edge, its line is the piece above's closer, made later perhaps.
    std::vector<std::pair<bool, bool>> loose;
    const auto addCloser = [&](const std::vector<QPointF> &run, bool looseFront, bool looseBack) {
        double length = 0.0;
        for (std::size_t k = 1; k < run.size(); ++k)
            length += QLineF(run[k - 1], run[k]).length();
        if (run.size() < 2 || length < kShortestCloser)
            return;
        // A short stretch whose two ends met the same point of a line (a corner's tip) is a
        // spike in and out again: it ends no region.
        if (QLineF(run.front(), run.back()).length() < kLineReach && length < 4.0 * kShortestCloser)
            return;
        for (std::size_t k = 1; k < run.size(); ++k)
            closerSegments.emplace_back(QLineF(run[k - 1], run[k]), out.size());
        loose.emplace_back(looseFront, looseBack);
        out.push_back({newId(), lineOfNoInk(run, penWidth)});
    };
    for (const auto &[outline, layer] : outlines) {
        const std::vector<QPointF> points = densified(outline);
        const std::size_t n = points.size();
        if (n < 3)
            continue;
        // 'o': the colour ends here and nothing draws the edge (a closer goes here); 'i': an
        // inked line runs here; 'h': a piece above hides the edge (the pose shows none); 's':
        // the same fill shows on both sides (no colour ends here); 'c': a closer made for an
        // outline before runs here (two pieces' outlines along one cut).
        std::vector<char> state(n);
        for (std::size_t k = 0; k < n; ++k)
            state[k] = covers.hides(layer, points[k]) ? 'h'
                       : inked(points[k])             ? 'i'
                       : nearCloser(points[k])        ? 'c'
                       : colourChanges(painted[layer], points[(k + n - 1) % n], points[k],
                                       points[(k + 1) % n])
                           ? 'o'
                           : 's';
        const auto first =
            std::find_if(state.begin(), state.end(), [](char c) { return c != 'o'; });
        if (first == state.end()) { // an edge drawn nowhere: closed whole
            std::vector<QPointF> ring = points;
            ring.push_back(points.front());
            addCloser(ring, false, false);
            continue;
        }
        // Walk from a point that needs no closer, so that a stretch across the polygon's first
        // point stays one line.
        const std::size_t start = std::size_t(first - state.begin());
        for (std::size_t k = 0; k < n;) {
            const std::size_t at = (start + k) % n;
            if (state[at] != 'o') {
                ++k;
                continue;
            }
            // The stretch k .. end-1 (walk order). It ends where it reaches a closer made
            // before or comes back along itself: an outline may run out along a cut and back
            // (two pieces' fills meeting there), and the cut needs one closer.
            std::vector<QPointF> run;
            std::size_t end = k;
            for (; end < n && state[(start + end) % n] == 'o'; ++end) {
                const QPointF p = points[(start + end) % n];
                const bool alongItself =
                    run.size() > 3 && std::any_of(run.begin(), run.end() - 3, [&](QPointF q) {
                        return QLineF(p, q).length() <= kLineReach;
                    });
                if (alongItself || nearCloser(p)) {
                    state[(start + end) % n] = 'c';
                    break;
                }
                run.push_back(p);
            }
            if (run.empty()) {
                ++k;
                continue;
            }
            // Where an inked line (or an earlier closer) meets it, the closer ends on that
            // line's middle (not along the line: beside it, it would make slivers), never in a
            // hidden edge.
            const auto meets = [](char c) { return c == 'i' || c == 'c'; };
            bool looseFront = true, looseBack = true;
            if (k > 0 && meets(state[(start + k - 1) % n]))
                if (const auto onto = ontoInk(run.front(), out.size())) {
                    run.insert(run.begin(), *onto);
                    looseFront = false;
                }
            if (meets(state[(start + end) % n]))
                if (const auto onto = ontoInk(run.back(), out.size())) {
                    run.push_back(*onto);
                    looseBack = false;
                }
            addCloser(run, looseFront, looseBack);
            k = end;
        }
    }
    // Ends left loose (where a piece above hid the edge, or an outline was walked before the
    // one whose closer it meets) go on to the nearest line or other closer, all made now.
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (!loose[i].first && !loose[i].second)
            continue;
        auto data = std::make_shared<StrokeData>(*out[i].data);
        auto &points = data->points;
        const auto endOn = [&](const StrokePoint &end) {
            return ontoInk(QPointF(end.x, end.y), i);
        };
        if (loose[i].first)
            if (const auto onto = endOn(points.front()))
                points.insert(points.begin(),
                              StrokePoint{float(onto->x()), float(onto->y()), 1.0f});
        if (loose[i].second)
            if (const auto onto = endOn(points.back()))
                points.push_back({float(onto->x()), float(onto->y()), 1.0f});
        out[i].data = std::move(data);
    }
    return out;
}

} // namespace finbook::model
