// Apply Pose of a cut-out pose (fill_render.h, bakedStrokes): the posed lines with the parts a
// piece drawn over them hides cut away, so the baked drawing, whose fills all lie under all its
// strokes, shows what the layered pose showed.
#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>

#include <QImage>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace finbook::model {

namespace {

// Bisection steps for where a segment enters or leaves a cover: 2⁻¹⁴ of a segment a few px
// long is far below what a pen shows.
constexpr int kCrossingSteps = 14;

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

struct Segment {
    StrokePoint a, b;
    std::size_t layer;
};

StrokePoint lerp(const StrokePoint &a, const StrokePoint &b, double t)
{
    const auto mix = [t](float u, float v) { return float(u + (v - u) * t); };
    return {mix(a.x, b.x), mix(a.y, b.y), mix(a.pressure, b.pressure)};
}

QPointF at(const StrokePoint &p)
{
    return {p.x, p.y};
}

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
            segments.push_back({seam->arc[j], seam->arc[j + 1], above});
        segments.push_back({seam->arc.back(), points[k + 1], layerOf(b)});
    }
    return segments;
}

// The parts of `segments` no cover hides, each a polyline of two points or more.
std::vector<std::vector<StrokePoint>> visibleRuns(const std::vector<Segment> &segments,
                                                  const Covers &covers)
{
    // Consecutive segments share their ends, so a run takes each segment's start only when it
    // begins there (points repeated in the stroke stay as drawn).
    std::vector<std::vector<StrokePoint>> runs;
    std::vector<StrokePoint> run;
    const auto end = [&] {
        if (run.size() >= 2)
            runs.push_back(std::move(run));
        run.clear();
    };
    const auto add = [&run](const StrokePoint &p) { run.push_back(p); };
    for (const Segment &s : segments) {
        const bool aShows = !covers.hides(s.layer, at(s.a));
        const bool bShows = !covers.hides(s.layer, at(s.b));
        if (aShows && bShows) {
            if (run.empty())
                add(s.a);
            add(s.b);
            continue;
        }
        if (!aShows && !bShows) {
            end();
            continue;
        }
        // One end shows: the cover's edge lies between them.
        double shown = aShows ? 0.0 : 1.0, hidden = 1.0 - shown;
        for (int step = 0; step < kCrossingSteps; ++step) {
            const double mid = 0.5 * (shown + hidden);
            (covers.hides(s.layer, at(lerp(s.a, s.b, mid))) ? hidden : shown) = mid;
        }
        const StrokePoint edge = lerp(s.a, s.b, shown);
        if (aShows) {
            if (run.empty())
                add(s.a);
            add(edge);
            end();
        } else {
            end();
            add(edge);
            add(s.b);
        }
    }
    end();
    return runs;
}

} // namespace

std::vector<Stroke> bakedStrokes(const StrokeGroup &group, const std::vector<PaintLayer> &layers,
                                 const std::function<Id()> &newId)
{
    const DeformedStrokes *d = group.deformed.get();
    if (!group.isDeformed() || !d || d->pieces.empty() ||
        d->pieceOf.size() != group.strokes.size() || d->strokes.size() != group.strokes.size())
        return posedStrokes(group);
    const Covers covers(layers);
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
        // the line posedStrokes makes.
        std::vector<std::vector<StrokePoint>> runs =
            visibleRuns(layeredSegments(group, i, points), covers);
        for (std::size_t r = 0; r < runs.size(); ++r) {
            auto part = r + 1 < runs.size() ? std::make_shared<StrokeData>(*stroke.data) : data;
            part->points = std::move(runs[r]);
            out.push_back({r == 0 ? stroke.id : newId(), std::move(part)});
        }
    }
    return out;
}

std::vector<Stroke> bakedStrokes(const StrokeGroup &group, double closeGap,
                                 const std::function<Id()> &newId)
{
    if (!group.isDeformed() || group.deformed->pieces.empty())
        return posedStrokes(group);
    DocumentSettings settings;
    settings.closeGap = closeGap;
    return bakedStrokes(group, paintLayers(group, settings), newId);
}

