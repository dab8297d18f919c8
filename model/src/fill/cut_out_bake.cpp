// Apply Pose of a cut-out pose (fill_render.h, bakedStrokes): the posed lines with the parts a
// piece drawn over them hides cut away, so the baked drawing, whose fills all lie under all its
// strokes, shows what the layered pose showed.
#include <finbook/model/fill/fill_render.h>

#include <algorithm>
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

} // namespace finbook::model
