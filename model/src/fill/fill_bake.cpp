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
// crossing the body cuts the body in two) keeps them all as its further regions (Fill::more),
// each tied the same way: still one fill, recoloured with one click. Resolving by seed points alone
// let a seed fall into a neighbouring region and a fill spread over faces the pose showed empty
// (slivers between a limb and the body).
#include "../skeleton/nearest_bone.h"

#include <finbook/model/fill/fill_render.h>
#include <finbook/model/fill/fill_resolve.h>

#include <QImage>
#include <QPainter>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <optional>
#include <unordered_map>
#include <utility>

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

// The faces of `regions` painted into `picture`, each as its index.
void paintFaces(IndexPicture &picture, const ObjectRegions &regions)
{
    QPainter painter(&picture.image);
    painter.setPen(Qt::NoPen);
    painter.setTransform(picture.toPixels);
    for (int f = 0; f < regions.faceCount(); ++f)
        painter.fillPath(regions.restPath(f), QColor::fromRgb(indexColour(f)));
}

// The two index pictures over the baked faces and the posed fills: per pixel, the baked face
// (−1 none) and the fill the pose showed there (−1 none). (The seams and the agreement look at
// every pixel several times: read through pointers kept, not QImage's calls.)
struct FacesAndFills {
    IndexPicture faces, fills;
    int width = 0, height = 0;
    int face(int x, int y) const { return colourIndex(m_faces[at(x, y)]); }
    int fill(int x, int y) const { return colourIndex(m_fills[at(x, y)]); }
    // Row y of either picture, raw (colourIndex reads it).
    const QRgb *faceRow(int y) const { return m_faces + at(0, y); }
    const QRgb *fillRow(int y) const { return m_fills + at(0, y); }

    void readOut()
    {
        width = faces.image.width();
        height = faces.image.height();
        // Both are RGB32 pictures of one size, whose lines QImage packs without padding.
        m_stride = std::size_t(faces.image.bytesPerLine()) / sizeof(QRgb);
        m_faces = reinterpret_cast<const QRgb *>(std::as_const(faces.image).constBits());
        m_fills = reinterpret_cast<const QRgb *>(std::as_const(fills.image).constBits());
    }

private:
    std::size_t at(int x, int y) const { return std::size_t(y) * m_stride + std::size_t(x); }
    std::size_t m_stride = 0;
    const QRgb *m_faces = nullptr;
    const QRgb *m_fills = nullptr;
};

} // namespace

// What ShownPose keeps painted: the pose's fills as painted (paintLayers), their index picture
// over the last box asked for, and the inked lines' pixels over the last picture and lines
// asked for. Apply Pose weighs a dozen bakes whose faces mostly span one box.
struct ShownPose::Painted {
    std::optional<std::vector<PaintLayer>> layers;
    QRectF layersBox;
    QRectF fillsBox;
    QImage fills; // an index picture (IndexPicture) over fillsBox
    QTransform fillsToPixels;
    QTransform inkToPixels;              // with the size of `ink`, the picture it covers
    std::vector<StrokeDataPtr> inkLines; // held, so no other line takes their address
    std::vector<char> ink;
};

ShownPose::ShownPose(const StrokeGroup &group, double closeGap)
    : m_group(group)
    , m_closeGap(closeGap)
    , m_painted(std::make_unique<Painted>())
{}

ShownPose::~ShownPose() = default;

