// Shaded fills (shade/fill_shading.h, shade/shade_commands.h): one undo step each, a disc lit
// from the left is bright on its left and shadowed on its right in every renderer, the tones
// follow a pose while the light stays on screen, onion skin stays flat, SVG gets tone paths,
// and the file keeps the shading and the light.
#include "../../model/src/export/export_formats.h"
#include "fill_support.h"

#include <finbook/model/deform_setup.h>
#include <finbook/model/export/export_plan.h>
#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_render.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/inbetween/inbetween_commands.h>
#include <finbook/model/shade/fill_shading.h>
#include <finbook/model/shade/same_object.h>
#include <finbook/model/shade/shade_commands.h>

#include <QTest>

#include <cmath>

using namespace finbook::model;
using finbook::testing::polylineStroke;

namespace {

constexpr QRgb kRed = 0xffe03020;
const QPointF kCentre(200, 200);
constexpr double kRadius = 100.0;

void push(Document &doc, std::unique_ptr<QUndoCommand> command)
{
    QVERIFY(command);
    doc.undoStack()->push(command.release());
}

// A document whose one object is a circle outline (one closed stroke), filled red.
Id discDocument(Document &doc)
{
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    const Id g = doc.frameAt(0).groups.at(0).id;
    QPolygonF circle;
    for (int i = 0; i <= 96; ++i)
        circle << kCentre +
                      kRadius * QPointF(std::cos(2 * M_PI * i / 96), std::sin(2 * M_PI * i / 96));
    doc.undoStack()->push(new AddStrokeCommand(&doc, g, polylineStroke(circle)));
    push(doc, fillRegionCommand(&doc, g, kCentre, kRed));
    DocumentSettings settings = doc.settings();
    settings.canvasSize = QSize(400, 400);
    doc.undoStack()->push(new ChangeSettingsCommand(&doc, settings));
    doc.undoStack()->clear();
    return g;
}

// The area-weighted centre of a tone's path (its pieces are triangles and quads).
QPointF centreOf(const QPainterPath &path)
{
    double area = 0.0;
    QPointF sum;
    for (const QPolygonF &ring : path.toSubpathPolygons()) {
        for (qsizetype i = 1; i + 1 < ring.size(); ++i) {
            const QPointF a = ring[0], b = ring[i], c = ring[i + 1];
            const double w =
                0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
            area += w;
            sum += w * (a + b + c) / 3.0;
        }
    }
    return area != 0.0 ? sum / area : QPointF();
}

int brightness(QRgb c)
{
    return qRed(c) + qGreen(c) + qBlue(c);
}

} // namespace

class TestFillShading : public QObject {
    Q_OBJECT
private slots:
    void shadingIsOneUndoStep();
    void shadingAppliesToTheObjectInEveryFrame();
    void framesMadeLaterShowTheShading();
    void sameNamesPairInOrder();
    void lightIsOneUndoStepAndSanitized();
    void newFillsAreShadedAsTheObjectsOthers();
    void discLitFromTheLeftIsBrighterOnItsLeft();
    void toneEdgesAreSmoothCurves();
    void everyRampAndRimGivesTones();
    void tonesFollowThePoseLightStaysOnScreen();
    void tonesStayInsideTheFillWhenPosed();
    void armOverTheBodyIsShadedAsTheArm();
    void onionSkinStaysFlat();
    void svgWritesToneRegionsNotRaster();
    void fileKeepsShadingAndLight();
    void fileWithoutShadingOpensFlat();
};

void TestFillShading::shadingIsOneUndoStep()
{
    Document doc;
    const Id g = discDocument(doc);
    const std::vector<Fill> before = doc.group(g)->fills;
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::ThreeTones, true}));
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.group(g)->fills[0].shading.ramp, ShadeRamp::ThreeTones);
    QVERIFY(doc.group(g)->fills[0].shading.rim);
    QVERIFY(!shadeFillsCommand(&doc, g, {ShadeRamp::ThreeTones, true})); // unchanged
    doc.undoStack()->undo();
    QCOMPARE(doc.group(g)->fills, before);
    doc.undoStack()->redo();
    QCOMPARE(doc.group(g)->fills[0].shading, (FillShading{ShadeRamp::ThreeTones, true}));
    QVERIFY(!shadeFillsCommand(&doc, 999999, {ShadeRamp::TwoTones, false})); // no such object
    // Recolouring keeps the shading.
    push(doc, fillRegionCommand(&doc, g, kCentre, 0xff2040e0));
    QCOMPARE(doc.group(g)->fills[0].shading.ramp, ShadeRamp::ThreeTones);
}

