// File > Export...: the dialog's defaults follow the document, the export runs on a worker
// thread while the GUI thread keeps handling events, files are replaced only after asking,
// Cancel leaves nothing, failures reach the user, and the File menu opens it.
#include "../model/export_support.h"
#include "tst_tools_support.h"

#include <finbook/model/document.h>
#include <finbook/ui/export/export_dialog.h>
#include <finbook/ui/export/export_done.h>
#include <finbook/ui/export/export_job.h>
#include <finbook/ui/window/main_window.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;
using model::ExportFormat;

namespace {

class ScriptedDialog : public ui::ExportDialog {
public:
    using ui::ExportDialog::ExportDialog;
    bool replace = false;
    QStringList askedAbout;
    QStringList failures;
    bool allowLarge = false;
    QStringList largeQuestions;

protected:
    bool confirmLargeExport(const QString &message) override
    {
        largeQuestions << message;
        return allowLarge;
    }
    bool confirmOverwrite(const QStringList &existing) override
    {
        askedAbout = existing;
        return replace;
    }
    void showFailure(const QString &message, const QString &) override { failures << message; }
};

void loadInto(model::Document &doc, int hold)
{
    model::ExportSource source = loadExample();
    for (model::Frame &f : source.frames)
        f.hold = hold;
    doc.reset(std::move(source.frames), source.settings, 1000000);
}

} // namespace

class TestExportDialog : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void defaultsFollowTheDocument();
    void exportRunsOffTheGuiThread();
    void gifThroughTheDialog();
    void replacingAsksFirst();
    void largeExportAsksFirst();
    void cancelLeavesNothing();
    void failureIsShown();
    void fileMenuOpensTheDialog();
    void finishedExportShowsWhereItWent();
    void objExportsTheCurrentFrame();

private:
    std::unique_ptr<IsolatedSettings> m_settings;
    QTemporaryDir m_dir;
};

void TestExportDialog::initTestCase()
{
    m_settings = std::make_unique<IsolatedSettings>();
    QVERIFY(m_dir.isValid());
}

void TestExportDialog::defaultsFollowTheDocument()
{
    model::Document doc;
    loadInto(doc, 1);
    model::DocumentSettings s = doc.settings();
    s.fps = 8;
    s.loop = false;
    doc.setSettings(s);
    ScriptedDialog dialog(doc, QStringLiteral("/films/walk.finbook"));
    QCOMPARE(dialog.fpsBox()->value(), 8);
    QVERIFY(!dialog.loopBox()->isChecked());
    QCOMPARE(dialog.options().format, ExportFormat::Gif);
    QCOMPARE(dialog.options().target, QStringLiteral("/films/walk.gif"));
    QCOMPARE(dialog.options().firstFrame, -1); // the play range

    dialog.setFormat(ExportFormat::Mp4);
    QCOMPARE(dialog.options().target, QStringLiteral("/films/walk.mp4"));
    auto *items = qobject_cast<QStandardItemModel *>(dialog.backgroundBox()->model());
    QVERIFY(!items->item(int(ui::ExportDialog::Background::Transparent))->isEnabled());
    QVERIFY(!dialog.loopBox()->isEnabled());
    dialog.setFormat(ExportFormat::PngSequence);
    QCOMPARE(dialog.options().target, QStringLiteral("/films/walk"));
    QVERIFY(dialog.perDrawingBox()->isEnabled());
    QVERIFY(items->item(int(ui::ExportDialog::Background::Transparent))->isEnabled());
    dialog.backgroundBox()->setCurrentIndex(int(ui::ExportDialog::Background::Transparent));
    dialog.scaleBox()->setValue(0.5);
    dialog.rangeBox()->setCurrentIndex(int(ui::ExportDialog::Range::Custom));
    dialog.firstFrameBox()->setValue(3);
    dialog.lastFrameBox()->setValue(5);
    const model::ExportOptions o = dialog.options();
    QVERIFY(o.transparent);
    QCOMPARE(o.scale, 0.5);
    QCOMPARE(o.firstFrame, 2);
    QCOMPARE(o.lastFrame, 4);
    QVERIFY(dialog.findChildren<QLabel *>().size() > 0);
    bool sizeShown = false;
    for (QLabel *label : dialog.findChildren<QLabel *>())
        sizeShown |= label->text().contains(QLatin1String("640 x 360"));
    QVERIFY(sizeShown);
    // MP4 cannot be transparent: choosing it falls back to the document background.
    dialog.setFormat(ExportFormat::Mp4);
    QVERIFY(!dialog.options().transparent);
}

