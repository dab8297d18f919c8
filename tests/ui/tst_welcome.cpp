// The welcome page: shown at the first start only (unless asked for at every start), and each
// of its choices does what it says in the real main window; the example opens as a new
// animation; the timeline says plainly where a drag scrubs and where it reorders.
#include "tst_window_support.h"

#include <finbook/ui/help/manual_browser.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/window/welcome_dialog.h>

#include <QCheckBox>
#include <QHelpEvent>
#include <QListWidget>
#include <QPushButton>
#include <QTextBrowser>
#include <QToolTip>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

class TestWelcome : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        m_settings = std::make_unique<IsolatedSettings>();
        m_window = std::make_unique<ui::MainWindow>();
        QVERIFY(showActive(*m_window));
    }
    void cleanup()
    {
        m_window.reset();
        m_settings.reset();
    }

    void shownAtTheFirstStartOnly();
    void exampleOpensAsANewAnimation();
    void choicesDoWhatTheySay();
    void timelineSaysWhereADragScrubsOrReorders();

private:
    ui::WelcomeDialog *welcome()
    {
        // One closed earlier is deleted once the event loop gets to it.
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
        m_window->showWelcome();
        const QList<ui::WelcomeDialog *> open = m_window->findChildren<ui::WelcomeDialog *>();
        return open.size() == 1 && open.front()->isVisible() ? open.front() : nullptr;
    }
    template <typename T> T *in(QWidget *w, const char *name)
    {
        return w->findChild<T *>(QString::fromLatin1(name));
    }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
};

void TestWelcome::shownAtTheFirstStartOnly()
{
    QVERIFY(ui::WelcomeDialog::shouldShowAtStart());
    ui::WelcomeDialog *dialog = welcome();
    QVERIFY(dialog);
    QVERIFY(!ui::WelcomeDialog::shouldShowAtStart()); // seen once
    auto *atStart = in<QCheckBox>(dialog, "welcomeAtStart");
    QVERIFY(!atStart->isChecked());
    atStart->setChecked(true);
    QVERIFY(ui::WelcomeDialog::shouldShowAtStart());
    atStart->setChecked(false);
    QVERIFY(!ui::WelcomeDialog::shouldShowAtStart());
    dialog->reject();
    QVERIFY(m_window->action(QStringLiteral("file.welcome")));
}

void TestWelcome::exampleOpensAsANewAnimation()
{
    ui::WelcomeDialog *dialog = welcome();
    QVERIFY(dialog);
    QTest::mouseClick(in<QPushButton>(dialog, "welcomeExample"), Qt::LeftButton);
    QVERIFY(!dialog->isVisible());
    QVERIFY(m_window->document()->frameCount() > 4);
    QVERIFY(m_window->filePath().isEmpty()); // saving asks where
    QCOMPARE(m_window->document()->undoStack()->count(), 0);
    // File > Open Example does the same.
    m_window->newDocument();
    QCOMPARE(m_window->document()->frameCount(), 1);
    m_window->action(QStringLiteral("file.openExample"))->trigger();
    QVERIFY(m_window->document()->frameCount() > 4);
}

void TestWelcome::choicesDoWhatTheySay()
{
    // A recent file opens from the list.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mine.finbook"));
    resetDocument(*m_window->document(), 3);
    QVERIFY(m_window->saveFile(path));
    m_window->newDocument();
    ui::WelcomeDialog *dialog = welcome();
    QVERIFY(dialog);
    QListWidget *recent = dialog->recentList();
    QCOMPARE(recent->item(0)->text(), QStringLiteral("mine.finbook"));
    recent->setCurrentRow(0);
    emit recent->itemActivated(recent->item(0));
    QCOMPARE(m_window->filePath(), QFileInfo(path).absoluteFilePath());
    QCOMPARE(m_window->document()->frameCount(), 3);
    // New empties it.
    dialog = welcome();
    QVERIFY(dialog);
    QTest::mouseClick(in<QPushButton>(dialog, "welcomeNew"), Qt::LeftButton);
    QCOMPARE(m_window->document()->frameCount(), 1);
    QVERIFY(m_window->filePath().isEmpty());
    // The walkthrough's link and the manual button open the manual's first steps.
    dialog = welcome();
    QVERIFY(
        dialog->walkthrough()->toPlainText().contains(QStringLiteral("bend"), Qt::CaseInsensitive));
    emit dialog->walkthrough()->anchorClicked(QUrl(QStringLiteral("getting-started.md")));
    QVERIFY(m_window->manual() && m_window->manual()->isVisible());
    QCOMPARE(m_window->manual()->currentPage(), QStringLiteral("getting-started.md"));
    m_window->manual()->hide();
    dialog = welcome();
    QVERIFY(dialog);
    QTest::mouseClick(in<QPushButton>(dialog, "welcomeManual"), Qt::LeftButton);
    QVERIFY(m_window->manual()->isVisible());
}

void TestWelcome::timelineSaysWhereADragScrubsOrReorders()
{
    resetDocument(*m_window->document(), 4);
    auto *timeline = m_window->findChild<ui::TimelineView *>();
    QVERIFY(timeline);
    const QRect cell = timeline->visualRect(timeline->model()->index(1, 0));
    const QPoint band(cell.center().x(), cell.top() + 3);
    const QPoint picture = cell.center() + QPoint(0, ui::TimelineView::kBandHeight / 2);
    QVERIFY(timeline->onNumberBand(band));
    QVERIFY(!timeline->onNumberBand(picture));
    sendMouse(timeline->viewport(), QEvent::MouseMove, band, Qt::NoButton, Qt::NoButton);
    QCOMPARE(timeline->viewport()->cursor().shape(), Qt::SizeHorCursor);
    sendMouse(timeline->viewport(), QEvent::MouseMove, picture, Qt::NoButton, Qt::NoButton);
    QCOMPARE(timeline->viewport()->cursor().shape(), Qt::OpenHandCursor);
    QHelpEvent tip(QEvent::ToolTip, band, timeline->viewport()->mapToGlobal(band));
    QApplication::sendEvent(timeline->viewport(), &tip);
    QTRY_VERIFY(QToolTip::isVisible());
    QVERIFY(QToolTip::text().contains(QStringLiteral("scrub")));
    QHelpEvent tip2(QEvent::ToolTip, picture, timeline->viewport()->mapToGlobal(picture));
    QApplication::sendEvent(timeline->viewport(), &tip2);
    QTRY_VERIFY(QToolTip::text().contains(QStringLiteral("move the frame")));
}

QTEST_MAIN(TestWelcome)
#include "tst_welcome.moc"