// Issue 45, item 4: a character shaded on frame 3 of 5 is shaded on all five, as one step; an
// object of another name stays flat; undo gives every frame back exactly; the file keeps it.
void TestFillShading::shadingAppliesToTheObjectInEveryFrame()
{
    Document doc;
    const Id g = discDocument(doc);
    for (int i = 1; i < 5; ++i)
        doc.undoStack()->push(new DuplicateFrameCommand(&doc, doc.frameAt(0).id, i));
    // Another object on frame 2, filled, and a frame-5 namesake that has no fill yet.
    auto *other = new AddObjectCommand(&doc, doc.frameAt(1).id, -1, QStringLiteral("Sun"));
    const Id sun = other->groupId();
    doc.undoStack()->push(other);
    QPolygonF square{QPointF(320, 20), QPointF(380, 20), QPointF(380, 80), QPointF(320, 80),
                     QPointF(320, 20)};
    doc.undoStack()->push(new AddStrokeCommand(&doc, sun, polylineStroke(square)));
    push(doc, fillRegionCommand(&doc, sun, QPointF(350, 50), 0xfff0d020));
    doc.undoStack()->clear();
    QCOMPARE(doc.frameCount(), 5);
    const std::vector<Frame> before = doc.frames();
    const QByteArray beforeBytes = serializeFinbook(doc);

    const Id onFrame3 = doc.frameAt(2).groups.at(0).id;
    QCOMPARE(sameObjectInFrames(doc, onFrame3).size(), std::size_t(5));
    QCOMPARE(sameObjectInFrames(doc, sun), std::vector<Id>{sun});
    push(doc, shadeFillsCommand(&doc, onFrame3, {ShadeRamp::ThreeTones, false}));
    QCOMPARE(doc.undoStack()->count(), 1);
    const FillShading three{ShadeRamp::ThreeTones, false};
    for (int i = 0; i < 5; ++i) {
        const StrokeGroup &disc = doc.frameAt(i).groups.at(0);
        QCOMPARE(disc.fills.size(), std::size_t(1));
        QCOMPARE(disc.fills[0].shading, three);
        // Every frame draws the tones, not only the one it was set on.
        QVERIFY(!fillList(disc, doc.settings()).at(0).tones.empty());
    }
    QCOMPARE(doc.group(sun)->fills.at(0).shading, FillShading());
    QVERIFY(!shadeFillsCommand(&doc, g, three)); // already so everywhere

    doc.undoStack()->undo();
    for (int i = 0; i < 5; ++i)
        QCOMPARE(doc.frameAt(i).groups.at(0).fills, before[std::size_t(i)].groups.at(0).fills);
    QCOMPARE(serializeFinbook(doc), beforeBytes);
    doc.undoStack()->redo();

    // Saved and opened again, every frame is still shaded.
    auto loaded = readFinbook(serializeFinbook(doc));
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->frames.size(), std::size_t(5));
    for (const Frame &frame : loaded->frames)
        QCOMPARE(frame.groups.at(0).fills.at(0).shading, three);
}

