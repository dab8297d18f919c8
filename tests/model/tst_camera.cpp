// The camera (issue 46): easing against closed forms, interpolation between keys, the shot's
// transform, undoable key edits, the "CAMR" section, and exports through the camera checked by
// pixels (a dot at a known place).
#include "stroke_support.h"

#include <finbook/model/camera/camera_commands.h>
#include <finbook/model/camera/camera_track.h>
#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/frame_list_model.h>

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstring>

using namespace finbook;
using namespace finbook::model;

namespace {

constexpr QSizeF kPage(200, 100);

CameraKey key(qint64 tick, QPointF center, double zoom = 1.0, double rotation = 0.0,
              CameraEasing easing = CameraEasing::Linear)
{
    CameraKey k;
    k.tick = tick;
    k.center = center;
    k.zoom = zoom;
    k.rotation = rotation;
    k.easing = easing;
    return k;
}

// A document with a 200 × 100 page, one frame held `hold` ticks, and a round dot of ink at `at`.
void dotDocument(Document &doc, QPointF at, int hold = 1)
{
    DocumentSettings settings;
    settings.canvasSize = QSize(200, 100);
    doc.reset(std::vector<Frame>{}, settings, 1);
    doc.undoStack()->push(new InsertFrameCommand(&doc, 0));
    const Frame &frame = doc.frameAt(0);
    doc.undoStack()->push(new SetFrameHoldCommand(&doc, frame.id, hold));
    doc.undoStack()->push(new AddStrokeCommand(
        &doc, frame.groups.at(0).id,
        testing::lineStroke(at - QPointF(0.5, 0), at + QPointF(0.5, 0), 2, 8.0f)));
}

} // namespace

class TestCamera : public QObject {
    Q_OBJECT
private slots:
    void easingsFollowTheirClosedForms();
    void bezierEasingFollowsItsCurve();
    void keysInterpolate();
    void restCameraShowsThePage();
    void shotTransformPlacesPoints();
    void keyEditsUndoExactly();
    void invalidKeysAreRefused();
    void fileKeepsTheCamera();
    void damagedCameraIsRefusedOrLeftOut();
    void exportFramesTheShot();
    void exportFollowsAPanDuringAHold();
    void exportWithoutCameraShowsThePage();
    void svgExportFramesTheShot();
    void timelineMarksTheFramesOfKeys();
};

void TestCamera::easingsFollowTheirClosedForms()
{
    CameraKey k;
    for (double t = 0.0; t <= 1.0; t += 0.05) {
        k.easing = CameraEasing::Linear;
        QCOMPARE(easedTime(k, t), t);
        k.easing = CameraEasing::EaseIn;
        QVERIFY(std::abs(easedTime(k, t) - t * t) < 1e-12);
        k.easing = CameraEasing::EaseOut;
        QVERIFY(std::abs(easedTime(k, t) - (1.0 - (1.0 - t) * (1.0 - t))) < 1e-12);
        k.easing = CameraEasing::EaseInOut;
        QVERIFY(std::abs(easedTime(k, t) - (3 * t * t - 2 * t * t * t)) < 1e-12);
        k.easing = CameraEasing::Hold;
        QCOMPARE(easedTime(k, t), t < 1.0 ? 0.0 : 1.0);
    }
    // Out of range and NaN shares are clamped.
    k.easing = CameraEasing::EaseIn;
    QCOMPARE(easedTime(k, -1.0), 0.0);
    QCOMPARE(easedTime(k, 2.0), 1.0);
    QCOMPARE(easedTime(k, std::nan("")), 0.0);
}

