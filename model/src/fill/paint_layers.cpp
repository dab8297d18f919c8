// An object's layers as the renderers paint them (fill_render.h, paintLayers): one, or one
// per piece of a cut-out pose.
#include <finbook/model/fill/fill_render.h>

#include <algorithm>
#include <optional>

namespace finbook::model {

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
    if (rigid) {
        StrokeGroup still = group;
        still.deformed.reset();
        rest = fillList(still, settings, options);
        if (rest.size() != layers[0].fills.size())
            rest.clear();
    }
    const std::vector<FillItem> shown = std::move(layers[0].fills);
    layers[0].fills.clear();
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
        const std::vector<FillItem> &source = moved ? rest : shown;
        const auto place = [&](const QPainterPath &path) {
            QPainterPath placed = moved ? motion->map(path) : path;
            placed.setFillRule(Qt::WindingFill);
            return outline ? placed.intersected(*outline) : placed;
        };
        for (const FillItem &fill : source) {
            FillItem clipped;
            clipped.path = place(fill.path);
            if (clipped.path.isEmpty())
                continue;
            clipped.path.setFillRule(Qt::WindingFill);
            clipped.color = fill.color;
            for (const ToneItem &tone : fill.tones) {
                ToneItem part = tone;
                part.path = place(tone.path);
                if (!part.path.isEmpty())
                    clipped.tones.push_back(std::move(part));
            }
            layers[layer].fills.push_back(std::move(clipped));
        }
    }
    // Sockets (round joints): painted on the piece above each cut (over its fills, under its
    // strokes) in the colour of the limb's fill that meets the socket, so a turned limb leaves
    // no gap at its joint.
    for (std::size_t k = 0; k < pieces && k < posed->sockets.size(); ++k) {
        const QPainterPath &socket = posed->sockets[k];
        if (socket.isEmpty() || k >= posed->socketAbove.size())
            continue;
        const std::vector<FillItem> &limb = layers[k + 1].fills;
        const auto colour = std::find_if(limb.rbegin(), limb.rend(), [&](const FillItem &fill) {
            return fill.path.intersects(socket);
        });
        if (colour == limb.rend())
            continue;
        FillItem fill;
        fill.path = socket;
        fill.color = colour->color;
        layers[std::size_t(std::clamp(posed->socketAbove[k] + 1, 0, int(pieces)))].fills.push_back(
            std::move(fill));
    }
    // The strokes: each item (a displayed stroke, folded repeats included) split into runs of
    // segments that moved with one piece; a segment across a cut goes with the deeper piece.
    const std::vector<PaintItem> items = std::move(layers[0].strokes);
    layers[0].strokes.clear();
    const auto *first = posed->strokes.data();
    struct Entry {
        std::size_t layer;
        PaintItem item;
        std::ptrdiff_t run; // into layers[layer].runs, or −1: the item as it is
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
        const auto layerOf = [&](std::size_t i) {
            const int p = i + 1 < points.size() ? std::max(piece[i], piece[i + 1]) : piece[i];
            return std::size_t(std::clamp(p + 1, 0, int(pieces)));
        };
        if (points.size() <= 1 || std::all_of(piece.begin(), piece.end(),
                                              [&](std::int16_t p) { return p == piece[0]; })) {
            entries.push_back({layerOf(0), item, -1});
            continue;
        }
        std::size_t start = 0;
        while (start + 1 < points.size()) {
            const std::size_t layer = layerOf(start);
            std::size_t end = start + 1;
            while (end + 1 < points.size() && layerOf(end) == layer)
                ++end;
            entries.push_back({layer, item, std::ptrdiff_t(layers[layer].runs.size())});
            layers[layer].runs.emplace_back(points.begin() + std::ptrdiff_t(start),
                                            points.begin() + std::ptrdiff_t(end) + 1);
            start = end;
        }
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
