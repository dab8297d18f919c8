// Several shortcuts per action, through the real keys and the real Preferences editor: Redo on
// Ctrl+Shift+Z and Ctrl+Y, Delete and Backspace, an alternative typed into the shortcut
// editor, saved and read back; Apply Pose to Drawing has a shortcut of its own.
#include "tst_window_support.h"

#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/dialogs/preferences_dialog.h>
#include <finbook/ui/dialogs/shortcut_editor.h>
#include <finbook/ui/dialogs/shortcuts_dialog.h>
#include <finbook/ui/keys/shortcut_registry.h>
#include <finbook/ui/window/editor_state.h>

#include <QKeySequenceEdit>
#include <QSettings>
#include <QTableWidget>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;
using ui::KeyList;

namespace {
QKeySequence keys(const char *portable)
{
    return QKeySequence(QString::fromLatin1(portable), QKeySequence::PortableText);
}
} // namespace

class TestShortcuts : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }
    void init();
    void cleanup() { m_window.reset(); }

    void redoAnswersBothShortcuts();
    void deleteAndBackspaceDeleteTheSelection();
    void alternativeTypedInPreferencesWorksAndIsSaved();
    void conflictsAcrossAlternativesAreFound();
    void settingsKeepListsAndReadOldSingleValues();
    void applyPoseHasAShortcut();
    void undoIsListedByItsName();

private:
    int strokeCount() const
    {
        int n = 0;
        for (const model::StrokeGroup &g : m_window->document()->frameAt(0).groups)
            n += int(g.strokes.size());
        return n;
    }
    void draw() { dragCanvas(m_window->canvas(), {80, 80}, {300, 200}); }
    QString tool() const { return m_window->canvas()->currentTool()->id(); }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
};

void TestShortcuts::init()
{
    QSettings().remove(QStringLiteral("shortcuts"));
    m_window = std::make_unique<ui::MainWindow>();
    resetDocument(*m_window->document(), 2);
    QVERIFY(showActive(*m_window));
    m_window->canvas()->setCurrentTool(QStringLiteral("tool.pen"));
    m_window->canvas()->setFocus();
}