void TestCamera::bezierEasingFollowsItsCurve()
{
    CameraKey k;
    k.easing = CameraEasing::Bezier;
    // Control points on the diagonal: the curve is the line y = x.
    k.control1 = QPointF(1.0 / 3.0, 1.0 / 3.0);
    k.control2 = QPointF(2.0 / 3.0, 2.0 / 3.0);
    for (double t = 0.0; t <= 1.0; t += 0.1)
        QVERIFY(std::abs(easedTime(k, t) - t) < 1e-7);
    // CSS's "ease" and a curve that overshoots: points of the curve, found from its own
    // parameter, are where easedTime puts them.
    for (const auto &[c1, c2] : {std::pair{QPointF(0.25, 0.1), QPointF(0.25, 1.0)},
                                 std::pair{QPointF(0.7, -0.5), QPointF(0.3, 1.6)}}) {
        k.control1 = c1;
        k.control2 = c2;
        for (double s = 0.0; s <= 1.0; s += 0.05) {
            const double r = 1.0 - s;
            const double x = 3 * r * r * s * c1.x() + 3 * r * s * s * c2.x() + s * s * s;
            const double y = 3 * r * r * s * c1.y() + 3 * r * s * s * c2.y() + s * s * s;
            QVERIFY2(
                std::abs(easedTime(k, x) - y) < 1e-6,
                qPrintable(QStringLiteral("s %1: %2 vs %3").arg(s).arg(easedTime(k, x)).arg(y)));
        }
    }
}

void TestCamera::keysInterpolate()
{
    CameraTrack track;
    track.keys = {key(10, {0, 0}, 1.0, 0.0), key(20, {100, 50}, 4.0, 90.0),
                  key(30, {100, 50}, 4.0, 90.0, CameraEasing::Hold), key(40, {0, 0})};
    track.keys[2].easing = CameraEasing::Hold;
    // Before the first key and after the last, the camera holds them.
    QCOMPARE(cameraAt(track, 0, kPage).center, QPointF(0, 0));
    QCOMPARE(cameraAt(track, 99, kPage).center, QPointF(0, 0));
    // Halfway (linear): the centre and the turn halfway, the zoom the geometric mean.
    const CameraState mid = cameraAt(track, 15, kPage);
    QVERIFY(std::abs(mid.center.x() - 50) < 1e-9 && std::abs(mid.center.y() - 25) < 1e-9);
    QVERIFY(std::abs(mid.zoom - 2.0) < 1e-9);
    QVERIFY(std::abs(mid.rotation - 45.0) < 1e-9);
    // Each tick zooms by the same factor.
    const double ratio = cameraAt(track, 11, kPage).zoom / cameraAt(track, 10, kPage).zoom;
    for (int t = 11; t < 20; ++t)
        QVERIFY(std::abs(cameraAt(track, t + 1, kPage).zoom / cameraAt(track, t, kPage).zoom -
                         ratio) < 1e-9);
    // A hold stays until the next key, then cuts.
    QCOMPARE(cameraAt(track, 39.9, kPage).center, QPointF(100, 50));
    QCOMPARE(cameraAt(track, 40, kPage).center, QPointF(0, 0));
    // Ease in: a quarter of the time in, a sixteenth of the way.
    track.keys[0].easing = CameraEasing::EaseIn;
    QVERIFY(std::abs(cameraAt(track, 12.5, kPage).center.x() - 100.0 / 16.0) < 1e-9);
    // What moves: between 10 and 20, not during the hold before its cut, again before 40.
    QVERIFY(track.movesBetween(12, 14));
    QVERIFY(!track.movesBetween(21, 29));
    QVERIFY(!track.movesBetween(31, 39));
    QVERIFY(track.movesBetween(31, 40));
    QVERIFY(!track.movesBetween(41, 100));
    QCOMPARE(track.keyAt(20), 1);
    QCOMPARE(track.keyAt(21), -1);
}

void TestCamera::restCameraShowsThePage()
{
    const QTransform t = cameraTransform(restCamera(kPage), kPage);
    QVERIFY(t.isIdentity() ||
            (qFuzzyCompare(t.m11(), 1.0) && qFuzzyIsNull(t.m12()) && qFuzzyIsNull(t.m21()) &&
             qFuzzyCompare(t.m22(), 1.0) && qFuzzyIsNull(t.dx()) && qFuzzyIsNull(t.dy())));
    CameraTrack track;
    QVERIFY(!track.isUsed(kPage));
    track.keys = {key(0, {100, 50})};
    QVERIFY(!track.isUsed(kPage)); // a key at rest frames the page as it is
    track.keys[0].zoom = 1.5;
    QVERIFY(track.isUsed(kPage));
}

