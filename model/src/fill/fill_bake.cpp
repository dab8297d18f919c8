// The fills of a pose made the drawing (fill_resolve.h, fillsAfterBake): each face of the
// baked drawing shows the fill the pose showed over most of it, exactly.
//
// The pose is what the animator saw, so it is the reference: its fills are painted as every
// renderer paints them (paintLayers: a cut-out's layers and round joints included) into a
// picture of fill indices, the baked drawing's faces into a picture of face indices, and each
// face takes the fill that covers most of its pixels (or none, when most of it showed no
// fill). Each fill is then tied to exactly its faces: a fill's seed and bounding strokes are
// those of one face (fillOfFace), so faceFills resolves it to that face alone (no split rule
// reaches past it), and a fill the pose showed on several faces of the baked drawing (a limb
// crossing the body cuts the body in two) gets one more fill per further face, in its colour
// and shading. Resolving by seed points alone let a seed fall into a neighbouring region and
// a fill spread over faces the pose showed empty (slivers between a limb and the body).
#include "../skeleton/nearest_bone.h"

#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>

#include <QImage>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <functional>
#include <unordered_map>

namespace finbook::model {

namespace {

// The longer side of the index pictures: a face of a few canvas pixels still covers pixels
// of them on any drawing a canvas holds, and the two pictures stay at 4 MB each.
constexpr int kIndexPictureSide = 1024;
constexpr double kMaxIndexScale = 8.0;

QRgb indexColour(int index)
{
    return 0xff000000u | QRgb(index + 1); // 0 (black) = nothing
}

int colourIndex(QRgb c)
{
    return int(c & 0x00ffffffu) - 1;
}

// A black picture of indices over `box` (canvas px) at up to kIndexPictureSide px, with the
// transform from canvas px to it; a null picture when the box is empty or not finite.
struct IndexPicture {
    QImage image;
    QTransform toPixels;
};

IndexPicture indexPicture(const QRectF &box)
{
    const double side = std::max(box.width(), box.height());
    if (!(side > 0.0) || !std::isfinite(side))
        return {};
    const double scale = std::min(kMaxIndexScale, kIndexPictureSide / side);
    IndexPicture out;
    out.image = QImage(std::max(1, int(std::ceil(box.width() * scale)) + 2),
                       std::max(1, int(std::ceil(box.height() * scale)) + 2), QImage::Format_RGB32);
    if (out.image.isNull())
        return out;
    out.image.fill(Qt::black);
    out.toPixels.translate(1, 1);
    out.toPixels.scale(scale, scale);
    out.toPixels.translate(-box.left(), -box.top());
    return out;
}

// The posed fills (`layers`) painted into `picture` as their fill indices, as shown.
void paintShownFills(IndexPicture &picture, const std::vector<PaintLayer> &layers)
{
    QPainter painter(&picture.image);
    painter.setPen(Qt::NoPen);
    painter.setTransform(picture.toPixels);
    for (const PaintLayer &layer : layers)
        for (const FillItem &item : layer.fills)
            if (item.fill >= 0)
                painter.fillPath(item.path, QColor::fromRgb(indexColour(item.fill)));
}

// The faces of `regions` painted into `picture`, each as index `indexOf(face)` (none if < 0).
void paintFaces(IndexPicture &picture, const ObjectRegions &regions,
                const std::function<int(int)> &indexOf)
{
    QPainter painter(&picture.image);
    painter.setPen(Qt::NoPen);
    painter.setTransform(picture.toPixels);
    for (int f = 0; f < regions.faceCount(); ++f)
        if (const int index = indexOf(f); index >= 0)
            painter.fillPath(regions.restPath(f), QColor::fromRgb(indexColour(index)));
}

// Per face of `regions`, the pixels of the posed fills (`layers`) over it: fill index (−1
// none) → count.
std::vector<std::unordered_map<int, long long>> coverage(const ObjectRegions &regions,
                                                         const std::vector<PaintLayer> &layers)
{
    std::vector<std::unordered_map<int, long long>> out(std::size_t(regions.faceCount()));
    QRectF box;
    for (int f = 0; f < regions.faceCount(); ++f)
        box = box.united(regions.restPath(f).boundingRect());
    IndexPicture faces = indexPicture(box), fills = indexPicture(box);
    if (faces.image.isNull() || fills.image.isNull())
        return out;
    paintFaces(faces, regions, [](int f) { return f; });
    paintShownFills(fills, layers);
    const QSize size = faces.image.size();
    for (int y = 0; y < size.height(); ++y) {
        const auto *face = reinterpret_cast<const QRgb *>(faces.image.constScanLine(y));
        const auto *fill = reinterpret_cast<const QRgb *>(fills.image.constScanLine(y));
        for (int x = 0; x < size.width();) {
            // Runs of one (face, fill) pair are counted at once.
            int end = x + 1;
            while (end < size.width() && face[end] == face[x] && fill[end] == fill[x])
                ++end;
            const int f = colourIndex(face[x]);
            if (f >= 0 && f < regions.faceCount())
                out[std::size_t(f)][colourIndex(fill[x])] += end - x;
            x = end;
        }
    }
    return out;
}

// Per face of `regions`, the index of the fill the pose (`layers`) shows over most of it, or
// −1 where most of it showed none.
std::vector<int> shownFillPerFace(const ObjectRegions &regions,
                                  const std::vector<PaintLayer> &layers, int fillCount)
{
    std::vector<int> out(std::size_t(regions.faceCount()), -1);
    const auto counts = coverage(regions, layers);
    for (int f = 0; f < regions.faceCount(); ++f) {
        int best = -1;
        long long bestCount = 0;
        for (const auto &[fill, count] : counts[std::size_t(f)])
            if (count > bestCount || (count == bestCount && fill > best)) {
                best = fill;
                bestCount = count;
            }
        if (bestCount == 0) { // smaller than a pixel of the picture: its seed decides
            const auto &seed = regions.regions().faces[std::size_t(f)].seed;
            best = shownFillAt(layers, QPointF(seed.x(), seed.y()));
        }
        out[std::size_t(f)] = best >= 0 && best < fillCount ? best : -1;
    }
    return out;
}

// The regions of the baked drawing (`baked`), the pose (`group`) as painted, and per face the
// fill the pose showed over most of it (shownFillPerFace).
struct BakedOwners {
    ObjectRegionsPtr regions;
    std::vector<PaintLayer> layers;
    std::vector<int> owner;
};

BakedOwners bakedOwners(const StrokeGroup &group, const std::vector<Stroke> &baked, double closeGap)
{
    StrokeGroup after;
    after.strokes = baked;
    BakedOwners out;
    out.regions = objectRegions(after, closeGap);
    DocumentSettings settings;
    settings.closeGap = closeGap;
    StrokeGroup shown = group;
    shown.visible = true; // a hidden object keeps its fills too
    out.layers = paintLayers(shown, settings);
    out.owner = shownFillPerFace(*out.regions, out.layers, int(group.fills.size()));
    return out;
}

// Whether a line of no ink in `baked` (a cut-out closer) already runs along `line`: its gap
// is closed there, and a second line on top of the first would only make slivers between
// them. (Inked lines are left out: across a gap a few px wide, both ends are that near.)
bool runsAlongALine(const std::vector<Stroke> &baked, const QLineF &line)
{
    constexpr int kSamples = 9;
    for (int k = 1; k <= kSamples; ++k) {
        const QPointF p = line.pointAt(double(k) / (kSamples + 1));
        bool near = false;
        for (const Stroke &s : baked) {
            if (!s.data || s.data->points.empty() || qAlpha(s.data->color) != 0)
                continue;
            const auto &pts = s.data->points;
            const double reach = 0.5 * double(s.data->width) + 1.5;
            for (std::size_t i = 0; i < pts.size() && !near; ++i) {
                const QPointF a(pts[i].x, pts[i].y);
                const QPointF b = i + 1 < pts.size() ? QPointF(pts[i + 1].x, pts[i + 1].y) : a;
                near = join_detail::project(p, a, b).second <= reach;
            }
            if (near)
                break;
        }
        if (!near)
            return false;
    }
    return true;
}

} // namespace

std::vector<Fill> fillsAfterBake(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                 double closeGap)
{
    if (group.fills.empty())
        return {};
    const BakedOwners baking = bakedOwners(group, baked, closeGap);
    const ObjectRegionsPtr &regions = baking.regions;
    const std::vector<int> &owner = baking.owner;
    // Each fill keeps its place in the list on its largest face; its other faces follow.
    std::vector<int> largest(group.fills.size(), -1);
    for (int f = 0; f < regions->faceCount(); ++f) {
        const int i = owner[std::size_t(f)];
        if (i < 0)
            continue;
        int &l = largest[std::size_t(i)];
        if (l < 0 || regions->regions().faces[std::size_t(f)].area >
                         regions->regions().faces[std::size_t(l)].area)
            l = f;
    }
    const auto tied = [&](int face, const Fill &source) {
        Fill fill = fillOfFace(*regions, face, source.color);
        fill.shading = source.shading;
        return fill;
    };
    std::vector<Fill> out;
    for (std::size_t i = 0; i < group.fills.size(); ++i)
        if (largest[i] >= 0)
            out.push_back(tied(largest[i], group.fills[i]));
    for (int f = 0; f < regions->faceCount(); ++f) {
        const int i = owner[std::size_t(f)];
        if (i >= 0 && largest[std::size_t(i)] != f)
            out.push_back(tied(f, group.fills[std::size_t(i)]));
    }
    return out;
}

double shownFillAgreement(const StrokeGroup &group, const std::vector<Stroke> &baked,
                          double closeGap)
{
    if (group.fills.empty())
        return 1.0;
    const BakedOwners baking = bakedOwners(group, baked, closeGap);
    const ObjectRegionsPtr &regions = baking.regions;
    const std::vector<PaintLayer> &layers = baking.layers;
    const std::vector<int> &owner = baking.owner;
    QRectF box;
    for (const PaintLayer &layer : layers)
        for (const FillItem &item : layer.fills)
            box = box.united(item.path.boundingRect());
    for (int f = 0; f < regions->faceCount(); ++f)
        box = box.united(regions->restPath(f).boundingRect());
    IndexPicture before = indexPicture(box), kept = indexPicture(box);
    if (before.image.isNull() || kept.image.isNull())
        return 1.0;
    paintShownFills(before, layers);
    paintFaces(kept, *regions, [&](int f) { return owner[std::size_t(f)]; });
    const QSize size = before.image.size();
    long long painted = 0, agreeing = 0;
    for (int y = 0; y < size.height(); ++y) {
        const auto *a = reinterpret_cast<const QRgb *>(before.image.constScanLine(y));
        const auto *b = reinterpret_cast<const QRgb *>(kept.image.constScanLine(y));
        for (int x = 0; x < size.width(); ++x)
            if (a[x] != 0xff000000u || b[x] != 0xff000000u) {
                ++painted;
                agreeing += a[x] == b[x];
            }
    }
    return painted > 0 ? double(agreeing) / double(painted) : 1.0;
}

std::vector<Stroke> keptGapClosers(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                   double closeGap, const std::function<Id()> &newId)
{
    if (group.fills.empty() || !group.isDeformed())
        return {};
    const ObjectRegionsPtr before = objectRegions(group, closeGap);
    const auto &closures = before->regions().closures;
    if (closures.empty())
        return {};
    const std::vector<QLineF> shown = before->displayedClosures(group);
    StrokeGroup after;
    after.strokes = baked;
    const ObjectRegionsPtr regions = objectRegions(after, closeGap);
    std::vector<Stroke> out;
    for (std::size_t i = 0; i < shown.size() && i < closures.size(); ++i) {
        const QLineF &line = shown[i];
        const int from = closures[i].fromStroke;
        const float width = from >= 0 && std::size_t(from) < group.strokes.size() &&
                                    group.strokes[std::size_t(from)].data
                                ? group.strokes[std::size_t(from)].data->width
                                : StrokeData().width;
        const double near = 2.0 * double(width) + 0.5;
        const auto close = [near](QPointF a, const Eigen::Vector2d &b) {
            return QLineF(a, QPointF(b.x(), b.y())).length() <= near;
        };
        const bool kept =
            std::any_of(regions->regions().closures.begin(), regions->regions().closures.end(),
                        [&](const geometry::GapClosure &c) {
                            return (close(line.p1(), c.from) && close(line.p2(), c.to)) ||
                                   (close(line.p1(), c.to) && close(line.p2(), c.from));
                        });
        if (kept || !(line.length() > 0.0) || !std::isfinite(line.length()) ||
            runsAlongALine(baked, line))
            continue;
        auto data = std::make_shared<StrokeData>();
        data->color = kGapCloserColor;
        data->width = width;
        data->points = {{float(line.x1()), float(line.y1()), 1.0f},
                        {float(line.x2()), float(line.y2()), 1.0f}};
        out.push_back({newId(), std::move(data)});
    }
    return out;
}

} // namespace finbook::model
