// The main window: new document, window-modified flag, open/save errors, prompts, recent
// files, shortcuts and the edit actions, all without modal dialogs (hooks are overridden).
#include "tst_tools_support.h"

#include <finbook/model/finbook_file.h>
#include <finbook/ui/dialogs/shortcuts_dialog.h>
#include <finbook/ui/keys/shortcut_registry.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

namespace {

class ScriptedWindow : public ui::MainWindow {
public:
    QStringList errors;
    int prompts = 0;
    QMessageBox::StandardButton answer = QMessageBox::Cancel;
    QString savePath;

protected:
    void reportError(const QString &, const QString &message) override
    {
        errors << message;
        emit errorReported(message);
    }
    QMessageBox::StandardButton askToSave() override
    {
        ++prompts;
        return answer;
    }
    QString askSavePath() override { return savePath; }
    QString askOpenPath() override { return {}; }
};

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }
    void init();
    void cleanup() { m_window.reset(); }

    void newDocumentHasOneFrameWithOneObject();
    void windowModifiedFollowsUndoStack();
    void drawingThroughTheWindow();
    void openMalformedFileKeepsDocument();
    void saveAndReopen();
    void unsavedChangesPrompt();
    void recentFilesPruneMissing();
    void shortcutsAreConflictFreeAndListed();
    void toolShortcutsSwitchTools();
    void userShortcutPersists();
    void editActionsFollowSelection();

private:
    void drawStroke()
    {
        ui::CanvasWidget *canvas = m_window->canvas();
        canvas->setCurrentTool(QStringLiteral("tool.pen"));
        const QSize page = m_window->document()->settings().canvasSize;
        dragCanvas(canvas, QPointF(page.width() * 0.2, page.height() * 0.3),
                   QPointF(page.width() * 0.6, page.height() * 0.5), 10);
    }
    int strokeCount() const
    {
        int n = 0;
        for (const model::StrokeGroup &g : m_window->document()->frameAt(0).groups)
            n += int(g.strokes.size());
        return n;
    }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ScriptedWindow> m_window;
    QTemporaryDir m_dir;
};

void TestMainWindow::init()
{
    m_window = std::make_unique<ScriptedWindow>();
    m_window->resize(1100, 750);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void TestMainWindow::newDocumentHasOneFrameWithOneObject()
{
    const model::Document *doc = m_window->document();
    QCOMPARE(doc->frameCount(), 1);
    QCOMPARE(doc->frameAt(0).groups.size(), std::size_t(1));
    QVERIFY(doc->undoStack()->isClean());
    QCOMPARE(doc->undoStack()->count(), 0);
    QVERIFY(!m_window->isWindowModified());
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("Untitled")));
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("[*]")));
}

void TestMainWindow::windowModifiedFollowsUndoStack()
{
    drawStroke();
    QCOMPARE(strokeCount(), 1);
    QVERIFY(m_window->isWindowModified());
    m_window->action(QStringLiteral("edit.undo"))->trigger();
    QCOMPARE(strokeCount(), 0);
    QVERIFY(!m_window->isWindowModified());
    m_window->action(QStringLiteral("edit.redo"))->trigger();
    QVERIFY(m_window->isWindowModified());
    QVERIFY(m_window->saveFile(m_dir.filePath(QStringLiteral("clean.finbook"))));
    QVERIFY(!m_window->isWindowModified());
    m_window->action(QStringLiteral("edit.undo"))->trigger();
    QVERIFY(m_window->isWindowModified()); // before the saved state is modified too
}