// Frames duplicated or in-betweened after the shading show it, and a frame where the object is
// filled for the first time takes the object's shading rather than starting flat.
void TestFillShading::framesMadeLaterShowTheShading()
{
    Document doc;
    const Id g = discDocument(doc);
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, doc.frameAt(0).id, 1));
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::TwoTones, true}));
    const FillShading two{ShadeRamp::TwoTones, true};
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, doc.frameAt(1).id, 2));
    QCOMPARE(doc.frameAt(2).groups.at(0).fills.at(0).shading, two);
    auto *between = new InsertInbetweensCommand(&doc, doc.frameAt(0).id, doc.frameAt(1).id, 2, {});
    QVERIFY(!between->isObsolete());
    doc.undoStack()->push(between);
    QCOMPARE(doc.frameCount(), 5);
    for (int i = 0; i < 5; ++i)
        QCOMPARE(doc.frameAt(i).groups.at(0).fills.at(0).shading, two);

    // A new frame: its default object "Object" is the disc's namesake; drawn and filled there,
    // it is shaded as the disc is.
    doc.undoStack()->push(new InsertFrameCommand(&doc, 5));
    const Id fresh = doc.frameAt(5).groups.at(0).id;
    QCOMPARE(doc.group(fresh)->name, doc.group(g)->name);
    QPolygonF circle;
    for (int i = 0; i <= 48; ++i)
        circle << kCentre +
                      80.0 * QPointF(std::cos(2 * M_PI * i / 48), std::sin(2 * M_PI * i / 48));
    doc.undoStack()->push(new AddStrokeCommand(&doc, fresh, polylineStroke(circle)));
    push(doc, fillRegionCommand(&doc, fresh, kCentre, kRed));
    QCOMPARE(doc.group(fresh)->fills.at(0).shading, two);
}

// Two objects of one name in a frame pair with the two of that name in another, in order.
void TestFillShading::sameNamesPairInOrder()
{
    Document doc;
    discDocument(doc);
    const Id frame = doc.frameAt(0).id;
    const QString name = doc.frameAt(0).groups.at(0).name;
    auto *second = new AddObjectCommand(&doc, frame, -1, name);
    doc.undoStack()->push(second);
    auto *third = new AddObjectCommand(&doc, frame, -1, QStringLiteral("Other"));
    doc.undoStack()->push(third);
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, frame, 1));
    const Frame &copy = doc.frameAt(1);
    QCOMPARE(sameObjectInFrames(doc, second->groupId()),
             (std::vector<Id>{second->groupId(), copy.groups.at(1).id}));
    QCOMPARE(sameObjectInFrames(doc, copy.groups.at(0).id),
             (std::vector<Id>{doc.frameAt(0).groups.at(0).id, copy.groups.at(0).id}));
    QCOMPARE(sameObjectInFrames(doc, third->groupId()),
             (std::vector<Id>{third->groupId(), copy.groups.at(2).id}));
    QVERIFY(sameObjectInFrames(doc, 999999).empty());
}

void TestFillShading::lightIsOneUndoStepAndSanitized()
{
    Document doc;
    discDocument(doc);
    push(doc, setLightCommand(&doc, 180.0, 30.0));
    QCOMPARE(doc.settings().lightAzimuth, 180.0);
    QCOMPARE(doc.settings().lightElevation, 30.0);
    push(doc, setLightCommand(&doc, -90.0, 200.0));
    QCOMPARE(doc.settings().lightAzimuth, 270.0);
    QCOMPARE(doc.settings().lightElevation, 90.0);
    push(doc, setLightCommand(&doc, std::nan(""), std::nan("")));
    QCOMPARE(doc.settings().lightAzimuth, DocumentSettings().lightAzimuth);
    QVERIFY(
        !setLightCommand(&doc, DocumentSettings().lightAzimuth, DocumentSettings().lightElevation));
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(doc.settings().lightAzimuth, 180.0);
    doc.undoStack()->undo();
    QCOMPARE(doc.settings().lightAzimuth, DocumentSettings().lightAzimuth);
}

void TestFillShading::newFillsAreShadedAsTheObjectsOthers()
{
    Document doc;
    const Id g = discDocument(doc);
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::Smooth, true}));
    // A second, separate outline in the same object: filling it shades it the same way.
    QPolygonF square{QPointF(320, 20), QPointF(380, 20), QPointF(380, 80), QPointF(320, 80),
                     QPointF(320, 20)};
    doc.undoStack()->push(new AddStrokeCommand(&doc, g, polylineStroke(square)));
    push(doc, fillRegionCommand(&doc, g, QPointF(350, 50), 0xff2040e0));
    QCOMPARE(doc.group(g)->fills.size(), std::size_t(2));
    QCOMPARE(doc.group(g)->fills[1].shading, (FillShading{ShadeRamp::Smooth, true}));
}