void TestShortcuts::redoAnswersBothShortcuts()
{
    ui::ShortcutRegistry *reg = m_window->shortcuts();
    // The file and edit commands every editor has keep their usual keys on every platform.
    for (const char *name : {"file.new", "file.open", "file.save", "file.saveAs", "edit.undo",
                             "edit.cut", "edit.copy", "edit.paste", "edit.selectAll"})
        QVERIFY2(!reg->shortcut(QString::fromLatin1(name)).isEmpty(), name);
    QCOMPARE(reg->shortcut(QStringLiteral("file.saveAs")), keys("Ctrl+Shift+S"));
    QCOMPARE(reg->shortcuts(QStringLiteral("edit.redo")),
             (KeyList{keys("Ctrl+Shift+Z"), keys("Ctrl+Y")}));
    draw();
    QCOMPARE(strokeCount(), 1);
    for (const QKeySequence &redo : {keys("Ctrl+Shift+Z"), keys("Ctrl+Y")}) {
        typeKey(Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(strokeCount(), 0);
        QTest::keySequence(static_cast<QWidget *>(nullptr), redo);
        QCOMPARE(strokeCount(), 1);
    }
}

void TestShortcuts::deleteAndBackspaceDeleteTheSelection()
{
    draw();
    for (Qt::Key key : {Qt::Key_Delete, Qt::Key_Backspace}) {
        m_window->action(QStringLiteral("edit.selectAll"))->trigger();
        QCOMPARE(m_window->editorState()->selectedStrokes().size(), std::size_t(1));
        typeKey(key);
        QCOMPARE(strokeCount(), 0);
        m_window->document()->undoStack()->undo();
        QCOMPARE(strokeCount(), 1);
    }
}

void TestShortcuts::alternativeTypedInPreferencesWorksAndIsSaved()
{
    ui::ShortcutRegistry *reg = m_window->shortcuts();
    {
        ui::PreferencesDialog dialog(m_window->preferences(), reg, m_window.get());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowActive(&dialog));
        auto *alternative =
            dialog.findChild<QKeySequenceEdit *>(QStringLiteral("tool.pen.alternative"));
        QVERIFY(alternative);
        QVERIFY(alternative->keySequence().isEmpty());
        QTest::mouseClick(alternative, Qt::LeftButton);
        QTest::keyClick(alternative, Qt::Key_N);
        QCOMPARE(dialog.shortcuts().value(QStringLiteral("tool.pen")),
                 (KeyList{keys("B"), keys("N")}));
        QVERIFY(!dialog.shortcutEditor()->hasConflicts());
        reg->apply(dialog.shortcuts());
    }
    QSettings settings;
    reg->save(settings);
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    m_window->canvas()->setFocus();
    QTRY_COMPARE(QApplication::focusWidget(), m_window->canvas());
    for (Qt::Key pen : {Qt::Key_B, Qt::Key_N}) {
        typeKey(Qt::Key_E);
        QCOMPARE(tool(), QStringLiteral("tool.eraser"));
        typeKey(pen);
        QCOMPARE(tool(), QStringLiteral("tool.pen"));
    }
    // The next window reads both back; the list of shortcuts shows both.
    m_window = std::make_unique<ui::MainWindow>();
    QCOMPARE(m_window->shortcuts()->shortcuts(QStringLiteral("tool.pen")),
             (KeyList{keys("B"), keys("N")}));
    ui::ShortcutsDialog list(m_window->shortcuts());
    auto *table = list.findChild<QTableWidget *>(QStringLiteral("shortcutsTable"));
    const QString pen = m_window->action(QStringLiteral("tool.pen"))->text().remove(u'&');
    bool listed = false;
    for (int r = 0; r < table->rowCount(); ++r)
        if (table->item(r, 0)->text() == pen)
            listed = table->item(r, 1)->text().contains(QLatin1Char('B')) &&
                     table->item(r, 1)->text().contains(QLatin1Char('N'));
    QVERIFY(listed);
    m_window->shortcuts()->resetToDefaults();
    QCOMPARE(m_window->shortcuts()->shortcuts(QStringLiteral("tool.pen")), KeyList{keys("B")});
}

void TestShortcuts::conflictsAcrossAlternativesAreFound()
{
    ui::ShortcutRegistry *reg = m_window->shortcuts();
    ui::ShortcutEditor editor(reg);
    QVERIFY(!editor.hasConflicts());
    // E as the pen's alternative clashes with the eraser's only shortcut.
    editor.edit(QStringLiteral("tool.pen"), 1)->setKeySequence(keys("E"));
    QVERIFY(editor.hasConflicts());
    const auto conflicts = ui::ShortcutRegistry::conflicts(editor.shortcuts());
    QCOMPARE(conflicts.size(), std::size_t(1));
    QCOMPARE(conflicts.front().names,
             (QStringList{QStringLiteral("tool.eraser"), QStringLiteral("tool.pen")}));
    // The same key twice for one action is no conflict, just one shortcut.
    editor.edit(QStringLiteral("tool.pen"), 1)->setKeySequence(keys("B"));
    QVERIFY(!editor.hasConflicts());
    QCOMPARE(editor.shortcuts().value(QStringLiteral("tool.pen")), KeyList{keys("B")});
}

void TestShortcuts::settingsKeepListsAndReadOldSingleValues()
{
    const QMap<QString, KeyList> chosen{
        {QStringLiteral("frame.previous"), {keys(","), keys("Left")}},
        {QStringLiteral("frame.next"), {keys("."), keys("Right")}},
        {QStringLiteral("view.showMesh"), {}}, // no shortcut at all
        {QStringLiteral("edit.preferences"), {keys("Ctrl+;")}},
    };
    ui::ShortcutRegistry *reg = m_window->shortcuts();
    reg->apply(chosen);
    {
        QSettings settings;
        reg->save(settings);
        // What an older Finbook wrote: one portable string.
        settings.setValue(QStringLiteral("shortcuts/view.fit"), QStringLiteral("Ctrl+9"));
    }
    m_window = std::make_unique<ui::MainWindow>();
    for (auto it = chosen.begin(); it != chosen.end(); ++it)
        QCOMPARE(m_window->shortcuts()->shortcuts(it.key()), it.value());
    QCOMPARE(m_window->shortcuts()->shortcuts(QStringLiteral("view.fit")), KeyList{keys("Ctrl+9")});
    QVERIFY(m_window->shortcuts()->conflicts().empty());
}

