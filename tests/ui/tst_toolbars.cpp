// The main window's toolbars at the size of a small laptop (1280×800): nothing moves when the
// undo text changes, and nothing an animator needs falls into an overflow menu, even with two
// more tools (Cage, Bone) and more deformation actions than today.
#include "tst_window_support.h"

#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/tool_options_bar.h>

#include <QLabel>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

namespace {
// Toolbar buttons and widgets an animator cannot reach without the overflow menu.
QStringList hiddenInOverflow(const QMainWindow &window)
{
    QStringList hidden;
    for (const QToolBar *bar : window.findChildren<QToolBar *>()) {
        if (!bar->isVisible())
            continue;
        const auto *more = bar->findChild<QToolButton *>(QStringLiteral("qt_toolbar_ext_button"));
        if (more && more->isVisible())
            hidden << bar->objectName() + QStringLiteral(" has an overflow menu");
        for (QAction *a : bar->actions()) {
            const QWidget *w = bar->widgetForAction(a);
            if (!a->isSeparator() && a->isVisible() && w && !w->isVisible())
                hidden << bar->objectName() + QLatin1Char('/') + a->text();
        }
    }
    return hidden;
}
} // namespace

class TestToolbars : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_settings = std::make_unique<IsolatedSettings>(); }
    void init()
    {
        m_window = std::make_unique<ui::MainWindow>();
        resetDocument(*m_window->document(), 2);
    }
    void cleanup() { m_window.reset(); }

    void undoButtonKeepsItsPlace();
    void nothingOverflowsAt1280();
    void toolsStandOnTheLeft();
    void toolTipsSayWhatAToolDoesAndItsKey();
    void optionsFollowTheToolInHand();

private:
    std::unique_ptr<IsolatedSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
};

void TestToolbars::undoButtonKeepsItsPlace()
{
    QVERIFY(showActive(*m_window));
    QAction *undo = m_window->action(QStringLiteral("edit.undo"));
    auto *fileBar = m_window->findChild<QToolBar *>(QStringLiteral("fileToolBar"));
    QWidget *button = fileBar->widgetForAction(undo);
    QVERIFY(button);
    // Every toolbar control, where it is before the undo text changes.
    QMap<QWidget *, QRect> before;
    for (QToolBar *bar : m_window->findChildren<QToolBar *>())
        for (QAction *a : bar->actions())
            if (QWidget *w = bar->widgetForAction(a))
                before.insert(w, QRect(w->mapTo(m_window.get(), QPoint()), w->size()));
    dragCanvas(m_window->canvas(), {40, 40}, {200, 120});
    QVERIFY(undo->isEnabled());
    QVERIFY(undo->text().size() > 6); // "Undo Draw Stroke", or the like
    QCoreApplication::processEvents();
    for (auto it = before.begin(); it != before.end(); ++it) {
        QWidget *w = it.key();
        QCOMPARE(QRect(w->mapTo(m_window.get(), QPoint()), w->size()), it.value());
    }
    // What would be undone is still said, in the tooltip.
    QVERIFY2(undo->toolTip().contains(m_window->document()->undoStack()->undoText()),
             qPrintable(undo->toolTip()));
    QVERIFY(!static_cast<QToolButton *>(button)->icon().isNull());
}

void TestToolbars::nothingOverflowsAt1280()
{
    QVERIFY(showActive(*m_window, QSize(1280, 800)));
    QCOMPARE(m_window->width(), 1280);
    // With each tool in hand: its options page is the widest thing in the top row.
    for (ui::CanvasTool *tool : m_window->canvas()->tools()) {
        m_window->canvas()->setCurrentTool(tool->id());
        QCoreApplication::processEvents();
        const QStringList hidden = hiddenInOverflow(*m_window);
        QVERIFY2(hidden.isEmpty(),
                 qPrintable(tool->id() + QStringLiteral(": ") + hidden.join(QStringLiteral(", "))));
    }
    // The deformer tools answer their keys like the others.
    m_window->canvas()->setFocus();
    typeKey(Qt::Key_K);
    QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.bone"));
    typeKey(Qt::Key_C);
    QCOMPARE(m_window->canvas()->currentTool()->id(), QStringLiteral("tool.cage"));
}

void TestToolbars::toolsStandOnTheLeft()
{
    QVERIFY(showActive(*m_window, QSize(1280, 800)));
    auto *tools = m_window->findChild<QToolBar *>(QStringLiteral("toolsToolBar"));
    QVERIFY(tools);
    QCOMPARE(m_window->toolBarArea(tools), Qt::LeftToolBarArea);
    QCOMPARE(tools->orientation(), Qt::Vertical);
    // Every other toolbar shares one row at the top: the canvas keeps its height. (The tools'
    // option pages are toolbars inside the options bar.)
    for (QToolBar *bar : m_window->findChildren<QToolBar *>(Qt::FindDirectChildrenOnly))
        if (bar != tools && bar->isVisible()) {
            QCOMPARE(m_window->toolBarArea(bar), Qt::TopToolBarArea);
            QCOMPARE(bar->y(), m_window->findChild<QToolBar *>(QStringLiteral("fileToolBar"))->y());
        }
}

