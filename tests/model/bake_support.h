// What you see is what you keep (issue 45): pictures of an object as the app draws it, and how
// much of two such pictures agrees; the real drawings of ../shared/data as filled documents and
// their automatic skeletons' bends. Shared by tst_pose_bake and finbook-bench bake.
#pragma once

#include <finbook/model/commands.h>
#include <finbook/model/deform_setup.h>
#include <finbook/model/document.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_render.h>
#include <finbook/model/render.h>
#include <finbook/model/skeleton/skeleton_commands.h>

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLineF>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <vector>

namespace finbook::testing {

constexpr int kColourTolerance = 8;      // per channel, of 255
constexpr float kDrawingPenWidth = 3.0f; // readDrawing's lines are drawn this wide

// Poses object g with `rig` as the deform service would: precompute, solve (converged), store.
// Returns an empty string, or the error.
inline QString poseObject(model::Document &doc, model::Id g, const model::Rig &rig)
{
    doc.setRig(g, rig);
    model::DeformJob job;
    job.groupId = g;
    job.key = model::MeshKey::of(*doc.group(g), doc.settings().closeGap);
    job.rig = rig.atRest();
    const auto setup = model::buildDeformSetup(job);
    if (!setup)
        return setup.error();
    const auto solved = model::solvePose(**setup, *doc.group(g));
    if (!solved)
        return solved.error();
    doc.setDeformed(g, solved->strokes);
    return {};
}

// The bounds of the object's points as shown (posed where it is posed).
inline QRectF shownBounds(const model::StrokeGroup &group)
{
    QRectF r;
    for (std::size_t s = 0; s < group.strokes.size(); ++s)
        for (const model::StrokePoint &p : model::displayedPoints(group, s))
            r = r.united(QRectF(p.x, p.y, 0.01, 0.01));
    return r;
}

// A transform showing `box` in a square picture of `side` px.
inline QTransform pictureView(const QRectF &box, int side)
{
    const double scale = (side - 20) / std::max(1.0, std::max(box.width(), box.height()));
    QTransform t;
    t.translate(10, 10);
    t.scale(scale, scale);
    t.translate(-box.left(), -box.top());
    return t;
}

// Frame `frame` as the app paints it (fills under strokes, a cut-out's layers), or with
// `fillsOnly` its fills alone in black without antialiasing (for the filled area).
inline QImage framePicture(const model::Document &doc, int frame, const QTransform &t, int side,
                           bool fillsOnly = false)
{
    QImage image(side, side, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setTransform(t);
    if (!fillsOnly) {
        painter.setRenderHint(QPainter::Antialiasing);
        model::paintFrame(painter, doc.frameAt(frame), doc.settings());
        return image;
    }
    painter.setPen(Qt::NoPen);
    for (const model::StrokeGroup &group : doc.frameAt(frame).groups)
        for (const model::PaintLayer &layer : model::paintLayers(group, doc.settings()))
            for (const model::FillItem &fill : layer.fills)
                painter.fillPath(fill.path, Qt::black);
    return image;
}

inline bool sameColour(QRgb a, QRgb b)
{
    return std::abs(qRed(a) - qRed(b)) <= kColourTolerance &&
           std::abs(qGreen(a) - qGreen(b)) <= kColourTolerance &&
           std::abs(qBlue(a) - qBlue(b)) <= kColourTolerance;
}

// Whether pixel (x, y) lies on a colour edge of `image`: a neighbour differs from it.
inline bool onColourEdge(const QImage &image, int x, int y)
{
    const QRgb c = image.pixel(x, y);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u >= 0 && v >= 0 && u < image.width() && v < image.height() &&
                !sameColour(image.pixel(u, v), c))
                return true;
        }
    return false;
}

struct PictureAgreement {
    double agreePct = 100.0; // of the drawing's pixels
    long long drawing = 0;   // pixels compared: not background in either, not a rim in both
    QImage difference;       // grey where they agree, red where they differ
};

// How much of two pictures of one drawing agrees: the drawing's pixels (not white in either)
// whose colours agree within kColourTolerance per channel, leaving out the anti-aliased rim (a
// pixel on a colour edge in both pictures). `ignore`, when given, marks pixels not to compare
// (non-zero alpha).
inline PictureAgreement comparePictures(const QImage &a, const QImage &b,
                                        const QImage *ignore = nullptr)
{
    PictureAgreement out;
    out.difference = QImage(a.size(), QImage::Format_RGB32);
    out.difference.fill(Qt::white);
    long long agree = 0;
    const QRgb white = qRgb(255, 255, 255);
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            if (sameColour(p, white) && sameColour(q, white))
                continue;
            if (ignore && qAlpha(ignore->pixel(x, y)) > 0)
                continue;
            if (onColourEdge(a, x, y) && onColourEdge(b, x, y))
                continue;
            ++out.drawing;
            const bool same = sameColour(p, q);
            agree += same;
            out.difference.setPixel(x, y, same ? qRgb(220, 220, 220) : qRgb(230, 0, 0));
        }
    out.agreePct = out.drawing > 0 ? 100.0 * double(agree) / double(out.drawing) : 100.0;
    return out;
}

// Pixels painted dark (a fillsOnly picture's fills).
inline long long darkPixels(const QImage &image)
{
    long long n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            n += qRed(image.pixel(x, y)) < 128;
    return n;
}

// A colour of its own for fill i (hues apart, never white or grey).
inline QRgb distinctColour(std::size_t i)
{
    return QColor::fromHsv(int(i * 137 % 360), 150 + int(i * 53 % 100), 190 + int(i * 29 % 60))
        .rgba();
}

