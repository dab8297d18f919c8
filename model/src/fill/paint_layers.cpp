// An object's layers as the renderers paint them (fill_render.h, paintLayers): one, or one
// per piece of a cut-out pose.
#include "line_runs.h"

#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_render.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

namespace finbook::model {

namespace {
// The rest fills of `still` (the object without its pose) as a piece moved by `motion` shows
// them: lit by the light turned back by the piece's turn, so once turned with the piece its
// tones face the light fixed on screen, as the posed body's do (moved as they were lit at
// rest, a limb turned 180° kept its light side away from the light, and its tones stopped hard
// against the body's at the cut). The fills as at rest when none is shaded.
std::vector<FillItem> restFillsLitFor(const StrokeGroup &still, const DocumentSettings &settings,
                                      const RenderOptions &options, const QTransform &motion,
                                      const std::vector<FillItem> &atRest)
{
    const bool shaded = std::any_of(atRest.begin(), atRest.end(),
                                    [](const FillItem &fill) { return !fill.tones.empty(); });
    // The motion's turn in canvas axes (x toward y, y down); the light's azimuth turns the
    // other way on screen (geometry::lightDirection), so lighting turned normals n' = R n by
    // L equals lighting n by R⁻¹ L = the light at azimuth + turn.
    const double turn = std::atan2(motion.m12(), motion.m11()) * 180.0 / std::numbers::pi;
    if (!shaded || !std::isfinite(turn) || std::abs(std::remainder(turn, 360.0)) < 1e-6)
        return atRest;
    DocumentSettings turned = settings;
    turned.lightAzimuth = std::fmod(settings.lightAzimuth + turn + 720.0, 360.0);
    std::vector<FillItem> lit = fillList(still, turned, options);
    return lit.size() == atRest.size() ? lit : atRest;
}

// A gap closer whose two ends the pose moved off a piece's motion (a closer from one toe's
// tip to the next toe's, the foot between them not turned) is shown where its ends went: the
// fills as posed end there, and Apply Pose keeps them so. The piece's fill moved with the
// piece ended where the closer was, a strip of fill past the closer shown (a flamingo's foot:
// 2 px). Per piece, the strips between each such closer as the piece's motion carries it and as
// the pose shows it: there the piece leaves the fill to the fills as posed beneath it. A closer
// with one end carried crosses a cut, where the fills as posed twist (the reason a piece paints
// its own): it stays as it was. Ends that moved less than this (canvas px) are carried.
constexpr double kCloserMoved = 0.25;
constexpr double kOnPiece = 1.5; // px: a closer's middle this near a piece's outline bounds it

QPainterPath closersMovedApart(const std::vector<QLineF> &atRest, const std::vector<QLineF> &shown,
                               const QTransform &motion, const QPainterPath &piece)
{
    QPainterPath strips;
    strips.setFillRule(Qt::WindingFill);
    const QRectF near = piece.boundingRect().adjusted(-kOnPiece, -kOnPiece, kOnPiece, kOnPiece);
    for (std::size_t i = 0; i < atRest.size() && i < shown.size(); ++i) {
        const QLineF carried = motion.map(atRest[i]);
        const QLineF &posed = shown[i];
        if (QLineF(carried.p1(), posed.p1()).length() <= kCloserMoved ||
            QLineF(carried.p2(), posed.p2()).length() <= kCloserMoved)
            continue;
        const QPointF middle = carried.center();
        if (!near.contains(middle) ||
            !piece.intersects(
                QRectF(middle - QPointF(kOnPiece, kOnPiece), middle + QPointF(kOnPiece, kOnPiece))))
            continue; // another piece's closer
        strips.addPolygon(
            QPolygonF{carried.p1(), carried.p2(), posed.p2(), posed.p1(), carried.p1()});
    }
    return strips;
}

// How far (canvas px) a cut-out piece's tones reach past its outline, over the fill beneath
// them. Cut where their fill is cut, a tone and its fill blend their anti-aliased edges twice
// on one pixel (the fill's edge, then the tone's over it), and a line of the fill's flat colour
// showed across the tone along every cut. A tone ends with its fill at the lines: only where a
// cut crosses it does it reach on, that pixel, under or over the next piece's same tone.
constexpr double kToneOverlap = 1.0;

// `outline` (a piece's boundary loops as the cut mesh gives them: its inside on one side of
// every loop, holes included) moved `by` px outward at each corner (mitred, capped at sharp
// ones): no path boolean, so every repaint can afford it.
QPainterPath grown(const QPainterPath &outline, double by)
{
    std::vector<std::vector<QPointF>> loops;
    for (int i = 0; i < outline.elementCount(); ++i) {
        const QPainterPath::Element e = outline.elementAt(i);
        if (e.isMoveTo() || loops.empty())
            loops.emplace_back();
        loops.back().emplace_back(e.x, e.y);
    }
    // Which side is inside: the largest loop is an outer one (the others wind the same way
    // round their pieces' inside, holes the other way round themselves).
    double largest = 0.0;
    for (std::vector<QPointF> &loop : loops) {
        if (loop.size() > 1 && loop.front() == loop.back())
            loop.pop_back();
        double area = 0.0;
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const QPointF &a = loop[i], &b = loop[(i + 1) % loop.size()];
            area += a.x() * b.y() - b.x() * a.y();
        }
        if (std::abs(area) > std::abs(largest))
            largest = area;
    }
    const double side = largest >= 0.0 ? 1.0 : -1.0; // outward = side × (dy, −dx)
    QPainterPath out;
    out.setFillRule(Qt::WindingFill);
    for (const std::vector<QPointF> &loop : loops) {
        const std::size_t n = loop.size();
        if (n < 3)
            continue;
        const auto normal = [&](std::size_t i) {
            const QPointF d = loop[(i + 1) % n] - loop[i];
            const double length = std::hypot(d.x(), d.y());
            return length > 0.0 ? QPointF(d.y(), -d.x()) * (side / length) : QPointF();
        };
        for (std::size_t i = 0; i < n; ++i) {
            const QPointF a = normal((i + n - 1) % n), b = normal(i);
            QPointF m = a + b;
            const double length = std::hypot(m.x(), m.y());
            m = length > 1e-9 ? m / length : (b.isNull() ? a : b);
            const double cosine = m.x() * b.x() + m.y() * b.y();
            const QPointF p = loop[i] + m * (by / std::max(cosine, 0.5));
            i == 0 ? out.moveTo(p) : out.lineTo(p);
        }
        out.closeSubpath();
    }
    return out;
}

// `fill`'s tones cut to `path`: what a socket or a seam's wedge painted in that fill shows.
std::vector<ToneItem> tonesWithin(const FillItem *fill, const QPainterPath &path)
{
    std::vector<ToneItem> out;
    if (!fill)
        return out;
    for (const ToneItem &tone : fill->tones) {
        ToneItem part{tone.path.intersected(path), tone.color};
        if (!part.path.isEmpty())
            out.push_back(std::move(part));
    }
    return out;
}
} // namespace

