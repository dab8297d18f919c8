// Small .finbook files that ask for a lot of work: the kinds an attacker (or an unlucky
// download) hands to the thumbnailer and the 3D exports. Shared by tst_limits and
// `finbook-bench thumbnail`, which craft them afresh each run.
#pragma once

#include <finbook/model/finbook_file.h>
#include <finbook/model/types.h>

#include <QPolygonF>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace crafted {

using namespace finbook;

// A straight pen line from `a` to `b` with `points` samples (at least 2).
inline model::StrokeDataPtr line(QPointF a, QPointF b, int points = 2, float width = 3.0f)
{
    auto data = std::make_shared<model::StrokeData>();
    data->width = width;
    data->color = qRgb(20, 20, 30);
    for (int k = 0; k < points; ++k) {
        const QPointF p = a + (b - a) * (double(k) / (points - 1));
        data->points.push_back({float(p.x()), float(p.y()), 1.0f});
    }
    return data;
}

// A closed circle of `points` samples.
inline model::StrokeDataPtr circle(QPointF centre, double radius, int points = 64)
{
    auto data = std::make_shared<model::StrokeData>();
    data->width = 3.0f;
    data->color = qRgb(20, 20, 30);
    for (int k = 0; k <= points; ++k) {
        const double t = 2.0 * std::numbers::pi * k / points;
        data->points.push_back({float(centre.x() + radius * std::cos(t)),
                                float(centre.y() + radius * std::sin(t)), 1.0f});
    }
    return data;
}

// One object: `lines` horizontal and `lines` vertical lines across the whole canvas, every
// cell filled (shaded with `ramp`), at mesh density `density` — a few kilobytes asking for a
// shading mesh per cell.
inline QByteArray shadedGrid(int lines, QSize canvas, double density,
                             model::ShadeRamp ramp = model::ShadeRamp::ThreeTones)
{
    model::Frame frame;
    frame.id = 1;
    model::StrokeGroup group;
    group.id = 2;
    group.name = QStringLiteral("grid");
    group.meshDensity = density;
    model::Id id = 3;
    const double w = canvas.width(), h = canvas.height();
    std::vector<model::Id> rows, columns;
    for (int i = 0; i < lines; ++i) {
        const double y = h * (i + 0.5) / lines, x = w * (i + 0.5) / lines;
        rows.push_back(id);
        group.strokes.push_back({id++, line({-4.0, y}, {w + 4.0, y})});
        columns.push_back(id);
        group.strokes.push_back({id++, line({x, -4.0}, {x, h + 4.0})});
    }
    for (int r = 0; r + 1 < lines; ++r)
        for (int c = 0; c + 1 < lines; ++c) {
            model::Fill fill;
            fill.color = qRgb(60 + 7 * r % 190, 120, 60 + 11 * c % 190);
            fill.seed = QPointF(w * (c + 1.0) / lines, h * (r + 1.0) / lines);
            fill.strokes = {rows[std::size_t(r)], columns[std::size_t(c)], rows[std::size_t(r) + 1],
                            columns[std::size_t(c) + 1]};
            std::sort(fill.strokes.begin(), fill.strokes.end());
            fill.shading.ramp = ramp;
            group.fills.push_back(fill);
        }
    frame.groups.push_back(std::move(group));
    model::DocumentSettings settings;
    settings.canvasSize = canvas;
    return model::serializeFinbook({frame}, settings);
}

// One frame (id 1) of one object (id 2, `name`) of one stroke (id 3) through `corners`.
inline model::Frame polygonFrame(const QString &name, const std::vector<QPointF> &corners)
{
    model::Frame frame;
    frame.id = 1;
    model::StrokeGroup group;
    group.id = 2;
    group.name = name;
    auto data = std::make_shared<model::StrokeData>();
    data->width = 3.0f;
    for (const QPointF &p : corners)
        data->points.push_back({float(p.x()), float(p.y()), 1.0f});
    group.strokes.push_back({3, data});
    frame.groups.push_back(std::move(group));
    return frame;
}

// `count` fills on one square (each a later coat of the same region).
inline QByteArray manyFills(int count)
{
    model::Frame frame = polygonFrame(QStringLiteral("square"),
                                      {QPointF(100, 100), QPointF(400, 100), QPointF(400, 400),
                                       QPointF(100, 400), QPointF(100, 100)});
    model::StrokeGroup &group = frame.groups.front();
    for (int i = 0; i < count; ++i) {
        model::Fill fill;
        fill.color = qRgb(i % 256, 90, 200);
        fill.seed = QPointF(250 + i % 97, 250 + i % 89);
        fill.strokes = {3};
        group.fills.push_back(fill);
    }
    return model::serializeFinbook({frame}, model::DocumentSettings{});
}

// `objects` objects all holding the one circle stroke data (the file stores it once), each
// filled, at mesh density `density`; `distinct`: each object its own circle, slightly smaller
// than the last (every object a separate stroke to mesh).
inline QByteArray repeatedCircles(int objects, double density, bool distinct = false)
{
    model::Frame frame;
    frame.id = 1;
    model::Id id = 2;
    const model::StrokeDataPtr shared = circle({640, 360}, 300);
    for (int i = 0; i < objects; ++i) {
        model::StrokeGroup group;
        group.id = id++;
        group.name = QStringLiteral("circle %1").arg(i);
        group.meshDensity = density;
        const model::Id stroke = id++;
        group.strokes.push_back(
            {stroke,
             distinct ? circle({640, 360}, 300.0 - 250.0 * i / std::max(1, objects)) : shared});
        model::Fill fill;
        fill.color = qRgb(200, 80 + i % 150, 60);
        fill.seed = QPointF(640, 360);
        fill.strokes = {stroke};
        group.fills.push_back(fill);
        frame.groups.push_back(std::move(group));
    }
    return model::serializeFinbook({frame}, model::DocumentSettings{});
}

} // namespace crafted
