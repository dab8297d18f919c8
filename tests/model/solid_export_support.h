// Shared by the 3D model export tests (OBJ, glTF): a generated frame whose objects cover every
// case (filled, unfilled, posed, hidden, a dot, a line, empty) and the checks a closed solid
// must pass, written against plain index triples so each test reads its own format.
#pragma once

#include "../geometry/closed_surface.h"
#include "export_support.h"
#include "fill_support.h"

#include <finbook/model/deform_setup.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/picture/picture_commands.h>
#include <finbook/model/picture/picture_object.h>

#include <QFile>
#include <QPainter>

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace finbook::test {

inline constexpr QRgb kBlue = 0xff2040e0;
inline constexpr QRgb kRed = 0xffe03020;
inline constexpr QRgb kGreen = 0xff20a040;
inline const QPointF kShift(300, 50); // where the pins move the posed object

inline QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

inline model::StrokeDataPtr circleStroke(QPointF centre, double radius, QRgb color)
{
    QPolygonF ring;
    for (int i = 0; i <= 48; ++i)
        ring << centre + radius * QPointF(std::cos(i * M_PI / 24), std::sin(i * M_PI / 24));
    return testing::polylineStroke(ring, 4.0, 3.0f, color);
}

inline model::Id addObject(model::Document &doc, const QString &name)
{
    auto *add = new model::AddObjectCommand(&doc, doc.frameAt(0).id,
                                            int(doc.frameAt(0).groups.size()), name);
    doc.undoStack()->push(add);
    return add->groupId();
}

// One frame, back to front:
//   "Body": a square with a smaller square inside, the inner one filled red (first fill), the
//           ring around it blue (larger): exported blue;
//   "Left arm": a green circle without fills: exported in its stroke colour, green;
//   "Body" again: a black circle posed by pins kShift away: exported where it shows;
//   "Hidden": a circle in a hidden object; "Dot": one point; "Line": a straight line;
//   "Empty": no stroke.
inline model::ExportSource generatedSource(model::Id *posed = nullptr)
{
    model::Document doc;
    const model::Id body = testing::squareDocument(doc, QRectF(100, 100, 200, 200));
    doc.undoStack()->push(new model::RenameObjectCommand(&doc, body, QStringLiteral("Body")));
    doc.undoStack()->push(new model::AddStrokeCommand(
        &doc, body, testing::polylineStroke(testing::squareCorners(QRectF(150, 150, 60, 60)))));
    doc.undoStack()->push(model::fillRegionCommand(&doc, body, QPointF(180, 180), kRed).release());
    doc.undoStack()->push(model::fillRegionCommand(&doc, body, QPointF(120, 250), kBlue).release());

    const model::Id arm = addObject(doc, QStringLiteral("Left arm"));
    doc.undoStack()->push(
        new model::AddStrokeCommand(&doc, arm, circleStroke(QPointF(500, 200), 60, kGreen)));

    const model::Id moved = addObject(doc, QStringLiteral("Body"));
    doc.undoStack()->push(
        new model::AddStrokeCommand(&doc, moved, circleStroke(QPointF(200, 500), 50, 0xff000000)));
    model::Rig rig;
    rig.pins = {{1, QPointF(150, 450), QPointF(150, 450) + kShift},
                {2, QPointF(250, 550), QPointF(250, 550) + kShift}};
    doc.setRig(moved, rig);
    model::DeformJob job;
    job.groupId = moved;
    job.key = model::MeshKey::of(*doc.group(moved), -1.0);
    job.rig = rig.atRest();
    if (const auto setup = model::buildDeformSetup(job))
        if (const auto pose = model::solvePose(**setup, *doc.group(moved)))
            doc.setDeformed(moved, pose->strokes);
    if (posed)
        *posed = moved;

    const model::Id hidden = addObject(doc, QStringLiteral("Hidden"));
    doc.undoStack()->push(
        new model::AddStrokeCommand(&doc, hidden, circleStroke(QPointF(700, 500), 40, kRed)));
    doc.undoStack()->push(
        new model::SetObjectFlagCommand(&doc, hidden, model::ObjectFlag::Visible, false));

    const model::Id dot = addObject(doc, QStringLiteral("Dot"));
    auto point = std::make_shared<model::StrokeData>();
    point->points = {{600.0f, 600.0f, 1.0f}};
    doc.undoStack()->push(new model::AddStrokeCommand(&doc, dot, point));
    const model::Id line = addObject(doc, QStringLiteral("Line"));
    doc.undoStack()->push(new model::AddStrokeCommand(
        &doc, line, testing::polylineStroke({QPointF(400, 650), QPointF(700, 640)})));
    addObject(doc, QStringLiteral("Empty"));

    model::DocumentSettings s = doc.settings();
    s.canvasSize = QSize(800, 700);
    return model::ExportSource{doc.frames(), s};
}

// A painted picture, transparent around a soft-edged rounded body striped in two colours.
inline QImage paintedBody()
{
    QImage image(180, 140, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing, true);
    QPainterPath body;
    body.addRoundedRect(QRectF(6, 6, 168, 128), 40, 40);
    p.setClipPath(body);
    for (int x = 0; x < 180; x += 10)
        p.fillRect(QRectF(x, 0, 5, 140), x % 20 ? QColor(230, 120, 30) : QColor(40, 60, 200));
    return image;
}

// One frame holding one picture object, "Painted", its right end lifted 40 px by pins (the
// document's own solve); `object` gets its id.
inline model::ExportSource pictureSource(model::Id *object = nullptr)
{
    model::Document doc;
    doc.undoStack()->push(new model::InsertFrameCommand(&doc, 0));
    auto made = model::makePictureObject(
        model::PictureLayer{QStringLiteral("Painted"), paintedBody(), {}}, QPointF(200, 150));
    if (!made)
        qFatal("%s", qPrintable(made.error()));
    std::vector<model::StrokeGroup> objects{*made};
    auto *import = new model::ImportPictureCommand(&doc, doc.frameAt(0).id, -1, std::move(objects));
    doc.undoStack()->push(import);
    const model::Id id = import->objectIds().front();
    model::Rig rig;
    rig.pins = {{doc.allocateId(), QPointF(220, 220), QPointF(220, 220)},
                {doc.allocateId(), QPointF(360, 220), QPointF(360, 180)}};
    doc.setRig(id, rig);
    model::DeformJob job;
    job.groupId = id;
    job.key = model::MeshKey::of(*doc.group(id), -1.0);
    job.rig = rig.atRest();
    if (const auto setup = model::buildDeformSetup(job))
        if (const auto pose = model::solvePose(**setup, *doc.group(id)))
            doc.setDeformed(id, pose->strokes);
    if (object)
        *object = id;
    model::DocumentSettings s = doc.settings();
    s.canvasSize = QSize(640, 480);
    return model::ExportSource{doc.frames(), s};
}

} // namespace finbook::test