void TestCamera::shotTransformPlacesPoints()
{
    // Zoom 2 on (150, 50): that point is the shot's middle, 10 px to its right are 20 px.
    const QTransform t = cameraTransform({QPointF(150, 50), 2.0, 0.0}, kPage);
    QCOMPARE(t.map(QPointF(150, 50)), QPointF(100, 50));
    QCOMPARE(t.map(QPointF(160, 50)), QPointF(120, 50));
    // A camera turned 90° counter-clockwise: the page turns clockwise in the shot, so a point
    // to the right of the centre shows below the middle (y grows downwards).
    const QTransform turned = cameraTransform({QPointF(100, 50), 1.0, 90.0}, kPage);
    const QPointF p = turned.map(QPointF(110, 50));
    QVERIFY(std::abs(p.x() - 100) < 1e-9 && std::abs(p.y() - 60) < 1e-9);
    // The frame on the page is the shot's outline mapped back: zoom 2 shows half the page.
    const QRectF frame = cameraFrame({QPointF(150, 50), 2.0, 0.0}, kPage).boundingRect();
    QVERIFY(std::abs(frame.left() - 100) < 1e-9 && std::abs(frame.width() - 100) < 1e-9);
    QVERIFY(std::abs(frame.top() - 25) < 1e-9 && std::abs(frame.height() - 50) < 1e-9);
}

void TestCamera::keyEditsUndoExactly()
{
    Document doc;
    dotDocument(doc, {50, 50});
    const QByteArray before = serializeFinbook(doc);
    const int start = doc.undoStack()->index();
    QSignalSpy changed(&doc, &Document::cameraChanged);
    auto add = setCameraKeyCommand(&doc, key(0, {60, 40}, 2.0));
    QVERIFY(add);
    QCOMPARE(add->text(), QStringLiteral("Add Camera Key"));
    doc.undoStack()->push(add.release());
    QCOMPARE(doc.camera().keys.size(), std::size_t(1));
    QCOMPARE(changed.count(), 1);
    // A drag at one tick is one undo step.
    const int steps = doc.undoStack()->count();
    for (int i = 1; i <= 5; ++i)
        doc.undoStack()->push(setCameraKeyCommand(&doc, key(0, {60.0 + i, 40}, 2.0), 7).release());
    QCOMPARE(doc.undoStack()->count(), steps + 1);
    QCOMPARE(doc.camera().keys.at(0).center, QPointF(65, 40));
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(12, {10, 10}, 0.5, 30.0)).release());
    doc.undoStack()->push(moveCameraKeyCommand(&doc, 12, 24).release());
    QCOMPARE(doc.camera().keys.at(1).tick, qint64(24));
    QVERIFY(!moveCameraKeyCommand(&doc, 24, 0)); // another key is there
    doc.undoStack()->push(removeCameraKeyCommand(&doc, 0).release());
    QCOMPARE(doc.camera().keys.size(), std::size_t(1));
    const QByteArray after = serializeFinbook(doc);
    const CameraTrack last = doc.camera();
    doc.undoStack()->setIndex(start);
    QVERIFY(doc.camera().isEmpty());
    QCOMPARE(serializeFinbook(doc), before);
    doc.undoStack()->setIndex(doc.undoStack()->count());
    QCOMPARE(doc.camera(), last);
    QCOMPARE(serializeFinbook(doc), after);
}

void TestCamera::invalidKeysAreRefused()
{
    Document doc;
    dotDocument(doc, {50, 50});
    QVERIFY(!setCameraKeyCommand(&doc, key(0, {std::nan(""), 0})));
    QVERIFY(!setCameraKeyCommand(&doc, key(0, {0, 0}, 0.0)));
    QVERIFY(!setCameraKeyCommand(&doc, key(0, {0, 0}, std::numeric_limits<double>::infinity())));
    QVERIFY(!setCameraKeyCommand(&doc, key(-1, {0, 0})));
    QVERIFY(!setCameraKeyCommand(&doc, key(kMaxCameraTick + 1, {0, 0})));
    CameraKey bent = key(0, {0, 0});
    bent.easing = CameraEasing::Bezier;
    bent.control1 = QPointF(1.5, 0); // x outside [0, 1]: the curve would go back in time
    QVERIFY(!setCameraKeyCommand(&doc, bent));
    QVERIFY(!removeCameraKeyCommand(&doc, 3)); // nothing there
    QVERIFY(doc.camera().isEmpty());
}

