// Numbers from anywhere: 1e30 coordinates, zero-length strokes (no point, one point, one spot
// repeated), huge and hairline widths, NaN and infinity where they can still come from. They
// never reach the screen as NaN and never crash a deformer: every rig kind either refuses the
// drawing with a sentence or gives a finite pose.
#include "tst_file_sample.h"

#include <finbook/model/deform_setup.h>
#include <finbook/model/render.h>

#include <limits>

using namespace finbook::model;
using namespace file_test;

namespace {
StrokeDataPtr strokeOf(std::vector<StrokePoint> points, float width = 3.0f)
{
    auto data = std::make_shared<StrokeData>();
    data->points = std::move(points);
    data->width = width;
    return data;
}

// An object with a plain stroke plus the hostile ones.
StrokeGroup hostileObject(const std::vector<StrokeDataPtr> &hostile)
{
    StrokeGroup g;
    g.id = 1;
    Id next = 100;
    g.strokes.push_back(
        {next++, strokeOf({{100, 100, 1}, {160, 110, 1}, {150, 180, 1}, {95, 170, 1}}, 6)});
    for (const StrokeDataPtr &s : hostile)
        g.strokes.push_back({next++, s});
    return g;
}

Rig rigOf(RigKind kind)
{
    Rig rig;
    switch (kind) {
    case RigKind::Pins:
        rig.pins = {{1, QPointF(100, 100), QPointF(110, 95)},
                    {2, QPointF(150, 180), QPointF(150, 180)}};
        break;
    case RigKind::Cage:
        rig.cage.rest = {{80, 80}, {180, 80}, {180, 200}, {80, 200}};
        rig.cage.posed = {{85, 80}, {190, 70}, {180, 210}, {80, 200}};
        break;
    case RigKind::Skeleton:
        rig.skeleton.joints = {{110, 110}, {140, 150}};
        rig.skeleton.parent = {-1, 0};
        rig.skeleton.radius = {5, 5};
        rig.skeleton.root = 0;
        rig.skeleton.angles = {0.0, 0.3};
        break;
    case RigKind::None:
        break;
    }
    return rig;
}

bool allFinite(const Pose &pose)
{
    if (!pose.vertices.allFinite())
        return false;
    if (pose.strokes)
        for (const auto &stroke : pose.strokes->strokes)
            for (const StrokePoint &p : stroke)
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.pressure))
                    return false;
    return true;
}
} // namespace

class TestHostileNumbers : public QObject {
    Q_OBJECT
private slots:
    void deformersNeverCrash_data();
    void deformersNeverCrash();
    void renderingShowsNoNaN();
    void fileRefusesNonFiniteAndZeroWidth();
};

void TestHostileNumbers::deformersNeverCrash_data()
{
    QTest::addColumn<std::vector<StrokeDataPtr>>("hostile");
    const float big = 1e30f;
    QTest::newRow("1e30 coordinates")
        << std::vector<StrokeDataPtr>{strokeOf({{big, big, 1}, {-big, big, 1}, {0, -big, 1}})};
    QTest::newRow("1e30 beside the drawing")
        << std::vector<StrokeDataPtr>{strokeOf({{120, 120, 1}, {120, big, 1}})};
    QTest::newRow("empty stroke") << std::vector<StrokeDataPtr>{strokeOf({})};
    QTest::newRow("one point") << std::vector<StrokeDataPtr>{strokeOf({{130, 130, 0.5f}})};
    QTest::newRow("one spot repeated")
        << std::vector<StrokeDataPtr>{strokeOf({{130, 130, 1}, {130, 130, 1}, {130, 130, 1}})};
    QTest::newRow("hairline and huge widths")
        << std::vector<StrokeDataPtr>{strokeOf({{110, 120, 1}, {140, 125, 1}}, 1e-30f),
                                      strokeOf({{110, 140, 1}, {140, 145, 1}}, 1e30f)};
    QTest::newRow("zero pressure")
        << std::vector<StrokeDataPtr>{strokeOf({{110, 120, 0}, {140, 125, 0}, {150, 150, 0}})};
}

void TestHostileNumbers::deformersNeverCrash()
{
    QFETCH(std::vector<StrokeDataPtr>, hostile);
    for (RigKind kind : {RigKind::Pins, RigKind::Cage, RigKind::Skeleton}) {
        StrokeGroup g = hostileObject(hostile);
        g.rig = rigOf(kind);
        DeformJob job;
        job.groupId = g.id;
        job.key = MeshKey::of(g, -1.0);
        job.rig = g.rig.atRest();
        const auto setup = buildDeformSetup(job);
        if (!setup) {
            QVERIFY2(!setup.error().isEmpty(), "a refusal says why");
            continue;
        }
        const auto pose = solvePose(**setup, g);
        if (!pose) {
            QVERIFY(!pose.error().isEmpty());
            continue;
        }
        QVERIFY2(allFinite(*pose), qPrintable(QStringLiteral("rig kind %1").arg(int(kind))));
    }
}

void TestHostileNumbers::renderingShowsNoNaN()
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    Frame frame;
    frame.id = 1;
    frame.groups.push_back(hostileObject({strokeOf({{1e30f, 5, 1}, {5, 5, 1}}),
                                          strokeOf({{nan, 5, 1}, {5, nan, nan}, {inf, 1, 1}}),
                                          strokeOf({}), strokeOf({{50, 50, 1}}, 1e30f)}));
    DocumentSettings settings;
    settings.canvasSize = QSize(200, 200);
    const QImage image = renderFrame(frame, settings, QSize(200, 200));
    QCOMPARE(image.size(), QSize(200, 200));
    // The 1e30-wide dot (drawn as wide as a file may hold) covers the canvas: every pixel is
    // ink, none is garbage.
    QCOMPARE(image.pixelColor(0, 0), QColor(Qt::black));
    QCOMPARE(image.pixelColor(199, 199), QColor(Qt::black));
    // A line as wide as a file allows is drawn that wide (QPen would draw 1 pixel for 32768).
    Frame wide;
    wide.id = 2;
    wide.groups.push_back(hostileObject({strokeOf({{-50, 100, 1}, {250, 100, 1}}, 1e30f)}));
    wide.groups[0].strokes.erase(wide.groups[0].strokes.begin()); // only the wide line
    const QImage line = renderFrame(wide, settings, QSize(200, 200));
    QCOMPARE(line.pixelColor(100, 0), QColor(Qt::black));
    QCOMPARE(line.pixelColor(100, 199), QColor(Qt::black));
}

void TestHostileNumbers::fileRefusesNonFiniteAndZeroWidth()
{
    for (float width : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(),
                        std::numeric_limits<float>::infinity(), 1e30f, kMaxStrokeWidth * 2}) {
        Document doc;
        Frame frame;
        frame.id = 1;
        frame.groups.push_back(hostileObject({strokeOf({{1, 1, 1}, {2, 2, 1}}, width)}));
        doc.reset({frame}, DocumentSettings(), 1000);
        QString message;
        QCOMPARE(errorOf(serializeFinbook(doc), &message), FileErrorCode::BadValue);
        QVERIFY2(message.contains(QLatin1String("width")), qPrintable(message));
    }
}

QTEST_GUILESS_MAIN(TestHostileNumbers)
#include "tst_hostile_numbers.moc"
