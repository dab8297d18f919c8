// The main window's fill parts: the Fill tool (F), the Fill toolbar with "Close gaps", and
// Object → Fill All Enclosed Regions.
#include <finbook/model/fill/fill_commands.h>
#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/fill/tool_fill.h>
#include <finbook/ui/keys/shortcut_registry.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>

#include <QMenu>
#include <QMenuBar>
#include <QSpinBox>
#include <QStatusBar>
#include <QToolBar>

#include <cmath>

namespace finbook::ui {

namespace {
QSpinBox *createCloseGapSpinBox(model::Document *doc, QWidget *parent)
{
    auto *spin = new QSpinBox(parent);
    spin->setObjectName(QStringLiteral("fill.closeGap"));
    spin->setRange(-1, int(model::kMaxCloseGap));
    spin->setSpecialValueText(MainWindow::tr("Close gaps: automatic"));
    spin->setPrefix(MainWindow::tr("Close gaps up to "));
    spin->setSuffix(MainWindow::tr(" px"));
    spin->setToolTip(MainWindow::tr("Openings in an outline up to this wide still make a region "
                                    "the Fill tool can fill (0 = only closed outlines)"));
    spin->setKeyboardTracking(false);
    const auto sync = [doc, spin] {
        const QSignalBlocker block(spin);
        const double gap = doc->settings().closeGap;
        spin->setValue(gap < 0 ? -1 : int(std::lround(gap)));
    };
    QObject::connect(doc, &model::Document::settingsChanged, spin, sync);
    QObject::connect(doc, &model::Document::documentReset, spin, sync);
    QObject::connect(spin, &QSpinBox::valueChanged, spin, [doc](int value) {
        if (auto command = model::setCloseGapCommand(doc, value < 0 ? -1.0 : double(value)))
            doc->undoStack()->push(command.release());
    });
    sync();
    return spin;
}
} // namespace

void MainWindow::createFill()
{
    auto tool = std::make_unique<FillTool>(m_pen);
    FillTool *fill = tool.get();
    addTool(std::move(tool));
    connect(fill, &FillTool::messagePosted, this,
            [this](const QString &message) { statusBar()->showMessage(message, 6000); });

    QAction *fillAll =
        makeAction(QStringLiteral("object.fillAll"), tr("Fill All Enclosed Re&gions"));
    fillAll->setStatusTip(
        tr("Fill every closed region of the current object that has no fill, in the pen colour"));
    connect(fillAll, &QAction::triggered, this, [this] {
        auto command = model::fillAllRegionsCommand(m_doc, m_state->currentGroupId(),
                                                    m_pen->settings().color.rgba());
        if (command)
            m_doc->undoStack()->push(command.release());
        else
            statusBar()->showMessage(tr("The current object has no unfilled closed region"), 6000);
    });
    if (auto *objectMenu = menuBar()->findChild<QMenu *>(QStringLiteral("objectMenu"))) {
        objectMenu->addSeparator();
        objectMenu->addAction(fillAll);
    }

    // The tool's options: shown while the Fill tool is current, so the one row of toolbars
    // keeps its room for the pen and the deformers the rest of the time.
    auto *bar = new QToolBar(tr("Fill"), this);
    bar->setObjectName(QStringLiteral("fillToolBar"));
    bar->addWidget(createCloseGapSpinBox(m_doc, bar));
    addToolBar(Qt::TopToolBarArea, bar);
    const auto showOptions = [bar](CanvasTool *current) {
        bar->setVisible(current && current->id() == QStringLiteral("tool.fill"));
    };
    connect(m_canvas, &CanvasWidget::currentToolChanged, bar, showOptions);
    showOptions(m_canvas->currentTool());
    // Again once the window has restored its saved state (which may show the bar) and tool.
    QMetaObject::invokeMethod(
        bar, [this, showOptions] { showOptions(m_canvas->currentTool()); }, Qt::QueuedConnection);
}

} // namespace finbook::ui