void TestCamera::fileKeepsTheCamera()
{
    Document doc;
    dotDocument(doc, {50, 50});
    const QByteArray plain = serializeFinbook(doc);
    QVERIFY(!plain.contains("CAMR")); // no camera: the bytes of a file without one
    CameraKey bent = key(30, {-20.5, 1e5}, 0.25, -720.0, CameraEasing::Bezier);
    bent.control1 = QPointF(0.1, -0.4);
    bent.control2 = QPointF(0.9, 1.7);
    for (const CameraKey &k :
         {key(0, {100, 50}), key(12, {120, 40}, 3.0, 15.0, CameraEasing::EaseInOut), bent})
        doc.undoStack()->push(setCameraKeyCommand(&doc, k).release());
    const QByteArray bytes = serializeFinbook(doc);
    auto loaded = readFinbook(bytes);
    QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
    QCOMPARE(loaded->camera, doc.camera());
    Document reopened;
    adoptLoadedDocument(reopened, std::move(*loaded));
    QCOMPARE(reopened.camera(), doc.camera());
    QCOMPARE(serializeFinbook(reopened), bytes);
}

void TestCamera::damagedCameraIsRefusedOrLeftOut()
{
    Document doc;
    dotDocument(doc, {50, 50});
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(0, {100, 50}, 2.0)).release());
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(8, {120, 50}, 2.0)).release());
    const QByteArray bytes = serializeFinbook(doc);
    const qsizetype at = bytes.indexOf("CAMR");
    QVERIFY(at > 0);
    // The first key's zoom (after tag, length, count, tick, x, y) set to −1: the section's
    // checksum no longer matches, and opened anyway the key's value is out of range.
    QByteArray bad = bytes;
    const qsizetype zoom = at + 4 + 8 + 4 + 8 + 8 + 8;
    const double minusOne = -1.0;
    std::memcpy(bad.data() + zoom, &minusOne, 8);
    const auto strict = readFinbook(bad);
    QVERIFY(!strict);
    QVERIFY2(strict.error().code == FileErrorCode::Damaged ||
                 strict.error().code == FileErrorCode::BadValue,
             qPrintable(strict.error().message));
    QStringList problems;
    const auto recovered = recoverFinbook(bad, &problems);
    QVERIFY(recovered);
    // Opened anyway: the drawing and the other key kept, the bad key left out.
    QCOMPARE(recovered->frames.size(), std::size_t(1));
    QCOMPARE(recovered->camera.keys.size(), std::size_t(1));
    QCOMPARE(recovered->camera.keys.at(0).tick, qint64(8));
    QVERIFY(!problems.isEmpty());
    // A count larger than the section can hold is refused before anything is allocated.
    QByteArray huge = bytes;
    const quint32 count = 0x7fffffff;
    std::memcpy(huge.data() + at + 12, &count, 4);
    QVERIFY(!readFinbook(huge));
    problems.clear();
    const auto cut = recoverFinbook(huge, &problems);
    QVERIFY(cut);
    QCOMPARE(cut->frames.size(), std::size_t(1));
    QVERIFY(cut->camera.keys.size() <= 2);
}

void TestCamera::exportFramesTheShot()
{
    QTemporaryDir dir;
    Document doc;
    dotDocument(doc, {150, 50});
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(0, {150, 50}, 2.0)).release());
    ExportOptions options;
    options.target = dir.filePath(QStringLiteral("shot"));
    const auto result = exportAnimation(exportSource(doc), options);
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    QCOMPARE(result->size, QSize(200, 100)); // the shot is the canvas size
    const QImage image(dir.filePath(QStringLiteral("shot/frame_0001.png")));
    QVERIFY(!image.isNull());
    // The dot is at the middle of the shot, twice as wide as on the page.
    const QPointF centre = testing::darkCentre(image);
    QVERIFY2(QLineF(centre, QPointF(100, 50)).length() < 0.75,
             qPrintable(QStringLiteral("%1, %2").arg(centre.x()).arg(centre.y())));
    int dark = 0;
    for (int x = 0; x < 200; ++x)
        dark += qGray(image.pixel(x, 50)) < 100;
    QVERIFY2(dark >= 14 && dark <= 20, qPrintable(QString::number(dark))); // 8 px pen × 2
}