void TestExportDialog::exportRunsOffTheGuiThread()
{
    model::Document doc;
    loadInto(doc, 20); // 240 files: long enough to watch
    ScriptedDialog dialog(doc, QString());
    dialog.setFormat(ExportFormat::PngSequence);
    dialog.scaleBox()->setValue(0.25);
    const QString folder = m_dir.filePath(QStringLiteral("thread"));
    dialog.setTarget(folder);
    QThread *worker = nullptr;
    qint64 guiEventsDuringExport = 0;
    QTimer ticker;
    connect(&ticker, &QTimer::timeout, this,
            [&] { guiEventsDuringExport += dialog.isExporting(); });
    ticker.start(0);
    connect(&dialog, &ui::ExportDialog::exportStarted, this, [&] {
        connect(
            dialog.job(), &ui::ExportJob::progressed, dialog.job(),
            [&] { worker = QThread::currentThread(); }, Qt::DirectConnection);
    });
    QSignalSpy finished(&dialog, &ui::ExportDialog::exportFinished);
    QTest::mouseClick(dialog.exportButton(), Qt::LeftButton);
    QVERIFY(dialog.isExporting());
    QVERIFY(dialog.cancelButton()->isVisible() || !dialog.isVisible());
    QVERIFY(finished.wait(120000));
    ticker.stop();
    QCOMPARE(finished.first().first().toBool(), true);
    QVERIFY(worker != nullptr);
    QVERIFY(worker != QThread::currentThread());
    QVERIFY2(guiEventsDuringExport > 0, "the GUI thread handled no events while exporting");
    QCOMPARE(QDir(folder).entryList(QDir::Files).size(), qsizetype(240));
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
    QVERIFY(dialog.summary().contains(QLatin1String("240")));
    QVERIFY(dialog.progressBar()->value() == dialog.progressBar()->maximum());
}

void TestExportDialog::gifThroughTheDialog()
{
    if (program("ffmpeg").isEmpty() || program("ffprobe").isEmpty())
        QSKIP("ffmpeg/ffprobe not installed (bash .ci/setup installs them)");
    model::Document doc;
    loadInto(doc, 2);
    ScriptedDialog dialog(doc, QString());
    dialog.setFormat(ExportFormat::Gif);
    dialog.scaleBox()->setValue(0.25);
    const QString gif = m_dir.filePath(QStringLiteral("dialog.gif"));
    dialog.setTarget(gif);
    QSignalSpy finished(&dialog, &ui::ExportDialog::exportFinished);
    QTest::mouseClick(dialog.exportButton(), Qt::LeftButton);
    QVERIFY(finished.wait(120000));
    QVERIFY2(finished.first().first().toBool(),
             qPrintable(dialog.failures.join(QLatin1Char('\n'))));
    const QJsonObject stream = probe(gif);
    QCOMPARE(stream[QStringLiteral("width")].toInt(), 320);
    QCOMPARE(stream[QStringLiteral("nb_read_frames")].toString().toInt(), 12);
    double seconds = 0;
    for (double d : frameDurations(gif))
        seconds += d;
    QVERIFY(std::abs(seconds - 2.0) < 0.02); // 24 ticks at 12 fps
}

void TestExportDialog::replacingAsksFirst()
{
    model::Document doc;
    loadInto(doc, 1);
    const QString page = m_dir.filePath(QStringLiteral("page.html"));
    QFile old(page);
    QVERIFY(old.open(QIODevice::WriteOnly));
    old.write("old");
    old.close();
    ScriptedDialog dialog(doc, QString());
    dialog.setFormat(ExportFormat::Html);
    dialog.setTarget(page);
    dialog.replace = false;
    QTest::mouseClick(dialog.exportButton(), Qt::LeftButton);
    QCOMPARE(dialog.askedAbout, QStringList{page});
    QVERIFY(!dialog.isExporting());
    QCOMPARE(QFileInfo(page).size(), qint64(3));
    dialog.replace = true;
    QSignalSpy finished(&dialog, &ui::ExportDialog::exportFinished);
    QTest::mouseClick(dialog.exportButton(), Qt::LeftButton);
    QVERIFY(finished.wait(60000));
    QVERIFY(finished.first().first().toBool());
    QVERIFY(QFileInfo(page).size() > 10000);
}