std::optional<CutOutSeam> cutOutSeam(const StrokeGroup &group, std::size_t stroke, std::size_t i)
{
    const DeformedStrokes *posed = group.deformed.get();
    if (!posed || stroke >= posed->pieceOf.size() || stroke >= posed->strokes.size() ||
        stroke >= group.strokes.size() || !group.strokes[stroke].data ||
        posed->pieceOf[stroke].size() != posed->strokes[stroke].size() ||
        group.strokes[stroke].data->points.size() != posed->strokes[stroke].size() ||
        i + 1 >= posed->strokes[stroke].size())
        return std::nullopt;
    const std::size_t pieces = posed->pieces.size();
    const std::vector<std::int16_t> &piece = posed->pieceOf[stroke];
    const int a = piece[i], b = piece[i + 1];
    const int deeper = std::max(a, b), other = std::min(a, b);
    if (a == b || deeper < 0 || std::size_t(deeper) >= pieces || other < -1 ||
        std::size_t(deeper) >= posed->socketAbove.size() ||
        std::size_t(deeper) >= posed->sockets.size() ||
        posed->socketAbove[std::size_t(deeper)] != other ||
        posed->sockets[std::size_t(deeper)].isEmpty() || posed->motions.size() != pieces + 1 ||
        !posed->motions[std::size_t(a + 1)] || !posed->motions[std::size_t(b + 1)])
        return std::nullopt;
    const QTransform &ma = *posed->motions[std::size_t(a + 1)];
    const QTransform &mb = *posed->motions[std::size_t(b + 1)];
    bool invertible = false;
    const QPointF joint = posed->sockets[std::size_t(deeper)].boundingRect().center();
    const QPointF restJoint = mb.inverted(&invertible).map(joint);
    if (!invertible)
        return std::nullopt;
    const StrokePoint &p = group.strokes[stroke].data->points[i];
    const StrokePoint &q = group.strokes[stroke].data->points[i + 1];
    const QPointF from(p.x, p.y), d(q.x - p.x, q.y - p.y);
    const double length2 = QPointF::dotProduct(d, d);
    const double t = length2 > 0.0
                         ? std::clamp(QPointF::dotProduct(restJoint - from, d) / length2, 0.0, 1.0)
                         : 0.0;
    const QPointF c = from + t * d;
    const float pressure = float(p.pressure + t * (q.pressure - p.pressure));
    const QPointF ca = ma.map(c), cb = mb.map(c);
    const double radius = QLineF(joint, ca).length();
    if (!(radius > 0.0) || !std::isfinite(radius))
        return std::nullopt;
    const double start = std::atan2(ca.y() - joint.y(), ca.x() - joint.x());
    const double sweep = std::remainder(std::atan2(cb.y() - joint.y(), cb.x() - joint.x()) - start,
                                        2.0 * std::numbers::pi);
    CutOutSeam seam;
    seam.cut = std::size_t(deeper);
    seam.joint = joint;
    const int steps = std::max(1, int(std::ceil(std::abs(sweep) / (std::numbers::pi / 16))));
    for (int k = 0; k <= steps; ++k) {
        const double angle = start + sweep * k / steps;
        seam.arc.push_back({float(joint.x() + radius * std::cos(angle)),
                            float(joint.y() + radius * std::sin(angle)), pressure});
    }
    seam.arc.front() = {float(ca.x()), float(ca.y()), pressure};
    seam.arc.back() = {float(cb.x()), float(cb.y()), pressure};
    return seam;
}