void TestCamera::exportFollowsAPanDuringAHold()
{
    QTemporaryDir dir;
    Document doc;
    dotDocument(doc, {100, 50}, 4); // one drawing held four ticks
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(0, {100, 50})).release());
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(3, {130, 50})).release());
    const ExportSource source = exportSource(doc);
    ExportOptions options;
    options.target = dir.filePath(QStringLiteral("pan"));
    const auto plan = planExport(source, options);
    QVERIFY(plan);
    QCOMPARE(plan->frames.size(), std::size_t(4)); // the hold split into its ticks
    QCOMPARE(plan->ticks, qint64(4));
    const auto result = exportAnimation(source, options);
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    for (int tick = 0; tick < 4; ++tick) {
        const QImage image(dir.filePath(
            QStringLiteral("pan/frame_%1.png").arg(tick + 1, 4, 10, QLatin1Char('0'))));
        // The camera pans right 10 px a tick, so the dot moves left 10 px a tick.
        const QPointF centre = testing::darkCentre(image);
        QVERIFY2(std::abs(centre.x() - (100.0 - 10.0 * tick)) < 0.75,
                 qPrintable(QStringLiteral("tick %1: x %2").arg(tick).arg(centre.x())));
    }
    // One file per drawing cannot show a moving shot: refused with a sentence, not a wrong file.
    options.onePerDrawing = true;
    const auto refused = planExport(source, options);
    QVERIFY(!refused);
    QCOMPARE(refused.error().code, ExportErrorCode::BadOptions);
}

void TestCamera::exportWithoutCameraShowsThePage()
{
    Document doc;
    dotDocument(doc, {150, 50}, 3);
    ExportOptions options;
    const auto plain = planExport(exportSource(doc), options);
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(0, {150, 50}, 2.0)).release());
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(2, {50, 50}, 2.0)).release());
    options.camera = false;
    const auto noCamera = planExport(exportSource(doc), options);
    QVERIFY(plain && noCamera);
    QVERIFY(noCamera->cameras.empty());
    QCOMPARE(noCamera->frames, plain->frames);
    QCOMPARE(noCamera->holds, plain->holds);
    const ExportSource source = exportSource(doc);
    const QImage page = renderExportFrame(source.frames.at(0), source.settings, *noCamera);
    QVERIFY(QLineF(testing::darkCentre(page), QPointF(150, 50)).length() < 0.75);
}

void TestCamera::svgExportFramesTheShot()
{
    QTemporaryDir dir;
    Document doc;
    dotDocument(doc, {150, 50});
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(0, {150, 50}, 2.0)).release());
    ExportOptions options;
    options.format = ExportFormat::SvgSequence;
    options.target = dir.filePath(QStringLiteral("svg"));
    const auto result = exportAnimation(exportSource(doc), options);
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    QFile file(dir.filePath(QStringLiteral("svg/frame_0001.svg")));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray svg = file.readAll();
    QVERIFY(svg.contains("<g transform=\"matrix(2 0 0 2 -200 -50)\">"));
}

// The timeline's frames say which hold a camera key (FrameListModel::CameraKeyRole), and the
// view hears of it when the camera changes.
void TestCamera::timelineMarksTheFramesOfKeys()
{
    Document doc;
    dotDocument(doc, {50, 50}, 3);                          // frame 1: ticks 0-2
    doc.undoStack()->push(new InsertFrameCommand(&doc, 1)); // frame 2: tick 3
    doc.undoStack()->push(new InsertFrameCommand(&doc, 2)); // frame 3: tick 4
    FrameListModel frames(&doc);
    const auto marked = [&] {
        QList<bool> out;
        for (int row = 0; row < frames.rowCount(); ++row)
            out << frames.index(row).data(FrameListModel::CameraKeyRole).toBool();
        return out;
    };
    QCOMPARE(marked(), (QList<bool>{false, false, false}));
    QSignalSpy changed(&frames, &QAbstractItemModel::dataChanged);
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(2, {60, 40})).release());
    QVERIFY(!changed.isEmpty());
    QCOMPARE(marked(), (QList<bool>{true, false, false})); // tick 2 is inside frame 1's hold
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(4, {60, 40})).release());
    QCOMPARE(marked(), (QList<bool>{true, false, true}));
    doc.undoStack()->push(setCameraKeyCommand(&doc, key(40, {60, 40})).release());
    QCOMPARE(marked(), (QList<bool>{true, false, true})); // past the last frame: no frame
}

QTEST_MAIN(TestCamera)
#include "tst_camera.moc"
