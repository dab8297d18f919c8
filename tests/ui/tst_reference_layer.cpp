// The reference layer in the window: File → Import Reference, the Reference panel's edits
// (undoable, lock), the canvas showing it under the drawing and the pen ignoring it.
#include "../model/hostile_media.h"
#include "../model/reference_support.h"
#include "tst_window_support.h"

#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/render.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/reference/reference_panel.h>
#include <finbook/ui/timeline/thumbnail_cache.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QSignalSpy>
#include <QSlider>
#include <QStatusBar>
#include <QTest>

using namespace finbook;
using namespace finbook::test;

class TestReferenceLayer : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }

    void panelEditsAreUndoable()
    {
        model::Document doc;
        doc.reset({model::Frame{doc.allocateId(), 1, {}, {}}}, model::DocumentSettings(),
                  doc.nextId());
        ui::ReferencePanel panel(&doc);
        QVERIFY(!panel.opacitySlider()->isEnabled());
        QVERIFY(!ui::importReference(doc, writeTwoColourPng(m_dir.path())));
        QVERIFY(panel.opacitySlider()->isEnabled());
        const model::Reference imported = doc.referenceLayer().reference();
        panel.opacitySlider()->setValue(80);
        QCOMPARE(doc.referenceLayer().reference().opacity, 0.8);
        panel.rotationBox()->setValue(30.0);
        QCOMPARE(doc.referenceLayer().reference().rotation, 30.0);
        panel.lockedBox()->setChecked(true);
        QVERIFY(!panel.xBox()->isEnabled());
        QVERIFY(!panel.rotationBox()->isEnabled());
        doc.undoStack()->undo(); // lock
        doc.undoStack()->undo(); // rotation
        doc.undoStack()->undo(); // opacity
        QCOMPARE(doc.referenceLayer().reference(), imported);
        QCOMPARE(panel.opacitySlider()->value(), 50);
        QVERIFY(panel.xBox()->isEnabled());
    }

    // A video counts animation frames per second of footage, a sequence pictures per second of
    // animation: the row says which, and a still has no rate at all.
    void rateRowSaysWhatItCounts()
    {
        model::Document doc;
        doc.reset({model::Frame{doc.allocateId(), 1, {}, {}}}, model::DocumentSettings(),
                  doc.nextId());
        ui::ReferencePanel panel(&doc);
        QVERIFY(!ui::importReference(doc, writeTwoColourPng(m_dir.path())));
        QVERIFY(!panel.rateBox()->isEnabled());
        QStringList pictures;
        for (int i = 1; i <= 2; ++i) {
            pictures << m_dir.filePath(QStringLiteral("shot_%1.png").arg(i));
            QVERIFY(QFile::copy(writeTwoColourPng(m_dir.path()), pictures.back()));
        }
        QVERIFY(!ui::importReference(doc, pictures));
        QCOMPARE(doc.referenceLayer().reference().kind, model::ReferenceKind::Sequence);
        QVERIFY(panel.rateBox()->isEnabled());
        QCOMPARE(panel.rateLabel()->text(), QStringLiteral("Picture rate:"));
        QVERIFY(panel.rateBox()->toolTip().startsWith(QStringLiteral("Pictures per second")));
        doc.undoStack()->undo();
        QCOMPARE(panel.rateLabel()->text(), QStringLiteral("Video rate:"));
        QVERIFY(!panel.rateBox()->isEnabled());
        const QString video =
            writeTestVideo(m_dir.path(), QStringLiteral("rate.mp4"), {64, 48}, 1, 12);
        if (video.isEmpty())
            QSKIP("ffmpeg could not write a test video");
        QVERIFY(!ui::importReference(doc, video));
        QVERIFY(panel.rateBox()->isEnabled());
        QCOMPARE(panel.rateLabel()->text(), QStringLiteral("Video rate:"));
        QVERIFY(
            panel.rateBox()->toolTip().startsWith(QStringLiteral("Animation frames per second")));
    }

    void refusedFileChangesNothing()
    {
        model::Document doc;
        QFile png(writeTwoColourPng(m_dir.path()));
        QVERIFY(png.open(QIODevice::ReadOnly));
        const QString cut = m_dir.filePath(QStringLiteral("half.png"));
        QFile out(cut);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(png.readAll().left(30));
        out.close();
        const auto error = ui::importReference(doc, cut);
        QVERIFY(error);
        QVERIFY(error->contains(QStringLiteral("half.png")));
        QVERIFY(doc.referenceLayer().isEmpty());
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void thumbnailsDoNotWaitForTheVideo()
    {
        model::Document doc;
        model::DocumentSettings settings;
        settings.canvasSize = QSize(64, 48);
        settings.fps = 12;
        std::vector<model::Frame> frames(12);
        for (model::Frame &f : frames)
            f.id = doc.allocateId();
        doc.reset(std::move(frames), settings, doc.nextId());
        const QString video =
            writeTestVideo(m_dir.path(), QStringLiteral("thumbs.mp4"), {64, 48}, 1, 12);
        if (video.isEmpty())
            QSKIP("ffmpeg could not write a test video");
        QVERIFY(!ui::importReference(doc, video));
        model::ReferenceLayer &layer = doc.referenceLayer();
        layer.media()->setCacheLimit(0); // only the frame decoded last stays
        ui::ThumbnailCache cache(&doc);
        cache.setThumbnailSize(QSize(64, 48));
        const model::Id id = doc.frameAt(9).id;
        QVERIFY(layer.media()->cachedFrame(layer.videoFrameAt(9)).isNull());
        // Rendered at once without the video's picture, which a worker decodes meanwhile.
        cache.thumbnail(id);
        cache.renderPending();
        QCOMPARE(cache.renderedCount(), 1);
        const QImage first = cache.thumbnail(id).toImage();
        QCOMPARE(first, model::renderFrame(doc.frameAt(9), doc.settings(), QSize(64, 48))
                            .convertToFormat(first.format()));
        // Then drawn again with it.
        QTRY_COMPARE(cache.renderedCount(), 2);
        QVERIFY(cache.isCurrent(id));
        const QImage second = cache.thumbnail(id).toImage();
        const QImage expected = model::renderFrameWithReference(
            doc.frameAt(9), doc.settings(), QSize(64, 48), layer.reference(), layer.pictureAt(9));
        QCOMPARE(second, expected.convertToFormat(second.format()));
        QVERIFY(second != first);
        // Edited while its picture is out of the cache: the older thumbnail stays, and asking
        // for it again while the picture decodes queues nothing more.
        layer.pictureAt(2); // the cache keeps only this one
        QVERIFY(layer.media()->cachedFrame(layer.videoFrameAt(9)).isNull());
        emit doc.frameChanged(id);
        QVERIFY(!cache.isCurrent(id));
        cache.thumbnail(id);
        cache.renderPending();
        QCOMPARE(cache.thumbnail(id).toImage(), second);
        QCOMPARE(cache.pendingCount(), 0);
        QTRY_VERIFY(cache.isCurrent(id));
        QCOMPARE(cache.thumbnail(id).toImage(), second);
    }

    void canvasShowsItUnderTheDrawing()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        QVERIFY(window.action(QStringLiteral("file.importReference")));
        model::Document *doc = window.document();
        QVERIFY(!ui::importReference(*doc, writeTwoColourPng(m_dir.path())));
        ui::CanvasWidget *canvas = window.canvas();
        const QSize page = doc->settings().canvasSize;
        const auto pixelAt = [&](QPointF canvasPoint) {
            const QImage shot = canvas->grab().toImage();
            const QPointF p = canvas->canvasToWidget().map(canvasPoint) * shot.devicePixelRatio();
            return QColor(shot.pixel(p.toPoint()));
        };
        // The left half of the picture is red at half opacity over the white page.
        const QColor left = pixelAt(QPointF(page.width() * 0.25, page.height() * 0.5));
        QVERIFY2(left.red() > 200 && left.green() < 180 && left.blue() < 180,
                 qPrintable(left.name()));
        const QColor right = pixelAt(QPointF(page.width() * 0.75, page.height() * 0.5));
        QVERIFY2(right.blue() > 200 && right.red() < 180, qPrintable(right.name()));
        // A stroke drawn over it goes into the drawing's object; the reference is unchanged.
        const model::Reference before = doc->referenceLayer().reference();
        const std::size_t objects = doc->frameAt(0).groups.size();
        canvas->setCurrentTool(QStringLiteral("tool.pen"));
        dragCanvas(canvas, QPointF(page.width() * 0.2, page.height() * 0.5),
                   QPointF(page.width() * 0.3, page.height() * 0.5), 8);
        QCOMPARE(doc->frameAt(0).groups.size(), objects);
        QCOMPARE(doc->frameAt(0).groups.front().strokes.size(), std::size_t(1));
        QCOMPARE(doc->referenceLayer().reference(), before);
        // The darkest pixel across the stroke (at a small zoom its 3 px are about one pixel).
        QColor stroke = Qt::white;
        for (int dy = -2; dy <= 2; ++dy) {
            const QColor c = pixelAt(QPointF(page.width() * 0.25, page.height() * 0.5 + dy));
            if (c.lightness() < stroke.lightness())
                stroke = c;
        }
        QVERIFY2(stroke.lightness() < 100, qPrintable(stroke.name()));
        // Hidden: the page is white again there.
        model::Reference hidden = before;
        hidden.visible = false;
        doc->undoStack()->push(
            model::editReferenceCommand(doc, hidden, model::ReferenceEdit::Visible).release());
        const QColor gone = pixelAt(QPointF(page.width() * 0.75, page.height() * 0.5));
        QCOMPARE(gone, QColor(Qt::white));
    }

    // Issue 47: a reference that cannot be used was silently not shown. The status bar says
    // so, once; the drawing still works.
    void unusableReferenceIsSaidOnTheStatusBar()
    {
        ui::MainWindow window;
        QVERIFY(showActive(window));
        model::Document *doc = window.document();
        QSignalSpy failed(&doc->referenceLayer(), &model::ReferenceLayer::mediaFailed);
        model::Reference r;
        r.kind = model::ReferenceKind::Image;
        r.name = QStringLiteral("bomb.svg");
        r.bytes = hostile_media::useBomb();
        r.mediaSize = QSizeF(100, 100);
        r.center = QPointF(50, 50);
        doc->referenceLayer().setReference(r);
        window.canvas()->repaint();
        QTRY_COMPARE(failed.count(), 1);
        const QString message = window.statusBar()->currentMessage();
        QVERIFY2(message.contains(QStringLiteral("bomb.svg")) &&
                     message.contains(QStringLiteral("100,000")),
                 qPrintable(message));
        window.canvas()->repaint();
        QTest::qWait(50);
        QCOMPARE(failed.count(), 1);
    }

private:
    std::unique_ptr<IsolatedSettings> m_settings;
    QTemporaryDir m_dir;
};

QTEST_MAIN(TestReferenceLayer)
#include "tst_reference_layer.moc"
