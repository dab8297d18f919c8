// Frame → Generate In-betweens… through the real window: two keys picked with Ctrl-click in
// the timeline, the dialog driven with QTest (count, spacing, preview in the canvas), OK
// inserts the frames as one undo step; Cancel leaves the document and the canvas as they were.
#include "../model/inbetween_support.h"
#include "../model/stroke_support.h"
#include "tst_tools_support.h"

#include <finbook/model/finbook_file.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/inbetween/between_fit_view.h>
#include <finbook/ui/inbetween/inbetween_dialog.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QtTest>

#include <functional>

using namespace finbook;
using namespace finbook::test;
using namespace finbook::inbetween_test;

class TestInbetweenDialog : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }
    void init();
    void cleanup() { m_window.reset(); }
    void ctrlClickPicksTwoKeys();
    void okInsertsOneUndoStep();
    void cancelLeavesNothing();
    void differentDrawingsAreCarriedOntoEachOther();
    void aRefusedFitIsListedOnceWithItsReason();
    void dialogShowsThePreviewAndRemembersItsPlace();

private:
    void pickKeys();
    // Triggers Frame → Generate In-betweens… and runs `drive` on the open dialog.
    bool runDialog(const std::function<void(ui::InbetweenDialog *)> &drive);
    QPoint thumbnailCenter(int row) const { return m_view->thumbnailRect(row).center(); }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
    ui::TimelineView *m_view = nullptr;
};

void TestInbetweenDialog::init()
{
    m_window = std::make_unique<ui::MainWindow>();
    auto [a, b] = armKeys(1);
    m_window->document()->reset({a, b}, {}, 100);
    m_window->resize(1100, 750);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_view = m_window->findChild<ui::TimelineView *>();
    QVERIFY(m_view);
    QCoreApplication::processEvents();
}

void TestInbetweenDialog::pickKeys()
{
    QTest::mouseClick(m_view->viewport(), Qt::LeftButton, {}, thumbnailCenter(0));
    QTest::mouseClick(m_view->viewport(), Qt::LeftButton, Qt::ControlModifier, thumbnailCenter(1));
}

bool TestInbetweenDialog::runDialog(const std::function<void(ui::InbetweenDialog *)> &drive)
{
    bool driven = false;
    QTimer::singleShot(0, this, [&] {
        auto *dialog = qobject_cast<ui::InbetweenDialog *>(QApplication::activeModalWidget());
        if (!dialog) {
            if (QWidget *modal = QApplication::activeModalWidget())
                modal->close();
            return;
        }
        driven = true;
        drive(dialog);
    });
    m_window->action(QStringLiteral("frame.inbetweens"))->trigger();
    return driven;
}

void TestInbetweenDialog::ctrlClickPicksTwoKeys()
{
    QAction *generate = m_window->action(QStringLiteral("frame.inbetweens"));
    QVERIFY(generate);
    QVERIFY(!generate->isEnabled()); // one frame picked
    pickKeys();
    QCOMPARE(m_window->editorState()->selectedFrames(), (std::vector<int>{0, 1}));
    QCOMPARE(m_window->editorState()->currentFrameIndex(), 1);
    QVERIFY(generate->isEnabled());
    // A plain click picks one frame again; Shift-click picks the range.
    QTest::mouseClick(m_view->viewport(), Qt::LeftButton, {}, thumbnailCenter(0));
    QCOMPARE(m_window->editorState()->selectedFrames(), (std::vector<int>{0}));
    QVERIFY(!generate->isEnabled());
    QTest::mouseClick(m_view->viewport(), Qt::LeftButton, Qt::ShiftModifier, thumbnailCenter(1));
    QCOMPARE(m_window->editorState()->selectedFrames(), (std::vector<int>{0, 1}));
    // Ctrl-click on a picked frame drops it.
    QTest::mouseClick(m_view->viewport(), Qt::LeftButton, Qt::ControlModifier, thumbnailCenter(0));
    QCOMPARE(m_window->editorState()->selectedFrames(), (std::vector<int>{1}));
    QVERIFY(!generate->isEnabled());
}