std::vector<PaintLayer> paintLayers(const StrokeGroup &group, const DocumentSettings &settings,
                                    const RenderOptions &options)
{
    std::vector<PaintLayer> layers(1);
    layers[0].fills = fillList(group, settings, options);
    layers[0].strokes = paintList(group, options);
    const DeformedStrokes *posed = group.deformed.get();
    if (!posed || posed->pieces.empty() || posed->pieceOf.size() != posed->strokes.size() ||
        posed->strokes.size() != group.strokes.size())
        return layers;
    const std::size_t pieces = posed->pieces.size();
    layers.resize(pieces + 1);
    // A piece that moved rigidly takes the rest fills moved with it, clipped to its outline:
    // whole, however far the pieces round it turned (the fills as posed follow the strokes,
    // and the lines across a cut stretch them into twists that leave holes). Any other cut
    // piece clips the fills as posed.
    const bool rigid =
        posed->motions.size() == pieces + 1 &&
        std::any_of(posed->motions.begin(), posed->motions.end(),
                    [](const std::optional<QTransform> &m) { return m.has_value(); });
    std::vector<FillItem> rest;
    StrokeGroup still;
    std::vector<QLineF> closersAtRest, closersShown;
    if (rigid) {
        still = group;
        still.deformed.reset();
        rest = fillList(still, settings, options);
        if (rest.size() != layers[0].fills.size())
            rest.clear();
        if (!rest.empty()) {
            const ObjectRegionsPtr regions = objectRegions(group, settings.closeGap);
            closersAtRest = regions->displayedClosures(still);
            closersShown = regions->displayedClosures(group);
        }
    }
    const std::vector<FillItem> shown = std::move(layers[0].fills);
    layers[0].fills.clear();
    // Per layer, its fills moved but not cut to its outline (a moved piece's) and which of them
    // each of its cut fills is: a socket painted in a limb's fill takes its tones from there.
    std::vector<std::vector<FillItem>> whole(pieces + 1);
    std::vector<std::vector<std::size_t>> wholeOf(pieces + 1);
    for (std::size_t layer = 0; layer <= pieces; ++layer) {
        const QPainterPath *outline = layer > 0               ? &posed->pieces[layer - 1]
                                      : posed->body.isEmpty() ? nullptr
                                                              : &posed->body;
        const std::optional<QTransform> motion =
            layer < posed->motions.size() ? posed->motions[layer] : std::nullopt;
        const bool moved = motion && outline && !rest.empty();
        // The body's layer starts with every fill as posed: under the pieces' own fills it
        // leaves no seam along the cuts (and the lines across a cut still close the outline).
        if (layer == 0) {
            layers[0].fills = shown;
            if (!moved)
                continue;
        }
        if (moved) {
            for (const FillItem &fill : restFillsLitFor(still, settings, options, *motion, rest)) {
                FillItem placed = fill; // all but where it lies
                placed.path = motion->map(fill.path);
                placed.path.setFillRule(Qt::WindingFill);
                for (ToneItem &tone : placed.tones)
                    tone.path = motion->map(tone.path);
                whole[layer].push_back(std::move(placed));
            }
        }
        const std::vector<FillItem> &source = moved ? whole[layer] : shown;
        const QPainterPath clip = outline ? *outline : QPainterPath();
        const bool shaded = std::any_of(source.begin(), source.end(),
                                        [](const FillItem &fill) { return !fill.tones.empty(); });
        const QPainterPath toneClip = outline && shaded ? grown(*outline, kToneOverlap) : clip;
        const QPainterPath strips =
            moved && outline ? closersMovedApart(closersAtRest, closersShown, *motion, *outline)
                             : QPainterPath();
        const auto place = [&](const QPainterPath &path, const QPainterPath &to) {
            QPainterPath placed = path;
            placed.setFillRule(Qt::WindingFill);
            if (!outline)
                return placed;
            placed = placed.intersected(to);
            return strips.isEmpty() ? placed : placed.subtracted(strips);
        };
        for (std::size_t i = 0; i < source.size(); ++i) {
            const FillItem &fill = source[i];
            FillItem clipped;
            clipped.path = place(fill.path, clip);
            if (clipped.path.isEmpty())
                continue;
            clipped.path.setFillRule(Qt::WindingFill);
            clipped.color = fill.color;
            clipped.fill = fill.fill;
            for (const ToneItem &tone : fill.tones) {
                ToneItem part = tone;
                part.path = place(tone.path, toneClip);
                if (!part.path.isEmpty())
                    clipped.tones.push_back(std::move(part));
            }
            layers[layer].fills.push_back(std::move(clipped));
            wholeOf[layer].push_back(i);
        }
    }
    // Sockets (round joints): painted on the piece above each cut (over its fills, under its
    // strokes) in the colour of the limb's fill that meets the socket, so a turned limb leaves
    // no gap at its joint.
    // A shaded limb's socket carries the limb's tones (its fill moved whole, or as posed), so
    // the round joint is shaded on as the limb is rather than a flat disc among the tones.
    std::vector<std::optional<QRgb>> socketColour(pieces);
    std::vector<const FillItem *> socketFill(pieces, nullptr);
    std::vector<int> socketIndex(pieces, -1); // the limb's fill (FillItem::fill)
    const auto layerAbove = [&](std::size_t k) {
        return std::size_t(std::clamp(posed->socketAbove[k] + 1, 0, int(pieces)));
    };
    // A joint that has not turned (the rest pose, a limb moved with its parent) opens no gap: its
    // socket is left out, as over shaded fills its edge would draw a seam through the tones.
    const auto turned = [&](std::size_t k) {
        const std::size_t above = layerAbove(k);
        if (posed->motions.size() != pieces + 1 || !posed->motions[k + 1] || !posed->motions[above])
            return true;
        return line_runs::movedApart(*posed->motions[k + 1], *posed->motions[above]);
    };
    for (std::size_t k = 0; k < pieces && k < posed->sockets.size(); ++k) {
        const QPainterPath &socket = posed->sockets[k];
        if (socket.isEmpty() || k >= posed->socketAbove.size() || !turned(k))
            continue;
        const std::vector<FillItem> &limb = layers[k + 1].fills;
        const auto colour = std::find_if(limb.rbegin(), limb.rend(), [&](const FillItem &fill) {
            return fill.path.intersects(socket);
        });
        if (colour == limb.rend())
            continue;
        socketColour[k] = colour->color;
        socketIndex[k] = colour->fill;
        const std::size_t at = std::size_t(limb.rend() - colour) - 1;
        if (!colour->tones.empty() && at < wholeOf[k + 1].size()) {
            const std::size_t i = wholeOf[k + 1][at];
            const std::vector<FillItem> &from = whole[k + 1].empty() ? shown : whole[k + 1];
            socketFill[k] = i < from.size() ? &from[i] : nullptr;
        }
        FillItem fill;
        fill.path = socket;
        fill.color = colour->color;
        fill.tones = tonesWithin(socketFill[k], socket);
        fill.fill = colour->fill;
        layers[layerAbove(k)].fills.push_back(std::move(fill));
    }
    // The strokes: each item (a displayed stroke, folded repeats included) split into runs of
    // segments that moved with one piece, joined across the cuts as above.
    const std::vector<PaintItem> items = std::move(layers[0].strokes);
    layers[0].strokes.clear();
    const auto *first = posed->strokes.data();
    struct Entry {
        std::size_t layer;
        PaintItem item;
        std::ptrdiff_t run; // into layers[layer].runs, or −1: the item as it is
        bool seam = false;  // the run is a seam's arc
    };
    std::vector<Entry> entries; // in painting order
    for (const PaintItem &item : items) {
        const std::ptrdiff_t s = item.points - first;
        if (s < 0 || std::size_t(s) >= posed->strokes.size() ||
            posed->pieceOf[std::size_t(s)].size() != item.points->size()) {
            entries.push_back({0, item, -1});
            continue;
        }
        const std::vector<StrokePoint> &points = *item.points;
        const std::vector<std::int16_t> &piece = posed->pieceOf[std::size_t(s)];
        const auto layerOfPiece = [&](int p) {
            return std::size_t(std::clamp(p + 1, 0, int(pieces)));
        };
        if (points.size() <= 1 || std::all_of(piece.begin(), piece.end(),
                                              [&](std::int16_t p) { return p == piece[0]; })) {
            entries.push_back({layerOfPiece(piece[0]), item, -1});
            continue;
        }
        std::size_t layer = layerOfPiece(piece[0]);
        std::vector<StrokePoint> run;
        const auto flush = [&](std::size_t into, std::vector<StrokePoint> &&part,
                               bool seam = false) {
            if (part.size() < 2)
                return;
            entries.push_back({into, item, std::ptrdiff_t(layers[into].runs.size()), seam});
            layers[into].runs.push_back(std::move(part));
        };
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            const int a = piece[i], b = piece[i + 1];
            std::optional<CutOutSeam> seam;
            if (a != b)
                seam = cutOutSeam(group, std::size_t(s), i);
            const std::size_t segment = a == b ? layerOfPiece(a)
                                        : seam ? layerOfPiece(a)
                                               : layerOfPiece(std::max(a, b));
            if (run.empty() || layer != segment) {
                flush(layer, std::exchange(run, {}));
                layer = segment;
                run.push_back(points[i]);
            }
            if (!seam) {
                run.push_back(points[i + 1]);
                continue;
            }
            // The arc and the wedge under it go on the piece above the cut.
            const std::size_t above = layerAbove(seam->cut);
            if (const std::optional<QRgb> colour = socketColour[seam->cut]) {
                FillItem wedge;
                wedge.path.moveTo(seam->joint);
                for (const StrokePoint &point : seam->arc)
                    wedge.path.lineTo(point.x, point.y);
                wedge.path.closeSubpath();
                wedge.path.setFillRule(Qt::WindingFill);
                wedge.color = *colour;
                wedge.tones = tonesWithin(socketFill[seam->cut], wedge.path);
                wedge.fill = socketIndex[seam->cut];
                layers[above].fills.push_back(std::move(wedge));
            }
            run.push_back(seam->arc.front());
            flush(layer, std::exchange(run, {}));
            run = {seam->arc.back(), points[i + 1]};
            flush(above, std::move(seam->arc), true);
            layer = layerOfPiece(b);
        }
        flush(layer, std::move(run));
    }
    // The parts of lines that the pose laid inside one fill are left out (line_runs.h,
    // MergedLines), as Apply Pose leaves them out.
    if (rigid && !rest.empty()) {
        const line_runs::MergedLines merged(group, layers, rest);
        std::vector<Entry> kept;
        kept.reserve(entries.size());
        for (Entry &entry : entries) {
            const std::vector<StrokePoint> &points =
                entry.run >= 0 ? layers[entry.layer].runs[std::size_t(entry.run)]
                               : *entry.item.points;
            if (!merged.any() || points.size() < 2) {
                kept.push_back(entry);
                continue;
            }
            std::vector<line_runs::Segment> segments;
            for (std::size_t k = 0; k + 1 < points.size(); ++k)
                segments.push_back({points[k], points[k + 1], entry.layer, entry.seam});
            const double width = entry.item.width;
            const std::vector<line_runs::Run> runs = line_runs::runsOf(line_runs::cutWhere(
                line_runs::piecesOf(segments),
                [&](const line_runs::Segment &s, QPointF p) {
                    return merged.hides(s.layer, p, width, s.seam);
                },
                line_runs::Hidden::Merged));
            if (runs.size() == 1 && runs.front().shows()) {
                kept.push_back(entry);
                continue;
            }
            for (const line_runs::Run &run : runs) {
                if (!run.shows())
                    continue;
                kept.push_back({entry.layer, entry.item,
                                std::ptrdiff_t(layers[entry.layer].runs.size()), entry.seam});
                layers[entry.layer].runs.push_back(run.points);
            }
        }
        entries = std::move(kept);
    }
    // Every run is stored before an item points at one (the runs do not move after).
    for (Entry &entry : entries) {
        PaintLayer &layer = layers[entry.layer];
        if (entry.run >= 0)
            entry.item.points = &layer.runs[std::size_t(entry.run)];
        layer.strokes.push_back(entry.item);
    }
    return layers;
}

} // namespace finbook::model
