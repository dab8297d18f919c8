// Fills → paths to draw (fill_render.h).
#include <finbook/model/fill/fill_regions.h>
#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
std::vector<FillItem> fillItems(const StrokeGroup &group, double closeGap,
                                const DocumentSettings *shade, const RenderOptions &options)
{
    if (group.fills.empty() || (!group.visible && !options.showHidden))
        return {};
    const ObjectRegionsPtr regions = objectRegions(group, closeGap);
    const std::vector<int> shown = faceFills(*regions, group.fills);
    std::vector<FillItem> items(group.fills.size());
    for (int f = 0; f < regions->faceCount(); ++f) {
        const int fill = shown[std::size_t(f)];
        if (fill < 0)
            continue;
        const QPainterPath facePath = regions->displayedPath(group, f);
        items[std::size_t(fill)].path.addPath(facePath);
        const Fill &source = group.fills[std::size_t(fill)];
        if (shade && options.shading && !options.tint && source.shading.shaded())
            for (ToneItem &tone :
                 faceTones(group, regions, f, facePath, source.shading, source.color, *shade))
                items[std::size_t(fill)].tones.push_back(std::move(tone));
    }
    std::vector<FillItem> out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items[i].path.isEmpty())
            continue;
        items[i].path.setFillRule(Qt::WindingFill);
        QRgb color = group.fills[i].color;
        if (!items[i].tones.empty())
            color = baseTone(color, group.fills[i].shading);
        if (options.tint) {
            const QColor t = *options.tint;
            color =
                qRgba(t.red(), t.green(), t.blue(), int(std::lround(t.alpha() * kTintedFillAlpha)));
        }
        items[i].color = color;
        items[i].fill = int(i);
        out.push_back(std::move(items[i]));
    }
    return out;
}
} // namespace

std::vector<FillItem> fillList(const StrokeGroup &group, double closeGap,
                               const RenderOptions &options)
{
    return fillItems(group, closeGap, nullptr, options);
}

std::vector<FillItem> fillList(const StrokeGroup &group, const DocumentSettings &settings,
                               const RenderOptions &options)
{
    return fillItems(group, settings.closeGap, &settings, options);
}

void paintFill(QPainter &painter, const FillItem &fill)
{
    painter.fillPath(fill.path, QColor::fromRgba(fill.color));
    for (const ToneItem &tone : fill.tones)
        painter.fillPath(tone.path, QColor::fromRgba(tone.color));
}

std::vector<FillItem> paintedFills(const StrokeGroup &group, const std::vector<FillItem> &fills)
{
    if (group.isDeformed() && group.rig.isPosed())
        return fills;
    std::vector<FillItem> out;
    std::vector<QRectF> boxes;
    out.reserve(fills.size());
    for (const FillItem &fill : fills) {
        const QRectF box = fill.path.controlPointRect();
        int into = -1;
        if (fill.tones.empty())
            for (int i = int(out.size()) - 1; i >= 0; --i) {
                const FillItem &o = out[std::size_t(i)];
                if (o.color == fill.color && o.tones.empty()) {
                    into = i;
                    break;
                }
                if (boxes[std::size_t(i)].intersects(box))
                    break; // painted between, over this fill's place: the order matters
            }
        if (into < 0) {
            out.push_back(fill);
            boxes.push_back(box);
            continue;
        }
        out[std::size_t(into)].path.addPath(fill.path);
        boxes[std::size_t(into)] |= box;
    }
    return out;
}

bool frameHasFills(const Frame &frame, const RenderOptions &options)
{
    return options.fills &&
           std::any_of(frame.groups.begin(), frame.groups.end(), [&](const StrokeGroup &g) {
               return !g.fills.empty() && (g.visible || options.showHidden);
           });
}

} // namespace finbook::model