void TestInbetweenDialog::okInsertsOneUndoStep()
{
    model::Document *doc = m_window->document();
    pickKeys();
    const QByteArray before = model::serializeFinbook(*doc);
    const bool driven = runDialog([&](ui::InbetweenDialog *dialog) {
        auto *objects = dialog->findChild<QListWidget *>(QStringLiteral("inbetweenObjects"));
        QCOMPARE(objects->count(), 1);
        QVERIFY(objects->item(0)->text().contains(QStringLiteral("interpolated")));
        // The middle in-between is posed on a worker, then on the canvas with the arm at its
        // length.
        QTRY_VERIFY(!dialog->posing());
        QVERIFY(m_window->canvas()->hasPreviewFrame());
        QVERIFY(dialog->previewFrame() && dialog->previewFrame()->groups[0].deformed);
        QVERIFY(std::abs(strokeLength(*dialog->previewFrame()->groups[0].deformed) / 200 - 1) <
                0.02);
        auto *count = dialog->findChild<QSpinBox *>(QStringLiteral("inbetweenCount"));
        count->setFocus();
        count->selectAll();
        QTest::keyClicks(count, QStringLiteral("4"));
        QCOMPARE(count->value(), 4);
        // The change is posed off the GUI thread: until the event loop hears back, the
        // dialog says so and the controls answer.
        QVERIFY(dialog->posing());
        auto *status = dialog->findChild<QLabel *>(QStringLiteral("inbetweenStatus"));
        QVERIFY(status->text().startsWith(QStringLiteral("Posing")));
        QTRY_VERIFY(!dialog->posing());
        QVERIFY(status->text().contains(QStringLiteral("middle in-between")));
        QVERIFY(dialog->previewFrame() && dialog->previewFrame()->groups[0].deformed);
        auto *spacing = dialog->findChild<QComboBox *>(QStringLiteral("inbetweenSpacing"));
        spacing->setFocus();
        QTest::keyClick(spacing, Qt::Key_Down); // ease in
        QCOMPARE(dialog->options().spacing.kind, model::SpacingKind::EaseIn);
        auto *buttons = dialog->findChild<QDialogButtonBox *>();
        QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
    });
    QVERIFY(driven);
    QVERIFY(!m_window->canvas()->hasPreviewFrame());
    QCOMPARE(doc->frameCount(), 6);
    QCOMPARE(doc->undoStack()->count(), 1);
    QCOMPARE(doc->frameAt(0).id, Id(1));
    // The DeformController poses the new frames (the keys were never posed in this window).
    QTRY_VERIFY_WITH_TIMEOUT(
        std::all_of(doc->frames().begin() + 1, doc->frames().end() - 1,
                    [](const model::Frame &f) { return f.groups[0].deformed != nullptr; }),
        10000);
    // Ease in: the first in-between moves less than the last one does.
    const auto handOf = [&](int row) { return doc->frameAt(row).groups[0].rig.pins[1].target; };
    const auto step = [](QPointF p, QPointF q) { return std::hypot(p.x() - q.x(), p.y() - q.y()); };
    QVERIFY(step(handOf(0), handOf(1)) < step(handOf(4), handOf(5)));
    doc->undoStack()->undo();
    QCOMPARE(doc->frameCount(), 2);
    QCOMPARE(model::serializeFinbook(*doc), before);
}

void TestInbetweenDialog::cancelLeavesNothing()
{
    model::Document *doc = m_window->document();
    pickKeys();
    const QByteArray before = model::serializeFinbook(*doc);
    const bool driven = runDialog([&](ui::InbetweenDialog *dialog) {
        QTRY_VERIFY(m_window->canvas()->hasPreviewFrame());
        // Cancelled while a changed preview is still being posed: that pose must not bring
        // the preview back after the dialog has gone.
        auto *count = dialog->findChild<QSpinBox *>(QStringLiteral("inbetweenCount"));
        count->setValue(5);
        QVERIFY(dialog->posing());
        auto *buttons = dialog->findChild<QDialogButtonBox *>();
        QTest::mouseClick(buttons->button(QDialogButtonBox::Cancel), Qt::LeftButton);
    });
    QVERIFY(driven);
    QVERIFY(!m_window->canvas()->hasPreviewFrame());
    QTest::qWait(100); // any late result of the worker would arrive now
    QVERIFY(!m_window->canvas()->hasPreviewFrame());
    QCOMPARE(doc->frameCount(), 2);
    QCOMPARE(doc->undoStack()->count(), 0);
    QCOMPARE(model::serializeFinbook(*doc), before);
}