namespace {

// The pose's fills as every renderer paints them (a hidden object keeps its fills too), and
// their bounding box, painted once.
const std::vector<PaintLayer> &shownLayers(const ShownPose &pose, QRectF *box = nullptr)
{
    ShownPose::Painted &painted = pose.painted();
    if (!painted.layers) {
        DocumentSettings settings;
        settings.closeGap = pose.closeGap();
        StrokeGroup shown = pose.group();
        shown.visible = true;
        painted.layers = paintLayers(shown, settings);
        for (const PaintLayer &layer : *painted.layers)
            for (const FillItem &item : layer.fills)
                painted.layersBox = painted.layersBox.united(item.path.boundingRect());
    }
    if (box)
        *box = painted.layersBox;
    return *painted.layers;
}

FacesAndFills facesAndFills(const ObjectRegions &regions, const ShownPose &pose)
{
    QRectF box;
    const std::vector<PaintLayer> &layers = shownLayers(pose, &box);
    for (int f = 0; f < regions.faceCount(); ++f)
        box = box.united(regions.restPath(f).boundingRect());
    FacesAndFills out;
    out.faces = indexPicture(box);
    if (out.faces.image.isNull())
        return {};
    ShownPose::Painted &painted = pose.painted();
    if (painted.fills.isNull() || painted.fillsBox != box) {
        IndexPicture fills = indexPicture(box);
        if (fills.image.isNull())
            return {};
        paintShownFills(fills, layers);
        painted.fills = std::move(fills.image);
        painted.fillsToPixels = fills.toPixels;
        painted.fillsBox = box;
    }
    out.fills = {painted.fills, painted.fillsToPixels}; // shared, read only
    paintFaces(out.faces, regions);
    out.readOut();
    return out;
}

// Per face (of `faceCount`), the pixels of the posed fills over it: fill index (−1 none) →
// count.
std::vector<std::unordered_map<int, long long>> coverage(const FacesAndFills &p, int faceCount)
{
    std::vector<std::unordered_map<int, long long>> out(static_cast<std::size_t>(faceCount));
    for (int y = 0; y < p.height; ++y) {
        const QRgb *face = p.faceRow(y);
        const QRgb *fill = p.fillRow(y);
        for (int x = 0; x < p.width;) {
            // Runs of one (face, fill) pair are counted at once.
            int end = x + 1;
            while (end < p.width && face[end] == face[x] && fill[end] == fill[x])
                ++end;
            const int f = colourIndex(face[x]);
            if (f >= 0 && f < faceCount)
                out[std::size_t(f)][colourIndex(fill[x])] += end - x;
            x = end;
        }
    }
    return out;
}

// Per face of `regions`, the index of the fill the pose (`layers`) shows over most of it, or
// −1 where most of it showed none.
std::vector<int> shownFillPerFace(const ObjectRegions &regions,
                                  const std::vector<PaintLayer> &layers, const FacesAndFills &p,
                                  int fillCount)
{
    std::vector<int> out(std::size_t(regions.faceCount()), -1);
    const auto counts = coverage(p, regions.faceCount());
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

// The regions of the baked drawing (`baked`), the pose as painted, and per face the fill the
// pose showed over most of it (shownFillPerFace).
struct BakedOwners {
    ObjectRegionsPtr regions;
    FacesAndFills pictures;
    std::vector<int> owner;
};

BakedOwners bakedOwners(const ShownPose &pose, const std::vector<Stroke> &baked)
{
    StrokeGroup after;
    after.strokes = baked;
    BakedOwners out;
    out.regions = objectRegions(after, pose.closeGap());
    out.pictures = facesAndFills(*out.regions, pose);
    out.owner = shownFillPerFace(*out.regions, shownLayers(pose), out.pictures,
                                 int(pose.group().fills.size()));
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
            if (!s.data || s.data->points.empty() || s.data->color != kGapCloserColor)
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

std::vector<char> inkMask(const std::vector<Stroke> &baked, bool closersToo,
                          const IndexPicture &like, int w, int h, double widthShare = 1.0);
bool boundingLine(const Stroke &s, bool closersToo);

// inkMask of the inked lines of `baked` over `p`'s pictures, painted once while the box and
// the lines stay the same (the bakes Apply Pose weighs differ in lines of no ink only).
const std::vector<char> &inkedPixels(const ShownPose &pose, const std::vector<Stroke> &baked,
                                     const FacesAndFills &p)
{
    ShownPose::Painted &painted = pose.painted();
    std::vector<StrokeDataPtr> lines;
    for (const Stroke &s : baked)
        if (boundingLine(s, false))
            lines.push_back(s.data);
    if (painted.ink.size() != std::size_t(p.width) * std::size_t(p.height) ||
        painted.inkToPixels != p.faces.toPixels || painted.inkLines != lines) {
        painted.ink = inkMask(baked, false, p.faces, p.width, p.height);
        painted.inkToPixels = p.faces.toPixels;
        painted.inkLines = std::move(lines);
    }
    return painted.ink;
}

// Of the pixels the pose showed filled, or the baked faces would fill, the share where the two
// agree: where no inked line of `baked` covers them, and everywhere (shownFillAgreement).
FillAgreement agreement(const ShownPose &pose, const BakedOwners &baking,
                        const std::vector<Stroke> &baked)
{
    const FacesAndFills &p = baking.pictures;
    const std::vector<char> &inked = inkedPixels(pose, baked, p);
    long long painted[2] = {0, 0}, agreeing[2] = {0, 0}; // seen, all
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            const int face = p.face(x, y);
            const int shown = p.fill(x, y);
            const int kept = face >= 0 ? baking.owner[std::size_t(face)] : -1;
            if (shown >= 0 || kept >= 0) {
                const bool seen = !inked[std::size_t(y) * std::size_t(p.width) + std::size_t(x)];
                painted[0] += seen;
                agreeing[0] += seen && shown == kept;
                ++painted[1];
                agreeing[1] += shown == kept;
            }
        }
    const auto share = [&](int k) {
        return painted[k] > 0 ? double(agreeing[k]) / double(painted[k]) : 1.0;
    };
    return {share(0), share(1)};
}

} // namespace

StrokeDataPtr lineOfNoInk(const std::vector<QPointF> &points, double width)
{
    auto data = std::make_shared<StrokeData>();
    data->color = kGapCloserColor;
    data->width = float(width);
    for (const QPointF &q : points)
        data->points.push_back({float(q.x()), float(q.y()), 1.0f});
    return data;
}

double medianInkWidth(const std::vector<Stroke> &strokes)
{
    std::vector<double> widths;
    for (const Stroke &s : strokes)
        if (s.data && qAlpha(s.data->color) != 0 && !s.data->points.empty() &&
            std::isfinite(s.data->width))
            widths.push_back(double(s.data->width));
    if (widths.empty())
        return 1.0;
    std::nth_element(widths.begin(), widths.begin() + std::ptrdiff_t(widths.size() / 2),
                     widths.end());
    return std::clamp(widths[widths.size() / 2], 0.5, 64.0);
}

std::vector<Fill> fillsAfterBake(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                 double closeGap)
{
    return fillsAfterBake(ShownPose(group, closeGap), baked);
}

std::vector<Fill> fillsAfterBake(const ShownPose &pose, const std::vector<Stroke> &baked)
{
    const StrokeGroup &group = pose.group();
    if (group.fills.empty())
        return {};
    const BakedOwners baking = bakedOwners(pose, baked);
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
    std::vector<int> at(group.fills.size(), -1); // each fill's place in `out`
    for (std::size_t i = 0; i < group.fills.size(); ++i)
        if (largest[i] >= 0) {
            at[i] = int(out.size());
            out.push_back(tied(largest[i], group.fills[i]));
        }
    for (int f = 0; f < regions->faceCount(); ++f) {
        const int i = owner[std::size_t(f)];
        if (i >= 0 && largest[std::size_t(i)] != f) {
            const Fill further = fillOfFace(*regions, f, 0);
            out[std::size_t(at[std::size_t(i)])].more.push_back(
                FillPlace{further.seed, further.strokes});
        }
    }
    return out;
}

FillAgreement shownFillAgreement(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                 double closeGap)
{
    return shownFillAgreement(ShownPose(group, closeGap), baked);
}

FillAgreement shownFillAgreement(const ShownPose &pose, const std::vector<Stroke> &baked)
{
    if (pose.group().fills.empty())
        return {};
    return agreement(pose, bakedOwners(pose, baked), baked);
}

std::vector<Stroke> keptGapClosers(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                   double closeGap, const std::function<Id()> &newId,
                                   GapMatch match, std::vector<Stroke> *rematched)
{
    if (rematched)
        rematched->clear();
    if (group.fills.empty() || !group.isDeformed())
        return {};
    const ObjectRegionsPtr before = objectRegions(group, closeGap);
    const auto &closures = before->regions().closures;
    if (closures.empty())
        return {};
    const std::vector<QLineF> shown = before->displayedClosures(group);
    const std::size_t count = std::min(shown.size(), closures.size());
    const auto widthOf = [&](std::size_t i) {
        const int from = before->strokeOfInput(closures[i].fromStroke);
        return from >= 0 && std::size_t(from) < group.strokes.size() &&
                       group.strokes[std::size_t(from)].data
                   ? group.strokes[std::size_t(from)].data->width
                   : StrokeData().width;
    };
    const auto reach = [&](std::size_t i, GapMatch m) {
        return (m == GapMatch::Near ? 2.0 : 0.5) * double(widthOf(i)) + 0.5;
    };
    // Matching again is tried only where a closer drawn in ends on (within half a pen of) the
    // end of one not drawn in: the end it took may have been that one's.
    const auto sharesAnEnd = [&](std::size_t i, const QLineF &kept) {
        const double near = reach(i, GapMatch::Exact);
        for (const QPointF &a : {shown[i].p1(), shown[i].p2()})
            for (const QPointF &b : {kept.p1(), kept.p2()})
                if (QLineF(a, b).length() <= near)
                    return true;
        return false;
    };
    constexpr int kRounds = 3; // with `rematched`: the header says why
    std::vector<Stroke> out;
    std::vector<char> added(count, 0);
    std::size_t firstRound = 0; // closers the first round drew in
    for (int round = 0; round < (rematched ? kRounds : 1); ++round) {
        if (round > 0) {
            bool touched = false;
            for (std::size_t i = 0; i < count && !touched; ++i)
                for (std::size_t k = 0; k < count && !touched; ++k)
                    touched = !added[i] && added[k] == round && sharesAnEnd(i, shown[k]);
            if (!touched)
                break;
        }
        StrokeGroup after;
        after.strokes = baked;
        after.strokes.insert(after.strokes.end(), out.begin(), out.end());
        const ObjectRegionsPtr regions = objectRegions(after, closeGap);
        bool grew = false;
        for (std::size_t i = 0; i < count; ++i) {
            if (added[i])
                continue;
            const QLineF &line = shown[i];
            const double near = reach(i, match);
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
            out.push_back({newId(), lineOfNoInk({line.p1(), line.p2()}, widthOf(i))});
            added[i] = char(round + 1);
            grew = true;
        }
        if (round == 0)
            firstRound = out.size();
        if (!grew)
            break;
    }
    if (rematched && out.size() > firstRound)
        *rematched = out;
    out.resize(firstRound);
    return out;
}

namespace {

// Seams (shownColourSeams). A part of a face that showed another fill is given a seam only
// when it covers this much (canvas px²): a speck is the pictures' rounding.
constexpr double kSeamSmallestArea = 6.0;
// A seam's staircase of pixel edges is straightened to within this many picture px.
constexpr double kSeamStraighten = 0.75;
// The most points all seams may have: the regions of a drawing take 20,000 segments at most,
// and each seam's ends are matched against every other seam.
constexpr std::size_t kSeamMostPoints = 4000;
// A seam ends this far (canvas px) past the edge or seam it meets, as gap closing's links do.
constexpr double kSeamHairPast = 0.01;
// ShownColourSeams::seamsAcrossInk: the share of a line's width that bounds a region there.
constexpr double kThinInkShare = 1.0 / 3.0;

// The four directions between pixel corners: right, down, left, up.
constexpr int kDx[4] = {1, 0, -1, 0};
constexpr int kDy[4] = {0, 1, 0, -1};

// Douglas–Peucker on `points` (first and last kept).
void straighten(const std::vector<QPointF> &points, std::size_t from, std::size_t to,
                double tolerance, std::vector<QPointF> &out)
{
    double worst = -1.0;
    std::size_t at = from;
    for (std::size_t k = from + 1; k < to; ++k) {
        const double d = join_detail::project(points[k], points[from], points[to]).second;
        if (d > worst) {
            worst = d;
            at = k;
        }
    }
    if (worst > tolerance) {
        straighten(points, from, at, tolerance, out);
        straighten(points, at, to, tolerance, out);
    } else {
        out.push_back(points[to]);
    }
}

std::vector<QPointF> straightened(const std::vector<QPointF> &points, double tolerance)
{
    if (points.size() < 3)
        return points;
    std::vector<QPointF> out{points.front()};
    if (points.front() == points.back()) { // a ring: split at its farthest point
        std::size_t far = 0;
        for (std::size_t k = 1; k < points.size(); ++k)
            if (QLineF(points[0], points[k]).length() > QLineF(points[0], points[far]).length())
                far = k;
        straighten(points, 0, far, tolerance, out);
        straighten(points, far, points.size() - 1, tolerance, out);
    } else {
        straighten(points, 0, points.size() - 1, tolerance, out);
    }
    return out;
}

// Whether `s` is a line that bounds regions: inked, or with `closersToo` a line of no ink that
// closes a gap (hidden lines bound nothing).
bool boundingLine(const Stroke &s, bool closersToo)
{
    return s.data && !s.data->points.empty() &&
           (qAlpha(s.data->color) != 0 || (closersToo && s.data->color == kGapCloserColor));
}

// Per pixel of a picture (`like`'s transform, w × h), whether a bounding line of `baked`
// (boundingLine) covers it, drawn at its pen width with round ends.
std::vector<char> inkMask(const std::vector<Stroke> &baked, bool closersToo,
                          const IndexPicture &like, int w, int h, double widthShare)
{
    QImage image(w, h, QImage::Format_Grayscale8);
    std::vector<char> out(std::size_t(w) * std::size_t(h), 0);
    if (image.isNull())
        return out;
    image.fill(0);
    {
        QPainter painter(&image);
        painter.setTransform(like.toPixels);
        for (const Stroke &s : baked) {
            if (!boundingLine(s, closersToo) || !std::isfinite(s.data->width))
                continue;
            QPainterPath path(QPointF(s.data->points.front().x, s.data->points.front().y));
            for (const StrokePoint &q : s.data->points)
                path.lineTo(q.x, q.y);
            painter.strokePath(path, QPen(Qt::white,
                                          widthShare * std::clamp(double(s.data->width), 0.0, 64.0),
                                          Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        }
    }
    for (int y = 0; y < h; ++y) {
        const uchar *line = image.constScanLine(y);
        for (int x = 0; x < w; ++x)
            out[std::size_t(y) * std::size_t(w) + std::size_t(x)] = line[x] != 0;
    }
    return out;
}

// The parts of the baked faces that showed a fill other than their face's, and the parts
// outside every face that showed a fill (a region whose gap the pose showed closed and the
// baked lines leave open), 4-connected, one face and one fill each, marked per pixel when
// large and thick enough for a seam.
struct SeamParts {
    std::vector<char> kept;
    bool any = false, outside = false;
};

SeamParts seamParts(const BakedOwners &baking, double scale, double penWidth, double widerThanPen)
{
    const FacesAndFills &p = baking.pictures;
    const int w = p.width, h = p.height;
    const auto index = [w](int x, int y) {
        return std::size_t(y) * std::size_t(w) + std::size_t(x);
    };
    const auto owner = [&](int face) { return face >= 0 ? baking.owner[std::size_t(face)] : -1; };
    const double smallest = kSeamSmallestArea * scale * scale;
    SeamParts out;
    out.kept.assign(std::size_t(w) * std::size_t(h), 0);
    std::vector<char> seen(out.kept.size(), 0);
    std::vector<std::pair<int, int>> part, stack;
    // How far (4-connected steps, picture px) the part's deepest pixel lies from its edge.
    std::vector<int> depth; // per pixel, while a part is measured; 0 elsewhere
    const auto deepest = [&](const std::vector<std::pair<int, int>> &pixels) {
        depth.resize(std::size_t(w) * std::size_t(h), 0);
        for (const auto &[px, py] : pixels)
            depth[index(px, py)] = -1; // in the part, not reached yet
        std::vector<std::pair<int, int>> front, next;
        const auto inPart = [&](int x, int y) {
            return x >= 0 && y >= 0 && x < w && y < h && depth[index(x, y)] != 0;
        };
        for (const auto &[px, py] : pixels)
            for (int k = 0; k < 4; ++k)
                if (!inPart(px + kDx[k], py + kDy[k])) {
                    depth[index(px, py)] = 1;
                    front.emplace_back(px, py);
                    break;
                }
        int reached = front.empty() ? 0 : 1;
        while (!front.empty()) {
            next.clear();
            for (const auto &[px, py] : front)
                for (int k = 0; k < 4; ++k) {
                    const int nx = px + kDx[k], ny = py + kDy[k];
                    if (inPart(nx, ny) && depth[index(nx, ny)] < 0) {
                        depth[index(nx, ny)] = depth[index(px, py)] + 1;
                        next.emplace_back(nx, ny);
                    }
                }
            if (!next.empty())
                ++reached;
            front.swap(next);
        }
        for (const auto &[px, py] : pixels)
            depth[index(px, py)] = 0;
        return double(reached);
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int f = p.face(x, y);
            if (seen[index(x, y)] || p.fill(x, y) == owner(f))
                continue;
            const int fill = p.fill(x, y);
            part.clear();
            stack = {{x, y}};
            seen[index(x, y)] = 1;
            long long rim = 0; // pixel edges between the part and the rest
            while (!stack.empty()) {
                const auto [cx, cy] = stack.back();
                stack.pop_back();
                part.emplace_back(cx, cy);
                for (int k = 0; k < 4; ++k) {
                    const int nx = cx + kDx[k], ny = cy + kDy[k];
                    const bool same = nx >= 0 && ny >= 0 && nx < w && ny < h &&
                                      p.face(nx, ny) == f && p.fill(nx, ny) == fill;
                    rim += !same;
                    if (same && !seen[index(nx, ny)]) {
                        seen[index(nx, ny)] = 1;
                        stack.emplace_back(nx, ny);
                    }
                }
            }
            // The regions merge a face thinner than the pen (twice its area over its
            // perimeter) into its neighbour, which may be the outside: such a part would lose
            // its colour instead of keeping it. A staircase of pixel edges is 4/π as long as
            // the outline it follows.
            const double area = double(part.size()) / (scale * scale);
            const double perimeter = double(rim) / scale * (std::numbers::pi / 4.0);
            bool thickEnough = perimeter > 0.0 &&
                               2.0 * area / perimeter >= widerThanPen * penWidth &&
                               area >= widerThanPen * 2.0 * penWidth * penWidth;
            // Outside every face, a part that the closest pass (widerThanPen 1) finds joins
            // the face beside it once its seam closes it (the seam takes up the free ends
            // whose gap closer left it out: a wedge along an open mouth), so on average it
            // may be thinner than the pen; somewhere it must be half a pen deep (the strips
            // that the pictures' rounding leaves along an outline are not).
            if (!thickEnough && f < 0 && widerThanPen <= 1.0 && perimeter > 0.0)
                thickEnough = deepest(part) >= std::max(1.0, 0.5 * penWidth * scale);
            if (thickEnough && double(part.size()) >= smallest) {
                for (const auto &[px, py] : part)
                    out.kept[index(px, py)] = 1;
                out.any = true;
                out.outside = out.outside || f < 0;
            }
        }
    return out;
}

// A seam before its ends are placed: picture px, then canvas px.
struct SeamChain {
    std::vector<QPointF> points;
    int face = -1; // the face it runs through (−1: outside every face)
    bool ring = false;
};

// The pixel edges between a kept part and the rest of its face showing another fill (those an
// inked line covers left out where `inked` marks them), chained into straightened lines in
// canvas px: through a corner of two edges, and straight on through a corner where three or
// four meet (the line that stops there ends on the one that goes on). Empty when there are
// more than kSeamMostPoints points (colours scattered over a drawing no pose made: the seams
// would cost more than they could keep).
std::vector<SeamChain> seamChains(const FacesAndFills &p, const std::vector<char> &kept,
                                  const std::vector<char> &inked)
{
    const int w = p.width, h = p.height;
    const auto index = [w](int x, int y) {
        return std::size_t(y) * std::size_t(w) + std::size_t(x);
    };
    // The edges as bits per pixel corner (corner (x, y) is the top left of pixel (x, y)).
    const int cw = w + 1, ch = h + 1;
    const auto corner = [cw](int x, int y) {
        return std::size_t(y) * std::size_t(cw) + std::size_t(x);
    };
    std::vector<std::uint8_t> edges(std::size_t(cw) * std::size_t(ch), 0);
    const auto link = [&](int x0, int y0, int dir) {
        const int x1 = x0 + kDx[dir], y1 = y0 + kDy[dir];
        edges[corner(x0, y0)] |= std::uint8_t(1u << dir);
        edges[corner(x1, y1)] |= std::uint8_t(1u << ((dir + 2) % 4));
    };
    const auto seamBetween = [&](int x0, int y0, int x1, int y1) {
        // (Kept pixels are few: tested first.)
        return (kept[index(x0, y0)] || kept[index(x1, y1)]) && !inked[index(x0, y0)] &&
               !inked[index(x1, y1)] && p.face(x1, y1) == p.face(x0, y0) &&
               p.fill(x1, y1) != p.fill(x0, y0);
    };
    bool any = false;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (x + 1 < w && seamBetween(x, y, x + 1, y)) {
                link(x + 1, y, 1); // the corner edge between them, downwards
                any = true;
            }
            if (y + 1 < h && seamBetween(x, y, x, y + 1)) {
                link(x, y + 1, 0); // rightwards
                any = true;
            }
        }
    if (!any)
        return {};
    // The face of the pixels either side of the edge from corner (x, y) in direction `dir`.
    const auto faceBeside = [&](int x, int y, int dir) {
        const int px = dir == 2 ? x - 1 : x, py = dir == 3 ? y - 1 : y;
        return p.face(std::clamp(px, 0, w - 1), std::clamp(py, 0, h - 1));
    };
    // (A table: without a popcount instruction in the target, std::popcount is a call.)
    constexpr std::uint8_t kBitsIn[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
    std::vector<std::uint8_t> degreeOf(edges.size());
    for (std::size_t i = 0; i < edges.size(); ++i)
        degreeOf[i] = kBitsIn[edges[i] & 15u];
    std::vector<SeamChain> chains;
    const auto walk = [&](int x, int y, int dir) {
        SeamChain chain;
        chain.face = faceBeside(x, y, dir);
        chain.points.emplace_back(x, y);
        const int startX = x, startY = y;
        while (true) {
            edges[corner(x, y)] &= std::uint8_t(~(1u << dir));
            x += kDx[dir];
            y += kDy[dir];
            edges[corner(x, y)] &= std::uint8_t(~(1u << ((dir + 2) % 4)));
            chain.points.emplace_back(x, y);
            const std::uint8_t left = edges[corner(x, y)];
            if (left == 0 || (x == startX && y == startY))
                break;
            if (degreeOf[corner(x, y)] == 2)
                dir = std::countr_zero(unsigned(left));
            else if (!(left & (1u << dir))) // straight on, or stop
                break;
        }
        chain.ring = chain.points.size() > 2 && chain.points.front() == chain.points.back();
        chains.push_back(std::move(chain));
    };
    for (int pass = 0; pass < 3; ++pass)
        for (int y = 0; y < ch; ++y)
            for (int x = 0; x < cw; ++x) {
                const std::size_t c = corner(x, y);
                // Line ends first, then corners where lines meet, then rings.
                const bool start = pass == 0   ? degreeOf[c] == 1
                                   : pass == 1 ? degreeOf[c] >= 3
                                               : true;
                while (start && edges[c] != 0)
                    walk(x, y, std::countr_zero(unsigned(edges[c])));
            }
    const QTransform toCanvas = p.faces.toPixels.inverted();
    std::size_t total = 0;
    for (SeamChain &chain : chains) {
        chain.points = straightened(chain.points, kSeamStraighten);
        for (QPointF &q : chain.points)
            q = toCanvas.map(q);
        total += chain.points.size();
    }
    if (total > kSeamMostPoints)
        return {};
    return chains;
}

// The segments of the bounding lines of `baked` (boundingLine; their middles).
std::vector<QLineF> inkSegments(const std::vector<Stroke> &baked, bool closersToo)
{
    std::vector<QLineF> out;
    for (const Stroke &s : baked)
        if (boundingLine(s, closersToo))
            for (std::size_t k = 0; k + 1 < s.data->points.size(); ++k)
                out.emplace_back(QPointF(s.data->points[k].x, s.data->points[k].y),
                                 QPointF(s.data->points[k + 1].x, s.data->points[k + 1].y));
    return out;
}

// The chains as lines of no ink, each end put onto the nearest edge of its face, the nearest
// inked line (outside every face, or everywhere with `endOnInk`) or the nearest other
// chain, a hair past it, so that the regions join it: the pixel edges stop short of what they
// meet by up to a pixel of the pictures.
std::vector<Stroke> placedSeams(const std::vector<SeamChain> &chains, const BakedOwners &baking,
                                const std::vector<QLineF> &inkLines, bool endOnInk, double scale,
                                double penWidth, const std::function<Id()> &newId)
{
    const ObjectRegions &regions = *baking.regions;
    const double reach = 2.0 / scale + 0.5 * penWidth + 1.0;
    std::vector<std::vector<QLineF>> faceEdges(std::size_t(regions.faceCount()));
    const auto edgesOf = [&](int face) -> const std::vector<QLineF> & {
        std::vector<QLineF> &out = faceEdges[std::size_t(face)];
        if (out.empty())
            for (const QPolygonF &ring : regions.restPath(face).toSubpathPolygons())
                for (qsizetype k = 0; k + 1 < ring.size(); ++k)
                    out.emplace_back(ring[k], ring[k + 1]);
        return out;
    };
    const auto onto = [&](QPointF end, std::size_t self, int face) -> std::optional<QPointF> {
        double best = reach;
        std::optional<QPointF> out;
        const auto consider = [&](const QLineF &line) {
            const auto [t, distance] = join_detail::project(end, line.p1(), line.p2());
            if (distance < best) {
                best = distance;
                out = line.pointAt(t);
            }
        };
        if (face >= 0 && face < regions.faceCount())
            for (const QLineF &line : edgesOf(face))
                consider(line);
        if (face < 0 || endOnInk)
            for (const QLineF &line : inkLines)
                consider(line);
        for (std::size_t i = 0; i < chains.size(); ++i)
            if (i != self)
                for (std::size_t k = 0; k + 1 < chains[i].points.size(); ++k)
                    consider(QLineF(chains[i].points[k], chains[i].points[k + 1]));
        if (out && best > 0.0)
            *out += (*out - end) * (kSeamHairPast / best);
        return out;
    };
    std::vector<Stroke> out;
    for (std::size_t i = 0; i < chains.size(); ++i) {
        std::vector<QPointF> points = chains[i].points;
        if (points.size() < 2)
            continue;
        if (!chains[i].ring) {
            // An end already past its face's edge (a pixel corner lies either side of it)
            // stays; outside every face, an end stops at a line's inked edge and goes on to
            // its middle.
            const int face = chains[i].face;
            const auto inside = [&](QPointF q) {
                return face < 0 ||
                       (face < regions.faceCount() && regions.restPath(face).contains(q));
            };
            if (inside(points.front()))
                if (const auto first = onto(points.front(), i, face))
                    points.insert(points.begin(), *first);
            if (inside(points.back()))
                if (const auto last = onto(points.back(), i, face))
                    points.push_back(*last);
        }
        out.push_back({newId(), lineOfNoInk(points, penWidth)});
    }
    return out;
}

} // namespace

ShownColourSeams shownColourSeams(const StrokeGroup &group, const std::vector<Stroke> &baked,
                                  double closeGap, const std::function<Id()> &newId,
                                  double widerThanPen)
{
    return shownColourSeams(ShownPose(group, closeGap), baked, newId, widerThanPen);
}

ShownColourSeams shownColourSeams(const ShownPose &pose, const std::vector<Stroke> &baked,
                                  const std::function<Id()> &newId, double widerThanPen)
{
    ShownColourSeams result;
    const StrokeGroup &group = pose.group();
    if (group.fills.empty() || !group.isDeformed())
        return result;
    const BakedOwners baking = bakedOwners(pose, baked);
    result.bakedAgreement = agreement(pose, baking, baked);
    const FacesAndFills &p = baking.pictures;
    const int w = p.width, h = p.height;
    if (w <= 0 || h <= 0)
        return result;
    const double scale = p.faces.toPixels.m11(); // picture px per canvas px
    if (!(scale > 0.0))
        return result;
    const double penWidth = medianInkWidth(baked);
    const SeamParts parts = seamParts(baking, scale, penWidth, widerThanPen);
    if (!parts.any)
        return result;
    // The pixels the lines cover, drawn at their width. Outside every face, a part's edge
    // along an inked line needs no seam in any variant (the line bounds it once the seams
    // close its gaps); inside a face only the variant that leaves the lines out skips it, and
    // it leaves out the gap closers too (a seam along one would make slivers just the same).
    std::vector<char> inkedOutside = inkedPixels(pose, baked, p);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (p.face(x, y) >= 0)
                inkedOutside[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 0;
    const std::vector<SeamChain> chains = seamChains(p, parts.kept, inkedOutside);
    const std::vector<SeamChain> offInk =
        seamChains(p, parts.kept, inkMask(baked, true, p.faces, w, h));
    result.seams =
        placedSeams(chains, baking, inkSegments(baked, false), false, scale, penWidth, newId);
    const auto samePoints = [](const SeamChain &a, const SeamChain &b) {
        return a.points == b.points;
    };
    if (!std::equal(chains.begin(), chains.end(), offInk.begin(), offInk.end(), samePoints))
        result.seamsOffInk =
            placedSeams(offInk, baking, inkSegments(baked, true), true, scale, penWidth, newId);
    if (parts.outside) {
        // Outside every face, where only a third of the pen's ink covers no edge: across the
        // ink of two lines that overlap without their middles meeting.
        std::vector<char> thinOutside = inkMask(baked, false, p.faces, w, h, kThinInkShare);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (p.face(x, y) >= 0)
                    thinOutside[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 0;
        const std::vector<SeamChain> across = seamChains(p, parts.kept, thinOutside);
        if (!std::equal(chains.begin(), chains.end(), across.begin(), across.end(), samePoints))
            result.seamsAcrossInk = placedSeams(across, baking, inkSegments(baked, false), false,
                                                scale, penWidth, newId);
    }
    if (!result.seams.empty() || !result.seamsOffInk.empty() || !result.seamsAcrossInk.empty())
        for (const geometry::GapClosure &closure : baking.regions->regions().closures) {
            if (!closure.from.allFinite() || !closure.to.allFinite() || closure.from == closure.to)
                continue;
            result.keptClosures.push_back(
                {newId(), lineOfNoInk({QPointF(closure.from.x(), closure.from.y()),
                                       QPointF(closure.to.x(), closure.to.y())},
                                      penWidth)});
        }
    return result;
}

} // namespace finbook::model
