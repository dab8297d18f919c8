// The Finbook Manual in the app: every page present with its links and pictures, F1 opening
// the page of the tool in hand, search, links and Back; and the manual's screenshots taken from
// the real window, so that they show the window as it is. A screenshot that no longer matches
// fails here: FINBOOK_UPDATE_MANUAL_SHOTS=1 writes the new ones into resources/manual/images.
#include "tst_window_support.h"

#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/export/export_dialog.h>
#include <finbook/ui/help/manual_browser.h>

#include <QDockWidget>
#include <QListWidget>
#include <QRegularExpression>
#include <QTextBrowser>
#include <QToolButton>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

class TestManual : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }
    void cleanup() { m_window.reset(); }

    void everyPageLinksAndPictureIsPresent();
    void f1OpensThePageOfTheToolInHand();
    void searchNarrowsTheContents();
    void linksAndBackWork();
    void screenshotsShowTheWindowAsItIs_data();
    void screenshotsShowTheWindowAsItIs();

private:
    void openExample()
    {
        m_window = std::make_unique<ui::MainWindow>();
        QVERIFY(showActive(*m_window));
        QVERIFY(m_window->openFile(QStringLiteral(FINBOOK_SOURCE_DIR) +
                                   QStringLiteral("/resources/examples/walk.finbook")));
        QTest::qWait(50);
    }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
};

void TestManual::everyPageLinksAndPictureIsPresent()
{
    const QList<ui::ManualBrowser::Page> pages = ui::ManualBrowser::pages();
    QVERIFY(pages.size() >= 10);
    QStringList files;
    for (const auto &p : pages) {
        files << p.file;
        QVERIFY2(!p.title.isEmpty(), qPrintable(p.file));
    }
    const QString index = ui::ManualBrowser::pageText(QStringLiteral("index.md"));
    const QRegularExpression link(QStringLiteral("\\]\\(([^)\\s]+)\\)"));
    QSet<QString> pictures;
    for (const QString &file : files) {
        const QString text = ui::ManualBrowser::pageText(file);
        QVERIFY2(text.startsWith(QLatin1String("# ")), qPrintable(file));
        if (file != QLatin1String("index.md"))
            QVERIFY2(index.contains(QStringLiteral("(") + file + QStringLiteral(")")),
                     qPrintable(file + QStringLiteral(" is not in the contents")));
        for (auto m = link.globalMatch(text); m.hasNext();) {
            const QString target = m.next().captured(1);
            if (target.startsWith(QLatin1String("http")))
                continue;
            if (target.startsWith(QLatin1String("images/"))) {
                const QImage picture(QStringLiteral(":/manual/") + target);
                QVERIFY2(!picture.isNull(), qPrintable(file + QStringLiteral(": ") + target));
                pictures.insert(target);
            } else {
                QVERIFY2(files.contains(target), qPrintable(file + QStringLiteral(": ") + target));
            }
        }
    }
    // Every screenshot this test takes is shown somewhere.
    QCOMPARE(pictures.size(), 11);
}

void TestManual::f1OpensThePageOfTheToolInHand()
{
    m_window = std::make_unique<ui::MainWindow>();
    QVERIFY(showActive(*m_window));
    int tools = 0;
    for (ui::CanvasTool *tool : m_window->canvas()->tools()) {
        m_window->canvas()->setCurrentTool(tool->id());
        m_window->canvas()->setFocus();
        QTRY_COMPARE(QApplication::focusWidget(), m_window->canvas());
        typeKey(Qt::Key_F1);
        ui::ManualBrowser *manual = m_window->manual();
        QVERIFY(manual && manual->isVisible());
        QCOMPARE(manual->currentPage(), ui::ManualBrowser::pageForTool(tool->id()));
        // The contents show which page it is.
        QCOMPARE(manual->contents()->currentItem()->data(Qt::UserRole).toString(),
                 manual->currentPage());
        QVERIFY2(manual->currentPage() != QLatin1String("index.md"), qPrintable(tool->id()));
        QVERIFY(!manual->text()->toPlainText().isEmpty());
        manual->hide();
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        ++tools;
    }
    QVERIFY(tools >= 10);
    QCOMPARE(ui::ManualBrowser::pageForTool(QStringLiteral("tool.bone")),
             QStringLiteral("bones.md"));
}

void TestManual::searchNarrowsTheContents()
{
    ui::ManualBrowser manual;
    const int all = manual.contents()->count();
    QCOMPARE(manual.search(QString()), all);
    const int cage = manual.search(QStringLiteral("Fit Cage"));
    QVERIFY(cage >= 1 && cage < all);
    const auto shown = [&](const QString &file) {
        for (int row = 0; row < manual.contents()->count(); ++row)
            if (manual.contents()->item(row)->data(Qt::UserRole).toString() == file)
                return !manual.contents()->item(row)->isHidden();
        return false;
    };
    QVERIFY(shown(QStringLiteral("cage.md")));
    QVERIFY(!shown(QStringLiteral("installing.md")));
    QCOMPARE(manual.search(QStringLiteral("zzqxj-no-such-word")), 0);
    // Typing and Return open the first page holding the words.
    manual.show();
    QVERIFY(QTest::qWaitForWindowExposed(&manual));
    manual.searchField()->setFocus();
    QTest::keyClicks(manual.searchField(), QStringLiteral("stabiliser"));
    QTest::keyClick(manual.searchField(), Qt::Key_Return);
    QVERIFY(ui::ManualBrowser::pageText(manual.currentPage())
                .contains(QStringLiteral("stabiliser"), Qt::CaseInsensitive));
    QVERIFY(!manual.text()->extraSelections().isEmpty()); // the word is highlighted
}