void TestFillShading::discLitFromTheLeftIsBrighterOnItsLeft()
{
    Document doc;
    const Id g = discDocument(doc);
    push(doc, setLightCommand(&doc, 180.0, 30.0));
    const QImage flat = renderFrame(doc.frameAt(0), doc.settings(), QSize(400, 400));
    QCOMPARE(flat.pixel(130, 200), kRed);
    QCOMPARE(flat.pixel(270, 200), kRed);
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::TwoTones, false}));
    const QImage shaded = renderFrame(doc.frameAt(0), doc.settings(), QSize(400, 400));
    QCOMPARE(shaded.pixel(130, 200), kRed);             // lit side: the fill's own colour
    QCOMPARE(shaded.pixel(270, 200), shadowTone(kRed)); // far side: the shadow
    QVERIFY(brightness(shaded.pixel(130, 200)) > brightness(shaded.pixel(270, 200)));
    QCOMPARE(shaded.pixel(200, 200), kRed);
    // Undo: flat again, pixel for pixel.
    doc.undoStack()->undo();
    QCOMPARE(renderFrame(doc.frameAt(0), doc.settings(), QSize(400, 400)), flat);
}

// Issue 45, item 5: on a round head the tones' edges are smooth curves, not a sawtooth. Along
// each tone's edge inside the disc (away from where it meets the outline), the edge turns one
// way: of the turns between consecutive edges larger than 1°, few turn against their
// neighbour (a sawtooth alternates at every mesh edge it crosses).
void TestFillShading::toneEdgesAreSmoothCurves()
{
    Document doc;
    const Id g = discDocument(doc);
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::ThreeTones, false}));
    const std::vector<FillItem> items = fillList(*doc.group(g), doc.settings());
    QCOMPARE(items.size(), std::size_t(1));
    QCOMPARE(items[0].tones.size(), std::size_t(2));
    int turns = 0, flips = 0;
    double length = 0.0;
    for (const ToneItem &tone : items[0].tones)
        for (const QPolygonF &ring : tone.path.toSubpathPolygons()) {
            QPolygonF inside; // consecutive points well inside the disc
            const auto flush = [&] {
                int last = 0;
                for (qsizetype i = 1; i + 1 < inside.size(); ++i) {
                    const QPointF u = inside[i] - inside[i - 1], v = inside[i + 1] - inside[i];
                    const double turn =
                        std::atan2(u.x() * v.y() - u.y() * v.x(), u.x() * v.x() + u.y() * v.y()) *
                        180.0 / M_PI;
                    if (std::abs(turn) <= 1.0)
                        continue;
                    const int sign = turn > 0 ? 1 : -1;
                    ++turns;
                    flips += last != 0 && sign != last ? 1 : 0;
                    last = sign;
                }
                for (qsizetype i = 1; i < inside.size(); ++i)
                    length += QLineF(inside[i - 1], inside[i]).length();
                inside.clear();
            };
            for (const QPointF &p : ring) {
                if (QLineF(p, kCentre).length() < kRadius - 10.0)
                    inside << p;
                else
                    flush();
            }
            flush();
        }
    qInfo("tone edges: %.0f px inside, %d turns over 1°, %d against the one before", length, turns,
          flips);
    QVERIFY(length > 200.0);
    // 6 of 101 now; 14 of 101 with three smoothing steps, as before.
    QVERIFY(turns > 20);
    QVERIFY2(flips * 10 <= turns, qPrintable(QStringLiteral("%1 of %2").arg(flips).arg(turns)));
}

void TestFillShading::everyRampAndRimGivesTones()
{
    Document doc;
    const Id g = discDocument(doc);
    const auto tones = [&] { return fillList(*doc.group(g), doc.settings()).at(0).tones; };
    QVERIFY(tones().empty());
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::TwoTones, false}));
    QCOMPARE(tones().size(), std::size_t(1));
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::ThreeTones, false}));
    QCOMPARE(tones().size(), std::size_t(2));
    QCOMPARE(tones()[1].color, highlightTone(kRed));
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::Smooth, true}));
    QVERIFY(tones().size() >= std::size_t(kSmoothLevels - 2));
    QCOMPARE(tones().back().color, rimTone(kRed));
    QCOMPARE(fillList(*doc.group(g), doc.settings()).at(0).color, shadowTone(kRed));
    // The highlight faces the light (upper left by default), the rim is across from it.
    const QPointF rim = centreOf(tones().back().path) - kCentre;
    QVERIFY(rim.x() > 20 && rim.y() > 20);
}