// 12 drawings held 1,000 ticks at 1 fps: 3.3 hours, beyond the 3 hours an export may take
// without a yes. No: nothing happens. Yes: the export runs with the limit raised to it.
void TestExportDialog::largeExportAsksFirst()
{
    model::Document doc;
    loadInto(doc, 1000);
    const QString page = m_dir.filePath(QStringLiteral("long.html"));
    ScriptedDialog dialog(doc, QString());
    dialog.setFormat(ExportFormat::Html);
    dialog.setTarget(page);
    dialog.fpsBox()->setValue(1);
    QTest::mouseClick(dialog.exportButton(), Qt::LeftButton);
    QCOMPARE(dialog.largeQuestions.size(), 1);
    QVERIFY2(dialog.largeQuestions.first().contains(QLatin1String("12000")),
             qPrintable(dialog.largeQuestions.first()));
    QVERIFY(!dialog.isExporting());
    QVERIFY(!QFileInfo::exists(page));
    dialog.allowLarge = true;
    QSignalSpy finished(&dialog, &ui::ExportDialog::exportFinished);
    QTest::mouseClick(dialog.exportButton(), Qt::LeftButton);
    QVERIFY(finished.wait(60000));
    QVERIFY(finished.first().first().toBool());
    QVERIFY(dialog.failures.isEmpty());
    QVERIFY(QFileInfo(page).size() > 10000);
}

void TestExportDialog::cancelLeavesNothing()
{
    model::Document doc;
    loadInto(doc, 40); // 480 files: Cancel arrives long before the end
    ScriptedDialog dialog(doc, QString());
    dialog.setFormat(ExportFormat::PngSequence);
    const QString folder = m_dir.filePath(QStringLiteral("cancelled/frames"));
    dialog.setTarget(folder);
    connect(&dialog, &ui::ExportDialog::exportStarted, this, [&] {
        connect(dialog.job(), &ui::ExportJob::progressed, &dialog,
                [&] { QTest::mouseClick(dialog.cancelButton(), Qt::LeftButton); });
    });
    QSignalSpy finished(&dialog, &ui::ExportDialog::exportFinished);
    dialog.show();
    QTest::mouseClick(dialog.exportButton(), Qt::LeftButton);
    QVERIFY(finished.wait(120000));
    QCOMPARE(finished.first().first().toBool(), false);
    QVERIFY(dialog.failures.isEmpty()); // a cancel is not an error
    QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("cancelled"))));
    QVERIFY(dialog.isVisible());
    QVERIFY(dialog.exportButton()->isVisible());
    QVERIFY(dialog.formatBox()->isEnabled());
}

void TestExportDialog::failureIsShown()
{
    model::Document doc;
    loadInto(doc, 1);
    const QString plain = m_dir.filePath(QStringLiteral("plain.txt"));
    QFile f(plain);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.close();
    ScriptedDialog dialog(doc, QString());
    dialog.setFormat(ExportFormat::PngSequence);
    dialog.setTarget(plain + QStringLiteral("/frames"));
    QSignalSpy finished(&dialog, &ui::ExportDialog::exportFinished);
    QTest::mouseClick(dialog.exportButton(), Qt::LeftButton);
    QVERIFY(finished.wait(60000));
    QCOMPARE(dialog.failures.size(), 1);
    QVERIFY(dialog.failures.first().contains(QLatin1String("frames")));
}

void TestExportDialog::fileMenuOpensTheDialog()
{
    ui::MainWindow window;
    QAction *action = window.action(QStringLiteral("file.export"));
    QVERIFY(action);
    // Issue 22, item 9: one export entry in the File menu (it was "Export..." and "Export
    // Frames..."), with the shortcut Export Frames had.
    QCOMPARE(action->shortcut(), QKeySequence(QStringLiteral("Ctrl+Shift+E")));
    const QMenu *file = nullptr;
    for (QObject *o : action->associatedObjects())
        if (auto *menu = qobject_cast<QMenu *>(o))
            file = menu;
    QVERIFY(file);
    int exports = 0;
    for (const QAction *a : file->actions())
        exports += a->text().remove(QLatin1Char('&')).startsWith(QLatin1String("Export"));
    QCOMPARE(exports, 1);
    bool opened = false;
    QTimer::singleShot(0, this, [&] {
        auto *dialog = qobject_cast<ui::ExportDialog *>(QApplication::activeModalWidget());
        opened = dialog != nullptr;
        if (dialog)
            dialog->reject();
    });
    action->trigger();
    QVERIFY(opened);
}

