// Shared by the Lottie export tests: drawings that exercise what Lottie makes hard (widths that
// follow the pressure, fills with holes, holds, poses, layers and a camera), and the comparison
// of a player's frame with Finbook's own.
#pragma once

#include "export_support.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/scene/shot.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>

#include <cmath>
#include <memory>

namespace finbook::test {

// Share of pixels where every channel (premultiplied, so what is transparent agrees whatever its
// colour) is within `tolerance` of the other picture's.
inline double agreement(const QImage &a, const QImage &b, int tolerance = 24)
{
    if (a.size() != b.size() || a.isNull())
        return 0.0;
    const QImage x = a.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    const QImage y = b.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    qint64 agree = 0;
    for (int row = 0; row < x.height(); ++row) {
        const auto *p = reinterpret_cast<const QRgb *>(x.constScanLine(row));
        const auto *q = reinterpret_cast<const QRgb *>(y.constScanLine(row));
        for (int col = 0; col < x.width(); ++col)
            agree += std::abs(qRed(p[col]) - qRed(q[col])) <= tolerance &&
                     std::abs(qGreen(p[col]) - qGreen(q[col])) <= tolerance &&
                     std::abs(qBlue(p[col]) - qBlue(q[col])) <= tolerance &&
                     std::abs(qAlpha(p[col]) - qAlpha(q[col])) <= tolerance;
    }
    return double(agree) / (double(x.width()) * x.height());
}

// Share of the pixels that are not background (some channel > 24 away from it) in either picture
// that agree: the agreement of the drawing itself, not of the empty page around it.
inline double inkAgreement(const QImage &a, const QImage &b, QRgb background, int tolerance = 24)
{
    const QImage x = a.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    const QImage y = b.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    const QRgb bg = qPremultiply(background);
    const auto far = [&](QRgb c, QRgb d) {
        return std::abs(qRed(c) - qRed(d)) > tolerance ||
               std::abs(qGreen(c) - qGreen(d)) > tolerance ||
               std::abs(qBlue(c) - qBlue(d)) > tolerance ||
               std::abs(qAlpha(c) - qAlpha(d)) > tolerance;
    };
    qint64 ink = 0, agree = 0;
    for (int row = 0; row < x.height(); ++row) {
        const auto *p = reinterpret_cast<const QRgb *>(x.constScanLine(row));
        const auto *q = reinterpret_cast<const QRgb *>(y.constScanLine(row));
        for (int col = 0; col < x.width(); ++col) {
            if (!far(p[col], bg) && !far(q[col], bg))
                continue;
            ++ink;
            agree += !far(p[col], q[col]);
        }
    }
    return ink == 0 ? 1.0 : double(agree) / double(ink);
}

// How much ink a picture holds: the sum over its pixels of how far each is from `background`
// (premultiplied, the largest channel difference, 0..1). Thin lines that two rasterizers
// anti-alias differently still hold about the same ink.
inline double inkOf(const QImage &image, QRgb background)
{
    const QImage x = image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    const QRgb bg = qPremultiply(background);
    double ink = 0;
    for (int row = 0; row < x.height(); ++row) {
        const auto *p = reinterpret_cast<const QRgb *>(x.constScanLine(row));
        for (int col = 0; col < x.width(); ++col)
            ink +=
                std::max({std::abs(qRed(p[col]) - qRed(bg)), std::abs(qGreen(p[col]) - qGreen(bg)),
                          std::abs(qBlue(p[col]) - qBlue(bg)),
                          std::abs(qAlpha(p[col]) - qAlpha(bg))}) /
                255.0;
    }
    return ink;
}

inline model::StrokeDataPtr strokeOf(const std::vector<QPointF> &points,
                                     const std::vector<float> &pressure, float width, QRgb color)
{
    auto data = std::make_shared<model::StrokeData>();
    data->width = width;
    data->color = color;
    for (std::size_t i = 0; i < points.size(); ++i)
        data->points.push_back({float(points[i].x()), float(points[i].y()),
                                pressure.empty() ? 1.0f : pressure[i % pressure.size()]});
    return data;
}

// A 400×300 page of strokes Lottie cannot draw with its own strokes: a pressure swell from a
// hair to 24 px, a loop (its hole must stay open), a zigzag of sharp turns, a tight spiral
// wider than its curvature, a lone dot, a translucent stroke over another.
inline model::Frame pressureStrokes()
{
    model::Frame frame;
    frame.id = 1;
    model::StrokeGroup g;
    g.id = 10;
    model::Id id = 100;
    const auto add = [&](model::StrokeDataPtr data) { g.strokes.push_back({++id, data}); };
    std::vector<QPointF> swell;
    std::vector<float> pressure;
    for (int i = 0; i <= 60; ++i) {
        swell.emplace_back(30 + i * 5, 40 + 15 * std::sin(i * 0.15));
        pressure.push_back(float(0.05 + 0.95 * std::sin(M_PI * i / 60.0)));
    }
    add(strokeOf(swell, pressure, 24.0f, 0xff202020));
    std::vector<QPointF> loop;
    for (int i = 0; i <= 72; ++i)
        loop.emplace_back(90 + 45 * std::cos(i * M_PI / 36), 150 + 45 * std::sin(i * M_PI / 36));
    add(strokeOf(loop, {}, 10.0f, 0xff1040a0));
    std::vector<QPointF> zigzag;
    for (int i = 0; i <= 8; ++i)
        zigzag.emplace_back(170 + i * 14, i % 2 ? 110 : 190);
    add(strokeOf(zigzag, {}, 6.0f, 0xffa02010));
    std::vector<QPointF> spiral;
    for (int i = 0; i <= 120; ++i) {
        const double t = i * 0.12, r = 4 + 2.2 * t;
        spiral.emplace_back(330 + r * std::cos(t), 150 + r * std::sin(t));
    }
    add(strokeOf(spiral, {}, 9.0f, 0xff208040));
    add(strokeOf({QPointF(60, 250)}, {}, 14.0f, 0xff000000));
    add(strokeOf({QPointF(40, 230), QPointF(380, 280)}, {1.0f, 0.4f}, 18.0f, 0x80ff8000));
    frame.groups.push_back(std::move(g));
    return frame;
}

// A ring with a hole, filled, and the hole filled in another colour: fills inside fills.
inline model::Frame nestedFills()
{
    model::Frame frame;
    frame.id = 2;
    model::StrokeGroup g;
    g.id = 20;
    const auto square = [](QRectF r) {
        std::vector<QPointF> p;
        const QPointF c[] = {r.topLeft(), r.topRight(), r.bottomRight(), r.bottomLeft(),
                             r.topLeft()};
        for (int s = 0; s < 4; ++s)
            for (int k = 0; k < 20; ++k)
                p.push_back(c[s] + (c[s + 1] - c[s]) * (k / 20.0));
        p.push_back(c[4]);
        return p;
    };
    g.strokes.push_back({201, strokeOf(square(QRectF(60, 40, 280, 220)), {}, 4.0f, 0xff000000)});
    g.strokes.push_back({202, strokeOf(square(QRectF(140, 100, 120, 100)), {}, 4.0f, 0xff000000)});
    model::Fill ring;
    ring.color = 0xff4080e0;
    ring.seed = QPointF(90, 70);
    model::Fill hole;
    hole.color = 0xfff0c020;
    hole.seed = QPointF(200, 150);
    g.fills = {ring, hole};
    frame.groups.push_back(std::move(g));
    return frame;
}

// A round body and an arm, filled and shaded in three cel tones with a rim light: the fill
// exports as its tone regions.
inline model::Frame shadedBody()
{
    model::Frame frame;
    frame.id = 3;
    model::StrokeGroup g;
    g.id = 30;
    std::vector<QPointF> body;
    for (int i = 0; i <= 90; ++i)
        body.emplace_back(170 + 110 * std::cos(i * M_PI / 45), 150 + 100 * std::sin(i * M_PI / 45));
    g.strokes.push_back({301, strokeOf(body, {}, 4.0f, 0xff202020)});
    model::Fill fill;
    fill.color = 0xffe08040;
    fill.seed = QPointF(170, 150);
    fill.shading.ramp = model::ShadeRamp::ThreeTones;
    fill.shading.rim = true;
    g.fills = {fill};
    frame.groups.push_back(std::move(g));
    return frame;
}

inline model::DocumentSettings smallPage()
{
    model::DocumentSettings s;
    s.canvasSize = QSize(400, 300);
    s.fps = 12;
    return s;
}

// The entry of the plan shown at `tick`.
inline std::size_t entryAt(const model::ExportPlan &plan, qint64 tick)
{
    qint64 start = 0;
    for (std::size_t e = 0; e < plan.frames.size(); ++e) {
        start += plan.holds[e];
        if (tick < start)
            return e;
    }
    return plan.frames.size() - 1;
}

// What Finbook's own export shows at `tick` (PNG export's picture, camera included).
inline QImage finbookFrame(const model::ExportSource &source, const model::ExportPlan &plan,
                           qint64 tick)
{
    const std::size_t e = entryAt(plan, tick);
    return model::renderExportFrame(source.frames[std::size_t(plan.frames[e])], source.settings,
                                    plan, nullptr, {},
                                    e < plan.cameras.size() ? &plan.cameras[e] : nullptr);
}

inline QJsonObject readJson(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

// A cycle of four drawings (the pressure strokes, each a step further) played `times` times.
inline model::ExportSource cycle(int times)
{
    model::ExportSource source;
    source.settings = smallPage();
    for (int t = 0; t < times; ++t)
        for (int i = 0; i < 4; ++i) {
            model::Frame f = pressureStrokes();
            f.id = 80 + i;
            for (model::Stroke &s : f.groups.front().strokes) {
                auto moved = std::make_shared<model::StrokeData>(*s.data);
                for (model::StrokePoint &p : moved->points)
                    p.y += float(6 * i);
                s.data = moved;
            }
            f.groups.front().strokes.pop_back(); // a stroke fewer: no pose, four drawings
            if (i % 2)
                f.groups.front().strokes.pop_back();
            source.frames.push_back(f);
        }
    return source;
}

// A scene of two layers: a still background (a big filled square, at half opacity, deep so
// it drifts) and a walking figure's four drawings; a camera that pushes in and turns.
inline model::ExportSource layeredScene()
{
    model::ExportSource source;
    source.settings = smallPage();
    model::Layer back;
    back.id = 7001;
    back.properties.name = QStringLiteral("Sky");
    back.properties.opacity = 0.5;
    back.properties.depth = 1.0;
    model::Frame sky = nestedFills();
    sky.hold = 8;
    back.cels.push_back(sky);
    model::Layer front;
    front.id = 7002;
    front.properties.name = QStringLiteral("Figure");
    for (int i = 0; i < 4; ++i) {
        model::Frame f = pressureStrokes();
        f.id = 50 + i;
        for (model::Stroke &s : f.groups.front().strokes) {
            auto moved = std::make_shared<model::StrokeData>(*s.data);
            for (model::StrokePoint &p : moved->points)
                p.x += float(12 * i);
            s.data = moved;
        }
        f.hold = 2;
        front.cels.push_back(f);
    }
    const std::vector<model::Layer> layers{back, front};
    source.frames = model::composeShots(layers);
    source.layerNames = {{back.id, back.properties.name}, {front.id, front.properties.name}};
    model::CameraKey k0, k1;
    k0.tick = 0;
    k0.center = QPointF(200, 150);
    k1.tick = 7;
    k1.center = QPointF(230, 140);
    k1.zoom = 1.4;
    k1.rotation = 12;
    source.camera.keys = {k0, k1};
    return source;
}

// A painted picture: a soft-edged disc with a gradient and stripes.
inline QImage paintedDisc()
{
    QImage image(120, 100, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing, true);
    QLinearGradient gradient(0, 0, 120, 100);
    gradient.setColorAt(0, QColor(220, 40, 30));
    gradient.setColorAt(1, QColor(30, 90, 220));
    p.setBrush(gradient);
    p.setPen(Qt::NoPen);
    p.drawEllipse(QRectF(4, 4, 112, 92));
    p.setPen(QPen(QColor(250, 240, 60), 5));
    for (int x = 10; x < 120; x += 20)
        p.drawLine(QPointF(x, 10), QPointF(x + 10, 90));
    return image;
}

// The picture object at `at`, bent by `amount` px (its vertices pushed along slow waves) as a
// pose, or at rest for 0.
inline model::StrokeGroup bentPicture(model::Id id, QPointF at, double amount)
{
    auto made = model::makePictureObject(
        model::PictureLayer{QStringLiteral("painted"), paintedDisc(), {}}, at);
    if (!made)
        qFatal("%s", qPrintable(made.error()));
    model::StrokeGroup g = *made;
    g.id = id;
    if (amount == 0.0)
        return g;
    g.rig.pins = {{id + 1, at, at}};
    auto pose = std::make_shared<model::DeformedStrokes>();
    const Eigen::MatrixX2d rest = g.picture->restVertices();
    for (Eigen::Index i = 0; i < rest.rows(); ++i)
        pose->pictureVertices.emplace_back(rest(i, 0) + amount * std::sin(rest(i, 1) * 0.05),
                                           rest(i, 1) + amount * std::cos(rest(i, 0) * 0.04));
    g.deformed = pose;
    return g;
}

// Three drawings: a picture that keeps still, one posed anew in each drawing, and a drawn line
// across both over them (the pictures lie under what is drawn after them).
inline model::ExportSource picturesScene()
{
    model::ExportSource source;
    source.settings = smallPage();
    for (int i = 0; i < 3; ++i) {
        model::Frame f;
        f.id = 90 + i;
        f.groups.push_back(bentPicture(1, QPointF(20, 30), 0.0));
        f.groups.push_back(bentPicture(10, QPointF(200, 120), 4.0 * (i + 1)));
        model::StrokeGroup line;
        line.id = 20;
        model::Stroke stroke;
        stroke.id = 21;
        stroke.data = strokeOf({QPointF(30, 80), QPointF(370, 180)}, {}, 8.0f, 0xff000000);
        line.strokes.push_back(stroke);
        f.groups.push_back(line);
        source.frames.push_back(f);
    }
    return source;
}

} // namespace finbook::test
