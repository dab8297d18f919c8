// Nothing set up by hand is lost when Finbook is started again: the pen's colour, width and
// smoothing, the stabiliser, the onion-skin counts and the last tool, set through the real
// controls, are there in the next window. Settings live in a temporary folder (IsolatedSettings).
#include "tst_window_support.h"

#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/window/editor_memory.h>
#include <finbook/ui/window/editor_state.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QSpinBox>
#include <QToolButton>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

class TestEditorMemory : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        m_settings = std::make_unique<IsolatedSettings>(); // a fresh, empty store per test
        m_window = std::make_unique<ui::MainWindow>();
        QVERIFY(showActive(*m_window));
        m_window->canvas()->setFocus();
    }
    void cleanup()
    {
        m_window.reset();
        m_settings.reset();
    }

    void firstStartHasDefaults();
    void penOnionAndToolComeBack();
    void unusableValuesFallBack();

private:
    template <typename T> T *child(const QString &name) const
    {
        return m_window->findChild<T *>(name);
    }
    void restart()
    {
        m_window = std::make_unique<ui::MainWindow>(); // the old one is gone before the new
        QVERIFY(showActive(*m_window));
    }

    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
};

void TestEditorMemory::firstStartHasDefaults()
{
    QCOMPARE(m_window->penTool()->settings(), ui::PenSettings{});
    QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.pen"));
    QCOMPARE(m_window->editorState()->onionSkin(), ui::OnionSkin{});
}

void TestEditorMemory::penOnionAndToolComeBack()
{
    // A swatch, the width typed in, smoothing and onion counts by their arrows, a tool key.
    QTest::mouseClick(child<QToolButton>(QStringLiteral("swatch#d03030")), Qt::LeftButton);
    clickIntoText(child<QDoubleSpinBox>(QStringLiteral("penWidth")));
    typeText(QStringLiteral("7.5"));
    typeKey(Qt::Key_Return);
    auto *smoothing = child<QSpinBox>(QStringLiteral("penSmoothing"));
    clickSpinArrow(smoothing, true);
    auto *stabiliser = child<QSpinBox>(QStringLiteral("penStabiliser"));
    clickSpinArrow(stabiliser, true);
    clickSpinArrow(stabiliser, true);
    QTest::mouseClick(child<QCheckBox>(QStringLiteral("penPressure")), Qt::LeftButton);
    clickSpinArrow(child<QSpinBox>(QStringLiteral("timeline.onionBefore")), true);
    clickSpinArrow(child<QSpinBox>(QStringLiteral("timeline.onionBefore")), true);
    clickSpinArrow(child<QSpinBox>(QStringLiteral("timeline.onionAfter")), false);
    QTRY_COMPARE(QApplication::focusWidget(), m_window->canvas());
    typeKey(Qt::Key_O); // onion skin on
    typeKey(Qt::Key_E);
    const ui::PenSettings pen = m_window->penTool()->settings();
    QCOMPARE(pen.color, QColor(0xd0, 0x30, 0x30));
    QCOMPARE(pen.width, 7.5);
    QCOMPARE(pen.smoothing, ui::PenSettings{}.smoothing + 1);
    QCOMPARE(pen.stabiliser, 2);
    QVERIFY(!pen.pressure);
    const ui::OnionSkin onion = m_window->editorState()->onionSkin();
    QCOMPARE(onion.before, 3);
    QCOMPARE(onion.after, 0);
    QVERIFY(onion.enabled);

    restart();
    QCOMPARE(m_window->penTool()->settings(), pen);
    QCOMPARE(m_window->editorState()->onionSkin(), onion);
    QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.eraser"));
    QVERIFY(m_window->action(QStringLiteral("tool.eraser"))->isChecked());
    // The controls show what came back.
    QCOMPARE(child<QDoubleSpinBox>(QStringLiteral("penWidth"))->value(), 7.5);
    QCOMPARE(child<QSpinBox>(QStringLiteral("penStabiliser"))->value(), 2);
    QVERIFY(!child<QCheckBox>(QStringLiteral("penPressure"))->isChecked());
    QCOMPARE(child<QSpinBox>(QStringLiteral("timeline.onionBefore"))->value(), 3);
    QCOMPARE(child<QSpinBox>(QStringLiteral("timeline.onionAfter"))->value(), 0);
    QVERIFY(m_window->action(QStringLiteral("view.onionSkin"))->isChecked());
}

void TestEditorMemory::unusableValuesFallBack()
{
    m_window.reset();
    {
        QSettings settings;
        settings.setValue(QStringLiteral("editor/pen/color"), QStringLiteral("not a colour"));
        settings.setValue(QStringLiteral("editor/pen/width"), QStringLiteral("nan"));
        settings.setValue(QStringLiteral("editor/pen/smoothing"), 999);
        settings.setValue(QStringLiteral("editor/pen/stabiliser"), -5);
        settings.setValue(QStringLiteral("editor/tool"), QStringLiteral("tool.gone"));
        settings.setValue(QStringLiteral("preferences/onion/before"), -4);
    }
    restart();
    const ui::PenSettings pen = m_window->penTool()->settings();
    QCOMPARE(pen.color, ui::PenSettings{}.color);
    QCOMPARE(pen.width, ui::PenSettings{}.width);
    QCOMPARE(pen.smoothing, ui::PenTool::kMaxSmoothing);
    QCOMPARE(pen.stabiliser, 0);
    QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.pen"));
    QCOMPARE(m_window->editorState()->onionSkin().before, 0);
}

QTEST_MAIN(TestEditorMemory)
#include "tst_editor_memory.moc"