void TestFillShading::tonesFollowThePoseLightStaysOnScreen()
{
    Document doc;
    const Id g = discDocument(doc);
    push(doc, setLightCommand(&doc, 180.0, 30.0));
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::TwoTones, false}));
    const QPointF restShadow = centreOf(fillList(*doc.group(g), doc.settings())[0].tones[0].path);
    QVERIFY(restShadow.x() > kCentre.x() + 30); // across from the light
    // A cage turns the disc half a turn about its centre and moves it: the shadow stays on the
    // side away from the light (right), moved with the disc.
    Rig rig;
    rig.cage.rest = {{80, 80}, {320, 80}, {320, 320}, {80, 320}};
    const QPointF by(-40, 30);
    for (const QPointF &p : rig.cage.rest)
        rig.cage.posed.push_back(2 * kCentre - p + by);
    doc.setRig(g, rig);
    DeformJob job;
    job.groupId = g;
    job.key = MeshKey::of(*doc.group(g), -1.0);
    job.rig = rig.atRest();
    const auto setup = buildDeformSetup(job);
    QVERIFY(setup);
    const auto solved = solvePose(**setup, *doc.group(g));
    QVERIFY(solved);
    doc.setDeformed(g, solved->strokes);
    const QPointF posedShadow = centreOf(fillList(*doc.group(g), doc.settings())[0].tones[0].path);
    qInfo("shadow centre at rest (%.1f, %.1f), turned half a turn and moved (%.1f, %.1f)",
          restShadow.x(), restShadow.y(), posedShadow.x(), posedShadow.y());
    QVERIFY(std::abs((posedShadow - by - restShadow).x()) < 3.0);
    QVERIFY(std::abs((posedShadow - by - restShadow).y()) < 3.0);
}

void TestFillShading::tonesStayInsideTheFillWhenPosed()
{
    // A cage squashes the disc unevenly (one corner pulled in): the shading mesh and the fill's
    // outline are posed by different maps, yet no tone shows past the fill.
    Document doc;
    const Id g = discDocument(doc);
    push(doc, setLightCommand(&doc, 180.0, 30.0));
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::ThreeTones, true}));
    Rig rig;
    rig.cage.rest = {{80, 80}, {320, 80}, {320, 320}, {80, 320}};
    rig.cage.posed = {{140, 80}, {260, 80}, {330, 330}, {70, 330}};
    doc.setRig(g, rig);
    DeformJob job;
    job.groupId = g;
    job.key = MeshKey::of(*doc.group(g), -1.0);
    job.rig = rig.atRest();
    const auto setup = buildDeformSetup(job);
    QVERIFY(setup);
    const auto solved = solvePose(**setup, *doc.group(g));
    QVERIFY(solved);
    doc.setDeformed(g, solved->strokes);
    const std::vector<FillItem> items = fillList(*doc.group(g), doc.settings());
    QCOMPARE(items.size(), std::size_t(1));
    QVERIFY(items[0].tones.size() >= 3);
    // Sampled every px: a tone point outside the fill would show past its outline.
    int inTones = 0, outside = 0;
    for (int y = 60; y < 340; ++y)
        for (int x = 40; x < 340; ++x) {
            const QPointF p(x + 0.5, y + 0.5);
            for (const ToneItem &tone : items[0].tones)
                if (tone.path.contains(p)) {
                    ++inTones;
                    if (!items[0].path.contains(p))
                        ++outside;
                }
        }
    qInfo("posed disc: %d tone samples, %d outside the fill", inTones, outside);
    QVERIFY(inTones > 1000);
    QCOMPARE(outside, 0);
}