void TestMainWindow::drawingThroughTheWindow()
{
    // Ctrl+Z reaches the undo action through the real shortcut machinery.
    drawStroke();
    QCOMPARE(strokeCount(), 1);
    m_window->canvas()->setFocus();
    QTest::keyClick(m_window->canvas(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(strokeCount(), 0);
    QTest::keySequence(m_window->canvas(),
                       m_window->shortcuts()->shortcut(QStringLiteral("edit.redo")));
    QCOMPARE(strokeCount(), 1);
}

void TestMainWindow::openMalformedFileKeepsDocument()
{
    drawStroke();
    const QString bad = m_dir.filePath(QStringLiteral("bad.finbook"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("this is not a finbook file at all");
    f.close();
    QSignalSpy spy(m_window.get(), &ui::MainWindow::errorReported);
    QVERIFY(!m_window->openFile(bad));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(m_window->errors.size(), 1);
    QVERIFY(!m_window->errors.first().isEmpty());
    QCOMPARE(strokeCount(), 1); // nothing lost
    QVERIFY(m_window->isWindowModified());
    QVERIFY(m_window->filePath().isEmpty());
    QVERIFY(!m_window->openFile(m_dir.filePath(QStringLiteral("missing.finbook"))));
    QCOMPARE(m_window->errors.size(), 2);
    QCOMPARE(strokeCount(), 1);
}

void TestMainWindow::saveAndReopen()
{
    drawStroke();
    const QString path = m_dir.filePath(QStringLiteral("round.finbook"));
    QVERIFY(m_window->saveFile(path));
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("round.finbook")));
    const model::Stroke saved = m_window->document()->frameAt(0).groups[0].strokes[0];
    m_window->newDocument();
    QCOMPARE(strokeCount(), 0);
    QVERIFY(m_window->openFile(path));
    QCOMPARE(strokeCount(), 1);
    QCOMPARE(*m_window->document()->frameAt(0).groups[0].strokes[0].data, *saved.data);
    QVERIFY(!m_window->isWindowModified());
    QCOMPARE(m_window->recentFiles().value(0), QFileInfo(path).absoluteFilePath());
}

void TestMainWindow::unsavedChangesPrompt()
{
    QVERIFY(m_window->maybeSave()); // clean: no question
    QCOMPARE(m_window->prompts, 0);
    drawStroke();
    m_window->answer = QMessageBox::Cancel;
    QVERIFY(!m_window->close());
    QCOMPARE(m_window->prompts, 1);
    QVERIFY(m_window->isVisible());
    QCOMPARE(strokeCount(), 1);
    m_window->action(QStringLiteral("file.new"))->trigger(); // cancelled too
    QCOMPARE(strokeCount(), 1);
    m_window->answer = QMessageBox::Save;
    m_window->savePath = m_dir.filePath(QStringLiteral("prompted"));
    QVERIFY(m_window->maybeSave());
    QVERIFY(QFileInfo::exists(m_dir.filePath(QStringLiteral("prompted.finbook"))));
    drawStroke();
    m_window->answer = QMessageBox::Discard;
    QVERIFY(m_window->close());
}

void TestMainWindow::recentFilesPruneMissing()
{
    const QString a = m_dir.filePath(QStringLiteral("a.finbook"));
    const QString b = m_dir.filePath(QStringLiteral("b.finbook"));
    QVERIFY(m_window->saveFile(a));
    QVERIFY(m_window->saveFile(b));
    QCOMPARE(m_window->recentFiles().mid(0, 2), (QStringList{b, a}));
    QVERIFY(QFile::remove(a));
    QVERIFY(!m_window->recentFiles().contains(a));
    for (int i = 0; i < 12; ++i)
        QVERIFY(m_window->saveFile(m_dir.filePath(QStringLiteral("n%1.finbook").arg(i))));
    QCOMPARE(m_window->recentFiles().size(), ui::MainWindow::kMaxRecentFiles);
}

void TestMainWindow::shortcutsAreConflictFreeAndListed()
{
    ui::ShortcutRegistry *reg = m_window->shortcuts();
    const auto conflicts = reg->conflicts();
    for (const auto &c : conflicts)
        qWarning() << c.keys << c.names;
    QVERIFY(conflicts.empty());
    const auto keys = [&](const char *name) { return reg->shortcut(QString::fromLatin1(name)); };
    QCOMPARE(keys("tool.pen"), QKeySequence(Qt::Key_B));
    QCOMPARE(keys("tool.eraser"), QKeySequence(Qt::Key_E));
    QCOMPARE(keys("tool.select"), QKeySequence(Qt::Key_V));
    QCOMPARE(keys("tool.hand"), QKeySequence(Qt::Key_H));
    QCOMPARE(keys("frame.previous"), QKeySequence(Qt::Key_Comma));
    QCOMPARE(keys("frame.next"), QKeySequence(Qt::Key_Period));
    QCOMPARE(keys("playback.toggle"), QKeySequence(Qt::Key_Return));
    QCOMPARE(keys("view.onionSkin"), QKeySequence(Qt::Key_O));
    QCOMPARE(keys("view.fit"), QKeySequence(Qt::CTRL | Qt::Key_0));
    QCOMPARE(keys("view.actualSize"), QKeySequence(Qt::CTRL | Qt::Key_1));
    QCOMPARE(keys("edit.undo"), QKeySequence(QKeySequence::Undo));
    QCOMPARE(keys("file.save"), QKeySequence(QKeySequence::Save));
    for (QAction *a : reg->actions())
        QVERIFY2(a->shortcut() != QKeySequence(Qt::Key_Space), qPrintable(a->objectName()));
    ui::ShortcutsDialog dialog(reg);
    QVERIFY(dialog.rowCount() >= int(reg->actions().size()));
    QVERIFY(reg->actions().size() > 30);
}

void TestMainWindow::toolShortcutsSwitchTools()
{
    m_window->canvas()->setFocus();
    QTest::keyClick(m_window->canvas(), Qt::Key_E);
    QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.eraser"));
    QVERIFY(m_window->action(QStringLiteral("tool.eraser"))->isChecked());
    QTest::keyClick(m_window->canvas(), Qt::Key_V);
    QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.select"));
    QTest::keyClick(m_window->canvas(), Qt::Key_B);
    QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.pen"));
    QTest::keyClick(m_window->canvas(), Qt::Key_O);
    QVERIFY(m_window->editorState()->onionSkin().enabled);
}

void TestMainWindow::userShortcutPersists()
{
    ui::ShortcutRegistry *reg = m_window->shortcuts();
    reg->apply({{QStringLiteral("tool.pen"), QKeySequence(Qt::Key_N)}});
    QVERIFY(m_window->close() || true);
    m_window = std::make_unique<ScriptedWindow>();
    QCOMPARE(m_window->shortcuts()->shortcut(QStringLiteral("tool.pen")), QKeySequence(Qt::Key_N));
    m_window->shortcuts()->resetToDefaults();
    QCOMPARE(m_window->shortcuts()->shortcut(QStringLiteral("tool.pen")), QKeySequence(Qt::Key_B));
    m_window->close();
}

void TestMainWindow::editActionsFollowSelection()
{
    QAction *copy = m_window->action(QStringLiteral("edit.copy"));
    QAction *remove = m_window->action(QStringLiteral("edit.delete"));
    QVERIFY(!copy->isEnabled());
    drawStroke();
    m_window->action(QStringLiteral("edit.selectAll"))->trigger();
    QCOMPARE(m_window->editorState()->selectedStrokes().size(), std::size_t(1));
    QVERIFY(copy->isEnabled());
    copy->trigger();
    QVERIFY(m_window->action(QStringLiteral("edit.paste"))->isEnabled());
    remove->trigger();
    QCOMPARE(strokeCount(), 0);
    QVERIFY(!copy->isEnabled());
    m_window->action(QStringLiteral("edit.paste"))->trigger();
    QCOMPARE(strokeCount(), 1);
    QCOMPARE(m_window->editorState()->selectedStrokes().size(), std::size_t(1));
}

QTEST_MAIN(TestMainWindow)
#include "tst_main_window.moc"