// Issue 50: the second key drawn anew (another outline, not a pose of the first): the dialog
// fits the drawings as it opens, says so, and OK carries the first onto the second.
void TestInbetweenDialog::differentDrawingsAreCarriedOntoEachOther()
{
    model::Document *doc = m_window->document();
    model::Frame a, b;
    a.id = 1;
    b.id = 5;
    model::StrokeGroup first, second;
    first.id = 2;
    first.name = QStringLiteral("Box");
    first.strokes.push_back({3, testing::squareOutline({100, 100}, 120, 30, 3.0f)});
    second.id = 6;
    second.name = QStringLiteral("Box");
    second.strokes.push_back({7, testing::squareOutline({160, 130}, 120, 22, 3.0f)});
    a.groups.push_back(first);
    b.groups.push_back(second);
    doc->reset({a, b}, {}, 100);
    QCoreApplication::processEvents();
    pickKeys();
    const QByteArray before = model::serializeFinbook(*doc);
    const bool driven = runDialog([&](ui::InbetweenDialog *dialog) {
        auto *ok = dialog->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
        auto *carry = dialog->findChild<QCheckBox *>(QStringLiteral("inbetweenBetweenDrawings"));
        QVERIFY(carry && !carry->isHidden() && carry->isChecked());
        QVERIFY(!dialog->fitting() || !ok->isEnabled()); // OK waits for the fit
        QTRY_VERIFY(!dialog->fitting());
        QVERIFY(ok->isEnabled());
        auto *objects = dialog->findChild<QListWidget *>(QStringLiteral("inbetweenObjects"));
        QCOMPARE(objects->count(), 1);
        QVERIFY2(objects->item(0)->text().contains(QStringLiteral("carried")),
                 qPrintable(objects->item(0)->text()));
        QCOMPARE(dialog->fits().size(), std::size_t(1));
        // The fit is shown; dragging from the first drawing's corner pins it 30 px lower on
        // the second, refitted live; Ctrl+Z takes the pin away again, Ctrl+Shift+Z brings it
        // back.
        auto *view = dialog->findChild<ui::BetweenFitView *>(QStringLiteral("inbetweenFitView"));
        QVERIFY(view && view->isVisible() && view->fit());
        const QPointF corner = view->fittedPoint(0, 0);
        const QPointF goal = corner + QPointF(0, 30);
        QTest::mousePress(view, Qt::LeftButton, {}, view->toWidget(corner).toPoint());
        QTest::mouseMove(view, view->toWidget(corner + QPointF(0, 15)).toPoint());
        QTest::mouseMove(view, view->toWidget(goal).toPoint());
        QTest::mouseRelease(view, Qt::LeftButton, {}, view->toWidget(goal).toPoint());
        QTRY_VERIFY(!dialog->fitting());
        QCOMPARE(dialog->fits().at(0)->pins.size(), std::size_t(1));
        const double pinned =
            QLineF(view->fittedPoint(0, 0), dialog->fits().at(0)->pins[0].onB).length();
        QVERIFY2(pinned < QLineF(corner, goal).length() / 2, qPrintable(QString::number(pinned)));
        // The keys go where the keyboard is after the drag (the count's field had it before).
        QCOMPARE(QApplication::focusWidget(), view);
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Z, Qt::ControlModifier);
        QTRY_VERIFY(!dialog->fitting() && dialog->fits().at(0)->pins.empty());
        QVERIFY(view->pins().empty());
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Z,
                        Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY(!dialog->fitting() && dialog->fits().at(0)->pins.size() == 1);
        // Right-click takes it away (one more undo step).
        QTest::mouseClick(view, Qt::RightButton, {},
                          view->toWidget(dialog->fits().at(0)->pins[0].onB).toPoint());
        QTRY_VERIFY(!dialog->fitting() && dialog->fits().at(0)->pins.empty());
        // Unchecked, the drawing switches over half way as before.
        carry->click();
        QVERIFY(dialog->fits().empty());
        QVERIFY(objects->item(0)->text().contains(QStringLiteral("only in the first key")));
        carry->click();
        QTRY_VERIFY(!dialog->posing());
        QTest::mouseClick(ok, Qt::LeftButton);
    });
    QVERIFY(driven);
    QCOMPARE(doc->frameCount(), 5);
    QCOMPARE(doc->undoStack()->count(), 1);
    // Each in-between is the box on its way: its outline's left edge between the keys', in order.
    double previous = 100.0;
    for (int row = 1; row <= 3; ++row) {
        const model::StrokeGroup &g = doc->frameAt(row).groups.at(0);
        QVERIFY(g.rig.empty());
        double left = 1e9;
        for (const model::StrokePoint &p : g.strokes.at(0).data->points)
            left = std::min(left, double(p.x));
        QVERIFY2(left > previous && left < 161.0, qPrintable(QString::number(left)));
        previous = left;
    }
    doc->undoStack()->undo();
    QCOMPARE(model::serializeFinbook(*doc), before);
}