void TestShortcuts::applyPoseHasAShortcut()
{
    ui::ShortcutRegistry *reg = m_window->shortcuts();
    const QKeySequence apply = reg->shortcut(QStringLiteral("deform.apply"));
    QVERIFY(!apply.isEmpty());
    QVERIFY(reg->conflicts().empty());
    // Pin a bar at both ends, drag one pin, then apply the pose from the keyboard.
    model::Document *doc = m_window->document();
    const model::Id group = doc->frameAt(0).groups[0].id;
    auto bar = std::make_shared<model::StrokeData>();
    for (int i = 0; i <= 60; ++i)
        bar->points.push_back({100.0f + 3.0f * float(i), 150.0f, 1.0f});
    bar->width = 8.0f;
    addStroke(*doc, group, bar);
    ui::CanvasWidget *canvas = m_window->canvas();
    typeKey(Qt::Key_P);
    QCOMPARE(tool(), QStringLiteral("tool.pin"));
    for (QPointF p : {QPointF(103, 150), QPointF(277, 150)})
        QTest::mouseClick(canvas, Qt::LeftButton, {}, canvas->mapFromCanvas(p).toPoint());
    QCOMPARE(doc->group(group)->rig.pins.size(), std::size_t(2));
    QTRY_VERIFY_WITH_TIMEOUT(doc->group(group)->isDeformed(), 10000);
    dragCanvas(canvas, {277, 150}, {260, 220});
    QTRY_VERIFY_WITH_TIMEOUT(doc->group(group)->deformed &&
                                 doc->group(group)->deformed->strokes[0].back().y > 180,
                             10000);
    QVERIFY(m_window->action(QStringLiteral("deform.apply"))->isEnabled());
    QTest::keySequence(static_cast<QWidget *>(nullptr), apply);
    // The pose is the drawing; the pins stay, rebased onto it.
    QVERIFY(!doc->group(group)->rig.isPosed());
    QCOMPARE(doc->group(group)->rig.pins.size(), std::size_t(2));
    QVERIFY(doc->group(group)->strokes[0].data->points.back().y > 180);
    // Nothing posed any more: nothing to reset or apply, but the rig can still go.
    QVERIFY(!m_window->action(QStringLiteral("deform.apply"))->isEnabled());
    QVERIFY(!m_window->action(QStringLiteral("deform.reset"))->isEnabled());
    QVERIFY(m_window->action(QStringLiteral("deform.removePins"))->isEnabled());
}

// Undo's menu text names the step it would undo; the shortcut lists name the command.
void TestShortcuts::undoIsListedByItsName()
{
    draw();
    QVERIFY(m_window->action(QStringLiteral("edit.undo"))->text().size() > 6);
    ui::ShortcutsDialog list(m_window->shortcuts());
    auto *table = list.findChild<QTableWidget *>(QStringLiteral("shortcutsTable"));
    QStringList names;
    for (int r = 0; r < table->rowCount(); ++r)
        names << table->item(r, 0)->text();
    QVERIFY2(names.contains(QStringLiteral("Undo")), qPrintable(names.join(u'|')));
    QVERIFY2(names.contains(QStringLiteral("Redo")), qPrintable(names.join(u'|')));
    for (const QString &name : names)
        QVERIFY2(!name.startsWith(QStringLiteral("Undo ")), qPrintable(name));
}

QTEST_MAIN(TestShortcuts)
#include "tst_shortcuts.moc"