void TestToolbars::toolTipsSayWhatAToolDoesAndItsKey()
{
    const QStringList ids{QStringLiteral("tool.pen"),      QStringLiteral("tool.eraser"),
                          QStringLiteral("tool.select"),   QStringLiteral("tool.eyedropper"),
                          QStringLiteral("tool.hand"),     QStringLiteral("tool.pin"),
                          QStringLiteral("tool.cage"),     QStringLiteral("tool.bone"),
                          QStringLiteral("tool.fill"),     QStringLiteral("tool.camera"),
                          QStringLiteral("tool.reference")};
    for (const QString &id : ids) {
        const ui::CanvasTool *tool = m_window->canvas()->tool(id);
        QAction *action = m_window->action(id);
        QVERIFY2(tool && action, qPrintable(id));
        QVERIFY2(!tool->description().isEmpty(), qPrintable(id));
        const QString keys = action->shortcut().toString(QKeySequence::NativeText);
        const QString expected =
            keys.isEmpty()
                ? tool->name() + QStringLiteral(": ") + tool->description()
                : QStringLiteral("%1 (%2): %3").arg(tool->name(), keys, tool->description());
        QCOMPARE(action->toolTip(), expected);
    }
    QCOMPARE(m_window->action(QStringLiteral("tool.bone"))->toolTip(),
             QStringLiteral("Bone (K): build a skeleton and pose the drawing by its bones"));
}

// One options bar: with each tool in hand it shows that tool's options and nothing of another
// tool's, and it keeps its height (the canvas does not jump when the tool changes).
void TestToolbars::optionsFollowTheToolInHand()
{
    QVERIFY(showActive(*m_window, QSize(1280, 800)));
    auto *bar = m_window->findChild<ui::ToolOptionsBar *>(QStringLiteral("toolOptionsBar"));
    QVERIFY(bar && bar->isVisible());
    const struct {
        const char *tool;
        const char *page;
        std::vector<const char *> shows;
    } expected[] = {
        {"tool.pen",
         "penOptions",
         {"penColor", "penWidth", "penSmoothing", "penStabiliser", "penPressure"}},
        {"tool.eyedropper", "penOptions", {"penColor"}},
        {"tool.eraser", "eraserOptions", {}},
        {"tool.pin", "pinOptions", {"deform.meshDensity"}},
        {"tool.cage", "cageOptions", {}},
        {"tool.bone", "boneOptions", {"skeleton.complexity.bar", "skeleton.prune.bar"}},
        {"tool.fill", "fillOptions", {"fillColor"}},
        {"tool.select", nullptr, {}},
        {"tool.hand", nullptr, {}},
    };
    const QStringList pages{QStringLiteral("penOptions"),  QStringLiteral("eraserOptions"),
                            QStringLiteral("pinOptions"),  QStringLiteral("cageOptions"),
                            QStringLiteral("boneOptions"), QStringLiteral("fillOptions")};
    const int height = bar->height();
    const int canvasTop = m_window->canvas()->mapTo(m_window.get(), QPoint()).y();
    for (const auto &e : expected) {
        const QString id = QString::fromLatin1(e.tool);
        m_window->canvas()->setCurrentTool(id);
        QCoreApplication::processEvents();
        for (const QString &page : pages) {
            auto *w = bar->findChild<QWidget *>(page);
            QVERIFY2(w, qPrintable(page));
            QCOMPARE(w->isVisible(), e.page && page == QLatin1String(e.page));
        }
        for (const char *name : e.shows) {
            auto *w = m_window->findChild<QWidget *>(QString::fromLatin1(name));
            QVERIFY2(w && w->isVisible(), qPrintable(id + QStringLiteral(": ") + name));
        }
        if (!e.page) { // a tool without options says what it does
            auto *about = bar->findChild<QLabel *>(QStringLiteral("toolOptionsAbout"));
            QVERIFY(about->isVisible());
            QVERIFY(about->text().contains(m_window->canvas()->tool(id)->description()));
        }
        QCOMPARE(bar->height(), height);
        QCOMPARE(m_window->canvas()->mapTo(m_window.get(), QPoint()).y(), canvasTop);
    }
    // The cage's corners and Fit Cage, the pins' density: only with their tools.
    m_window->canvas()->setCurrentTool(QStringLiteral("tool.pen"));
    QVERIFY(!m_window->findChild<QWidget *>(QStringLiteral("deform.meshDensity"))->isVisible());
}

QTEST_MAIN(TestToolbars)
#include "tst_toolbars.moc"