// A Quick, Draw! drawing ("strokes") or a shape's outline ("contours"), shared/data/README.md.
inline std::vector<std::vector<QPointF>> readDrawing(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot open");
        return {};
    }
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    std::vector<std::vector<QPointF>> lines;
    const auto points = [](const QJsonArray &array) {
        std::vector<QPointF> out;
        for (const QJsonValue &p : array)
            out.emplace_back(p.toArray().at(0).toDouble(), p.toArray().at(1).toDouble());
        return out;
    };
    if (json.contains(QStringLiteral("strokes"))) {
        for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray())
            lines.push_back(points(stroke.toArray()));
    } else if (json.contains(QStringLiteral("contours"))) {
        for (const QJsonValue &contour : json.value(QStringLiteral("contours")).toArray()) {
            std::vector<QPointF> ring = points(contour.toArray());
            if (!ring.empty())
                ring.push_back(ring.front());
            lines.push_back(std::move(ring));
        }
    } else {
        *error = QStringLiteral("neither strokes nor contours");
    }
    return lines;
}

// A line drawn as the bench draws them: pen kDrawingPenWidth, full pressure.
inline std::shared_ptr<model::StrokeData> drawnLine(const std::vector<QPointF> &line)
{
    auto data = std::make_shared<model::StrokeData>();
    data->width = kDrawingPenWidth;
    for (const QPointF &p : line)
        data->points.push_back({float(p.x()), float(p.y()), 1.0f});
    return data;
}

// A document of one frame whose one object holds the drawing, every region filled, each fill
// in its own colour. Returns the object's id (kNoId when nothing could be drawn). Pen 3 px, as the
// bench draws them.
inline model::Id drawingDocument(model::Document &doc,
                                 const std::vector<std::vector<QPointF>> &lines)
{
    doc.undoStack()->push(new model::InsertFrameCommand(&doc, 0));
    const model::Id g = doc.frameAt(0).groups.at(0).id;
    for (const std::vector<QPointF> &line : lines) {
        if (line.size() >= 2)
            doc.undoStack()->push(new model::AddStrokeCommand(&doc, g, drawnLine(line)));
    }
    if (auto all = model::fillAllRegionsCommand(&doc, g, 0xff808080))
        doc.undoStack()->push(all.release());
    std::vector<model::Fill> fills = doc.group(g)->fills;
    for (std::size_t i = 0; i < fills.size(); ++i)
        fills[i].color = distinctColour(i);
    if (!fills.empty())
        doc.undoStack()->push(new model::SetFillsCommand(&doc, g, fills, QStringLiteral("Colour")));
    return g;
}

// The automatic skeleton, each limb turned ±`degrees` where it leaves the body (a joint flagged as
// a limb base; without any, each bone from the root).
inline model::Rig skeletonBend(const model::StrokeGroup &group, double closeGap,
                               model::SkinningMode mode, double degrees = 60.0)
{
    model::Rig rig;
    const auto built = model::buildSkeletonRig(group, {}, std::nullopt, closeGap);
    if (!built || built->jointCount() < 2)
        return rig;
    rig.skeleton = *built;
    rig.skeleton.mode = mode;
    rig.skeleton.angles.assign(std::size_t(built->jointCount()), 0.0);
    bool anyBase = false;
    for (int j = 0; j < built->jointCount(); ++j)
        anyBase = anyBase || built->isLimbBase(j);
    int sign = 1;
    for (int j = 0; j < built->jointCount(); ++j) {
        const int parent = built->parent[std::size_t(j)];
        const bool turns = anyBase ? parent >= 0 && built->isLimbBase(parent)
                                   : parent >= 0 && parent == built->root;
        if (!turns)
            continue;
        rig.skeleton.angles[std::size_t(j)] = sign * degrees * std::numbers::pi / 180.0;
        sign = -sign;
    }
    return rig;
}

// Each joint along a limb past its base (an elbow) turned by `radians` (rigs of skeletonBend).
inline void bendElbows(model::Rig &rig, double radians)
{
    model::SkeletonRig &skeleton = rig.skeleton;
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        const int parent = skeleton.parent[std::size_t(j)];
        if (parent >= 0 && parent != skeleton.root && !skeleton.isLimbBase(parent))
            skeleton.angles[std::size_t(j)] = radians;
    }
}

// Every elbow as posed (a joint along a limb past its base, with the bone to one child), and a
// line across the limb there: square to the mean of its two bones, `half` px each side.
struct ElbowRub {
    int elbow = -1;
    QPointF at;
    QLineF across;
};
inline std::vector<ElbowRub> elbowRubs(const model::SkeletonRig &skeleton, double half)
{
    std::vector<ElbowRub> out;
    const std::vector<QPointF> joints = skeleton.posedJoints();
    const auto unit = [](QPointF d) { return d / std::hypot(d.x(), d.y()); };
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        const int parent = skeleton.parent[std::size_t(j)];
        if (parent < 0 || parent == skeleton.root || skeleton.isLimbBase(parent))
            continue;
        const QPointF at = joints[std::size_t(parent)];
        const QPointF along =
            unit(unit(at - joints[std::size_t(skeleton.parent[std::size_t(parent)])]) +
                 unit(joints[std::size_t(j)] - at));
        const QPointF across(-along.y() * half, along.x() * half);
        out.push_back({parent, at, QLineF(at - across, at + across)});
    }
    return out;
}

} // namespace finbook::testing