// Issue 22, item 9: a finished export says where the files went and opens their folder (and an
// HTML page in the browser) on request.
void TestExportDialog::finishedExportShowsWhereItWent()
{
    QWidget parent;
    QList<QUrl> opened;
    const auto open = [&opened](const QUrl &url) {
        opened << url;
        return true;
    };
    const QString page = m_dir.filePath(QStringLiteral("walk.html"));
    QPointer<QMessageBox> box = ui::showExportDone(
        &parent, QStringLiteral("Exported 1 file to ") + page, {page}, page, open);
    QVERIFY(box && box->isVisible());
    QVERIFY(!box->isModal());
    QVERIFY(box->text().contains(page));
    auto *browse = box->findChild<QPushButton *>(QStringLiteral("export.openBrowser"));
    QVERIFY(browse);
    browse->click();
    QCOMPARE(opened, QList<QUrl>{QUrl::fromLocalFile(page)});
    // Frames: no browser, the folder they fill.
    const QStringList frames{m_dir.filePath(QStringLiteral("f/frame_0001.png")),
                             m_dir.filePath(QStringLiteral("f/frame_0002.png"))};
    box = ui::showExportDone(&parent, QStringLiteral("Exported 2 files"), frames, {}, open);
    QVERIFY(!box->findChild<QPushButton *>(QStringLiteral("export.openBrowser")));
    box->findChild<QPushButton *>(QStringLiteral("export.showFolder"))->click();
    QCOMPARE(opened.last(), QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("f"))));
}

// Issue 27: the 3D model (OBJ) is the current frame; the fields that do not apply to it are
// disabled and the dialog says why. It writes what `finbook export --frame` writes.
void TestExportDialog::objExportsTheCurrentFrame()
{
    model::Document doc;
    loadInto(doc, 1);
    ScriptedDialog dialog(doc, QStringLiteral("/films/walk.finbook"));
    dialog.setCurrentFrame(4);
    dialog.setFormat(ExportFormat::Obj);
    QCOMPARE(dialog.options().target, QStringLiteral("/films/walk.obj"));
    QCOMPARE(dialog.options().firstFrame, 4);
    QCOMPARE(dialog.options().lastFrame, 4);
    const QList<QWidget *> unused{dialog.rangeBox(), dialog.firstFrameBox(), dialog.lastFrameBox(),
                                  dialog.scaleBox(), dialog.backgroundBox(), dialog.fpsBox(),
                                  dialog.loopBox(),  dialog.perDrawingBox()};
    for (QWidget *field : unused)
        QVERIFY(!field->isEnabled());
    bool explained = false;
    for (QLabel *label : dialog.findChildren<QLabel *>())
        explained |= label->text().contains(QLatin1String("current frame (5)"));
    QVERIFY(explained);
    dialog.setFormat(ExportFormat::Gif);
    QVERIFY(dialog.rangeBox()->isEnabled() && dialog.scaleBox()->isEnabled() &&
            dialog.fpsBox()->isEnabled());
    QCOMPARE(dialog.options().firstFrame, -1);

    dialog.setFormat(ExportFormat::Obj);
    const QString target = m_dir.filePath(QStringLiteral("frame5.obj"));
    dialog.setTarget(target);
    QSignalSpy finished(&dialog, &ui::ExportDialog::exportFinished);
    QTest::mouseClick(dialog.exportButton(), Qt::LeftButton);
    QVERIFY(finished.wait(120000));
    QVERIFY2(finished.first().first().toBool(),
             qPrintable(dialog.failures.join(QLatin1Char('\n'))));
    const QString mtl = m_dir.filePath(QStringLiteral("frame5.mtl"));
    QCOMPARE(dialog.writtenFiles(), QStringList({target, mtl}));
    QVERIFY2(dialog.summary().contains(QLatin1String("2")), qPrintable(dialog.summary()));

    // The same bytes as the model's export of frame 5.
    QTemporaryDir other;
    model::ExportOptions options;
    options.format = ExportFormat::Obj;
    options.target = other.filePath(QStringLiteral("frame5.obj"));
    options.firstFrame = options.lastFrame = 4;
    QVERIFY(model::exportAnimation(model::exportSource(doc), options));
    QFile a(target), b(options.target);
    QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
    QCOMPARE(a.readAll(), b.readAll());
}

QTEST_MAIN(TestExportDialog)
#include "tst_export_dialog.moc"