void TestFillShading::armOverTheBodyIsShadedAsTheArm()
{
    // A body (disc, r 100) and an arm drawn over it (disc, r 60, 110 px right), filled in two
    // colours, lit from the left. Just inside the body's right edge, on the arm, the arm's
    // dome faces left (lit); the body's, or the lens-shaped piece inflated alone, face right
    // (in shadow).
    Document doc;
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    const Id g = doc.frameAt(0).groups.at(0).id;
    const auto disc = [](QPointF centre, double radius) {
        QPolygonF ring;
        for (int i = 0; i <= 120; ++i)
            ring << centre + radius * QPointF(std::cos(2 * M_PI * i / 120),
                                              std::sin(2 * M_PI * i / 120));
        return ring;
    };
    const QPointF body(150, 200), arm(260, 200);
    doc.undoStack()->push(new AddStrokeCommand(&doc, g, polylineStroke(disc(body, 100))));
    doc.undoStack()->push(new AddStrokeCommand(&doc, g, polylineStroke(disc(arm, 60))));
    DocumentSettings settings = doc.settings();
    settings.canvasSize = QSize(400, 400);
    settings.closeGap = 0.0;
    doc.undoStack()->push(new ChangeSettingsCommand(&doc, settings));
    push(doc, fillRegionCommand(&doc, g, body - QPointF(50, 0), kRed));
    push(doc, fillRegionCommand(&doc, g, arm + QPointF(30, 0), 0xff3060e0));
    push(doc, fillRegionCommand(&doc, g, QPointF(240, 200), 0xff3060e0));
    push(doc, setLightCommand(&doc, 180.0, 30.0));
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::TwoTones, false}));
    const std::vector<FillItem> items = fillList(*doc.group(g), doc.settings());
    QVERIFY(items.size() >= 2);
    const auto shaded = [&](QPointF p) {
        for (const FillItem &item : items)
            for (const ToneItem &tone : item.tones)
                if (tone.path.contains(p))
                    return true;
        return false;
    };
    QVERIFY(!shaded(QPointF(245, 200))); // on the arm over the body, near the body's edge
    QVERIFY(shaded(QPointF(315, 200)));  // the arm's own right side
    QVERIFY(shaded(QPointF(210, 150)));  // the body right of its middle, beside the arm
}

void TestFillShading::onionSkinStaysFlat()
{
    Document doc;
    const Id g = discDocument(doc);
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::ThreeTones, true}));
    RenderOptions onion;
    onion.tint = QColor(0, 200, 0);
    const auto items = fillList(*doc.group(g), doc.settings(), onion);
    QCOMPARE(items.size(), std::size_t(1));
    QVERIFY(items[0].tones.empty());
}

void TestFillShading::svgWritesToneRegionsNotRaster()
{
    Document doc;
    const Id g = discDocument(doc);
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::ThreeTones, false}));
    ExportPlan plan;
    plan.background = doc.settings().background;
    const QByteArray svg = frameSvg(doc.frameAt(0), doc.settings(), plan);
    QCOMPARE(svg.count("class=\"tone\""), 2);
    QVERIFY(!svg.contains("<image"));
    QVERIFY(svg.contains(QColor::fromRgb(shadowTone(kRed)).name().toLatin1()));
    // A few polygons per tone, not one per mesh triangle.
    const qsizetype start = svg.indexOf("class=\"tone\"");
    const qsizetype end = svg.indexOf("/>", start);
    QVERIFY(svg.mid(start, end - start).count('M') <= 4);
}

void TestFillShading::fileKeepsShadingAndLight()
{
    Document doc;
    const Id g = discDocument(doc);
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::Smooth, true}));
    push(doc, setLightCommand(&doc, 200.0, 20.0));
    const QByteArray bytes = serializeFinbook(doc);
    QVERIFY(bytes.contains("shad") && bytes.contains("lite"));
    auto loaded = readFinbook(bytes);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->formatVersion, kFinbookFormatVersion);
    QCOMPARE(loaded->settings.lightAzimuth, 200.0);
    QCOMPARE(loaded->settings.lightElevation, 20.0);
    QCOMPARE(loaded->frames.at(0).groups.at(0).fills, doc.group(g)->fills);
    Document reopened;
    adoptLoadedDocument(reopened, std::move(*loaded));
    QCOMPARE(serializeFinbook(reopened), bytes);
}

void TestFillShading::fileWithoutShadingOpensFlat()
{
    // Flat fills and the default light write neither the chunk nor the section: files that
    // do not use shading are the bytes they were.
    Document doc;
    const Id g = discDocument(doc);
    const QByteArray flat = serializeFinbook(doc);
    QVERIFY(!flat.contains("shad") && !flat.contains("lite"));
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::TwoTones, false}));
    push(doc, shadeFillsCommand(&doc, g, {ShadeRamp::Off, false}));
    QCOMPARE(serializeFinbook(doc), flat);
}

QTEST_MAIN(TestFillShading)
#include "tst_fill_shading.moc"