// tests/data/between_arm_out.finbook (the arm drawn over the body and swung out in the second
// key) is carried, the arm as a piece of its own; the same first key with a scribble for the
// second is refused: one line in the objects list, with why, and the in-betweens switch it over
// half way.
void TestInbetweenDialog::aRefusedFitIsListedOnceWithItsReason()
{
    model::Document *doc = m_window->document();
    const auto loaded = model::loadFinbook(
        QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data/between_arm_out.finbook"));
    QVERIFY(loaded && loaded->frames.size() == 2);
    std::vector<model::Frame> scribbled = loaded->frames;
    std::vector<model::StrokePoint> zigzag;
    for (int i = 0; i < 24; ++i)
        zigzag.push_back({float(560 + 16 * i), float(i % 2 ? 250 : 560), 1.0f});
    model::StrokeGroup &second = scribbled[1].groups.at(0);
    second.fills.clear();
    second.strokes.resize(1);
    auto data = std::make_shared<model::StrokeData>(*second.strokes[0].data);
    data->points = zigzag;
    second.strokes[0].data = std::move(data);
    for (const bool refused : {false, true}) {
        doc->reset(refused ? scribbled : loaded->frames, loaded->settings, loaded->nextId);
        QCoreApplication::processEvents();
        pickKeys();
        QStringList lines;
        bool fitted = true, settled = false;
        const bool driven = runDialog([&](ui::InbetweenDialog *dialog) {
            // Read, then closed, so that a failing check below does not leave the dialog open.
            settled = QTest::qWaitFor([dialog] { return !dialog->fitting(); }, 20000);
            auto *objects = dialog->findChild<QListWidget *>(QStringLiteral("inbetweenObjects"));
            for (int row = 0; objects && row < objects->count(); ++row)
                lines << objects->item(row)->text();
            fitted = !dialog->fits().empty();
            dialog->reject();
        });
        QVERIFY(driven && settled);
        QCOMPARE(lines.size(), 1);
        if (!refused) {
            QVERIFY2(lines[0].contains(QStringLiteral("carried from the first key")),
                     qPrintable(lines[0]));
            QVERIFY(fitted);
            continue;
        }
        QVERIFY2(lines[0].contains(QStringLiteral("could not be carried")) &&
                     lines[0].contains(QStringLiteral("too different")),
                 qPrintable(lines[0]));
        QVERIFY(!fitted);
    }
}

// Issue 22, item 6: the dialog does not cover the page it previews on, the canvas shows the
// preview's own pins, Favour shows only when chosen, and the dialog comes back where the user
// put it.
void TestInbetweenDialog::dialogShowsThePreviewAndRemembersItsPlace()
{
    pickKeys();
    ui::CanvasWidget *canvas = m_window->canvas();
    const QSize page = m_window->document()->settings().canvasSize;
    const QPoint pageCentre = canvas->mapToGlobal(
        canvas->mapFromCanvas(QPointF(page.width() / 2.0, page.height() / 2.0)).toPoint());
    QPoint movedTo;
    bool driven = runDialog([&](ui::InbetweenDialog *dialog) {
        QVERIFY2(!dialog->frameGeometry().contains(pageCentre), "the dialog covers the preview");
        auto *favour = dialog->findChild<QSlider *>(QStringLiteral("inbetweenFavour"));
        QVERIFY(!favour->isVisibleTo(dialog));
        auto *spacing = dialog->findChild<QComboBox *>(QStringLiteral("inbetweenSpacing"));
        spacing->setCurrentIndex(spacing->findData(int(model::SpacingKind::Favour)));
        QVERIFY(favour->isVisibleTo(dialog));
        QTRY_VERIFY(!dialog->posing());
        QTRY_VERIFY(canvas->hasPreviewFrame());
        // The overlays draw the frame on show: the in-between's pins, not the second key's.
        const model::Pin &shown = canvas->shownFrame()->groups[0].rig.pins[1];
        QCOMPARE(shown.target, dialog->previewFrame()->groups[0].rig.pins[1].target);
        QVERIFY(shown.target !=
                m_window->editorState()->currentFrame()->groups[0].rig.pins[1].target);
        movedTo = dialog->pos() + QPoint(-37, 23);
        dialog->move(movedTo);
        dialog->reject();
    });
    QVERIFY(driven);
    QVERIFY(!canvas->hasPreviewFrame());
    QCOMPARE(canvas->shownFrame(), m_window->editorState()->currentFrame());
    pickKeys();
    driven = runDialog([&](ui::InbetweenDialog *dialog) {
        QCOMPARE(dialog->pos(), movedTo);
        dialog->reject();
    });
    QVERIFY(driven);
}

QTEST_MAIN(TestInbetweenDialog)
#include "tst_inbetween_dialog.moc"