void TestManual::linksAndBackWork()
{
    ui::ManualBrowser manual;
    manual.show();
    QVERIFY(QTest::qWaitForWindowExposed(&manual));
    QCOMPARE(manual.currentPage(), QStringLiteral("index.md"));
    emit manual.text()->anchorClicked(QUrl(QStringLiteral("pins.md")));
    QCOMPARE(manual.currentPage(), QStringLiteral("pins.md"));
    QVERIFY(manual.text()->toPlainText().contains(QStringLiteral("pin"), Qt::CaseInsensitive));
    auto *back = manual.findChild<QToolButton *>(QStringLiteral("manualBack"));
    QVERIFY(back->isEnabled());
    QTest::mouseClick(back, Qt::LeftButton);
    QCOMPARE(manual.currentPage(), QStringLiteral("index.md"));
    // A page name that is not in the manual shows the contents.
    manual.openPage(QStringLiteral("../../etc/passwd"));
    QCOMPARE(manual.currentPage(), QStringLiteral("index.md"));
}

void TestManual::screenshotsShowTheWindowAsItIs_data()
{
    QTest::addColumn<QString>("name");
    for (const char *name : {"main-window", "drawing", "turned-view", "palette", "fills", "pins",
                             "cage", "bones", "timeline", "camera", "export-dialog"})
        QTest::newRow(name) << QString::fromLatin1(name);
}

void TestManual::screenshotsShowTheWindowAsItIs()
{
    QFETCH(QString, name);
    openExample();
    ui::CanvasWidget *canvas = m_window->canvas();
    canvas->setCurrentTool(QStringLiteral("tool.pen")); // whatever an earlier row left in hand
    const auto action = [this](const char *objectName) {
        QAction *a = m_window->action(QString::fromLatin1(objectName));
        if (!a)
            a = m_window->findChild<QAction *>(QString::fromLatin1(objectName));
        return a;
    };
    QWidget *shot = m_window.get();
    std::unique_ptr<ui::ExportDialog> dialog;
    if (name == QLatin1String("drawing")) {
        canvas->setCurrentTool(QStringLiteral("tool.select"));
        action("edit.selectAll")->trigger();
    } else if (name == QLatin1String("turned-view")) {
        canvas->setRotation(30);
    } else if (name == QLatin1String("palette")) {
        shot = m_window->findChild<QDockWidget *>(QStringLiteral("paletteDock"));
    } else if (name == QLatin1String("fills")) {
        canvas->setCurrentTool(QStringLiteral("tool.fill"));
    } else if (name == QLatin1String("pins")) {
        canvas->setCurrentTool(QStringLiteral("tool.pin"));
        action("view.showMesh")->setChecked(true);
    } else if (name == QLatin1String("cage")) {
        canvas->setCurrentTool(QStringLiteral("tool.cage"));
    } else if (name == QLatin1String("bones")) {
        canvas->setCurrentTool(QStringLiteral("tool.bone"));
    } else if (name == QLatin1String("timeline")) {
        shot = m_window->findChild<QDockWidget *>(QStringLiteral("timelineDock"));
    } else if (name == QLatin1String("camera")) {
        canvas->setCurrentTool(QStringLiteral("tool.camera"));
        action("view.cameraView")->setChecked(true);
    } else if (name == QLatin1String("export-dialog")) {
        dialog =
            std::make_unique<ui::ExportDialog>(*m_window->document(), QString(), m_window.get());
        dialog->show();
        QVERIFY(QTest::qWaitForWindowExposed(dialog.get()));
        shot = dialog.get();
    }
    QVERIFY(shot);
    QTest::qWait(100);
    QApplication::processEvents();
    QImage taken = shot->grab().toImage().convertToFormat(QImage::Format_RGB32);
    // As wide as the manual's page shows without a scroll bar at its default size.
    if (taken.width() > 640)
        taken = taken.scaledToWidth(640, Qt::SmoothTransformation);
    const QString path = QStringLiteral(FINBOOK_SOURCE_DIR) +
                         QStringLiteral("/resources/manual/images/%1.png").arg(name);
    if (qEnvironmentVariableIsSet("FINBOOK_UPDATE_MANUAL_SHOTS")) {
        QDir().mkpath(QFileInfo(path).absolutePath());
        QVERIFY(taken.save(path, "PNG", 9));
        return;
    }
    const QImage stored = QImage(path).convertToFormat(QImage::Format_RGB32);
    QVERIFY2(!stored.isNull(), qPrintable(path + QStringLiteral(" is missing")));
    QCOMPARE(stored.size(), taken.size());
    // Text may be rendered a little differently from one machine to the next; the window's
    // layout may not. Compared as 8×8-pixel blocks, a block differing by more than 40 of 255 on
    // average counts as changed.
    constexpr int kBlock = 8;
    const QSize blocks(stored.width() / kBlock, stored.height() / kBlock);
    const QImage a = stored.scaled(blocks, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    const QImage b = taken.scaled(blocks, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    int changed = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const int d = (std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) +
                           std::abs(qBlue(p) - qBlue(q))) /
                          3;
            changed += d > 40;
        }
    const double share = double(changed) / double(a.width() * a.height());
    if (share > 0.02)
        taken.save(QDir::temp().filePath(QStringLiteral("manual-%1.png").arg(name)));
    QVERIFY2(share <= 0.02,
             qPrintable(QStringLiteral("%1: %2 % of the picture changed (the new one is in %3); "
                                       "FINBOOK_UPDATE_MANUAL_SHOTS=1 takes the new ones")
                            .arg(name)
                            .arg(100.0 * share, 0, 'f', 1)
                            .arg(QDir::tempPath())));
}

QTEST_MAIN(TestManual)
#include "tst_manual.moc"