namespace {
// Outline points closer than this (canvas px) to an inked baked line need no closer.
constexpr double kLineReach = 1.5;
// Outline stretches shorter than this (canvas px) are left open: the Close gaps distance
// closes such slits anyway.
constexpr double kShortestCloser = 3.0;
// Outlines are walked in steps of at most this many px.
constexpr double kOutlineStep = 1.0;

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
    QRectF bounds;
    for (std::size_t l = 0; l < layers.size(); ++l) {
        QPainterPath painted;
        painted.setFillRule(Qt::WindingFill);
        for (const FillItem &fill : layers[l].fills)
            painted.addPath(fill.path);
        if (painted.isEmpty())
            continue;
        for (const QPolygonF &polygon : painted.simplified().toSubpathPolygons()) {
            outlines.emplace_back(polygon, l);
            bounds |= polygon.boundingRect();
        }
    }
    if (outlines.empty() || !bounds.isValid() || bounds.width() * bounds.height() > 64e6)
        return {};
    // Where the inked baked lines run, drawn into a mask over the outlines' bounds.
    bounds.adjust(-4, -4, 4, 4);
    QImage mask(bounds.size().toSize() + QSize(1, 1), QImage::Format_Alpha8);
    if (mask.isNull())
        return {};
    mask.fill(0);
    double widest = 1.0;
    {
        QPainter painter(&mask);
        painter.translate(-bounds.topLeft());
        for (const Stroke &s : baked) {
            if (!s.data || qAlpha(s.data->color) == 0 || s.data->points.empty())
                continue;
            const double width = std::isfinite(s.data->width) ? double(s.data->width) : 1.0;
            widest = std::max(widest, std::min(width, 64.0));
            painter.setPen(QPen(Qt::black, width + 2.0 * kLineReach, Qt::SolidLine, Qt::RoundCap,
                                Qt::RoundJoin));
            QPolygonF line;
            for (const StrokePoint &p : s.data->points)
                line << QPointF(p.x, p.y);
            line.size() == 1 ? painter.drawPoint(line.front()) : painter.drawPolyline(line);
        }
    }
    const auto inked = [&](QPointF p) {
        const QPoint at = (p - bounds.topLeft()).toPoint();
        return mask.rect().contains(at) && qAlpha(mask.pixel(at)) > 0;
    };
    const Covers covers(layers);
    // A closer runs on into the line it meets, past its middle, so that the regions join them
    // (they follow the lines' middles).
    const int reach = int(std::ceil((0.5 * widest + kLineReach + 1.0) / kOutlineStep));
    std::vector<Stroke> out;
    const auto addCloser = [&](const std::vector<QPointF> &run) {
        double length = 0.0;
        for (std::size_t k = 1; k < run.size(); ++k)
            length += QLineF(run[k - 1], run[k]).length();
        if (run.size() < 2 || length < kShortestCloser)
            return;
        auto data = std::make_shared<StrokeData>();
        data->color = kGapCloserColor;
        data->width = 1.0f;
        for (const QPointF &p : run)
            data->points.push_back({float(p.x()), float(p.y()), 1.0f});
        out.push_back({newId(), std::move(data)});
    };
    for (const auto &[outline, layer] : outlines) {
        const std::vector<QPointF> points = densified(outline);
        const std::size_t n = points.size();
        if (n < 3)
            continue;
        // 'o': the colour ends here and nothing draws the edge (a closer goes here); 'i': an
        // inked line runs here; 'h': a piece above hides the edge (the pose shows none).
        std::vector<char> state(n);
        for (std::size_t k = 0; k < n; ++k)
            state[k] = covers.hides(layer, points[k]) ? 'h' : inked(points[k]) ? 'i' : 'o';
        const auto first =
            std::find_if(state.begin(), state.end(), [](char c) { return c != 'o'; });
        if (first == state.end()) { // an edge drawn nowhere: closed whole
            std::vector<QPointF> ring = points;
            ring.push_back(points.front());
            addCloser(ring);
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
            std::size_t end = k; // the stretch k .. end-1 (walk order)
            while (end < n && state[(start + end) % n] == 'o')
                ++end;
            std::vector<QPointF> run;
            // Into the inked line before it and after it, never into a hidden edge.
            int back = 0;
            while (back < reach && k > std::size_t(back) &&
                   state[(start + k - std::size_t(back) - 1) % n] == 'i')
                ++back;
            for (int j = back; j > 0; --j)
                run.push_back(points[(start + k - std::size_t(j)) % n]);
            for (std::size_t j = k; j < end; ++j)
                run.push_back(points[(start + j) % n]);
            for (int j = 0; j < reach && state[(start + end + std::size_t(j)) % n] == 'i'; ++j)
                run.push_back(points[(start + end + std::size_t(j)) % n]);
            addCloser(run);
            k = end;
        }
    }
    return out;
}

} // namespace finbook::model
