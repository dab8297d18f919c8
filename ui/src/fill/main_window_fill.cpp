// The main window's fill parts: the Fill tool (F), the Fill toolbar with "Close gaps", and
// Object → Fill All Enclosed Regions.
#include "close_gap_box.h"

#include <finbook/model/fill/fill_commands.h>
#include <finbook/model/fill/fill_regions.h>
#include <finbook/ui/canvas/canvas_tool.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/fill/tool_fill.h>
#include <finbook/ui/keys/shortcut_registry.h>
#include <finbook/ui/tools/tool_pen.h>
#include <finbook/ui/widgets/color_button.h>
#include <finbook/ui/window/editor_state.h>
#include <finbook/ui/window/main_window.h>
#include <finbook/ui/window/tool_options_bar.h>

#include <QElapsedTimer>
#include <QMenu>
#include <QMenuBar>
#include <QSpinBox>
#include <QStatusBar>
#include <QToolBar>

#include <cmath>
#include <memory>

namespace finbook::ui {

namespace {
QSpinBox *createCloseGapSpinBox(EditorState *state, QWidget *parent)
{
    model::Document *doc = state->document();
    auto *spin = new CloseGapBox(
        [state] {
            const model::StrokeGroup *g = state->currentGroup();
            return g ? model::objectRegions(*g, -1.0)->regions().closeGap : -1.0;
        },
        parent);
    spin->setObjectName(QStringLiteral("fill.closeGap"));
    spin->setRange(-1, int(model::kMaxCloseGap));
    spin->setPrefix(MainWindow::tr("Close gaps up to "));
    spin->setSuffix(MainWindow::tr(" px"));
    spin->setToolTip(MainWindow::tr("Openings in an outline up to this wide still make a region "
                                    "the Fill tool can fill (0 = only closed outlines)"));
    spin->setKeyboardTracking(false);
    const auto sync = [doc, spin] {
        const QSignalBlocker block(spin);
        if (spin->isVisible()) // else when it shows: no regions while the pen draws
            spin->refreshAutomatic();
        const double gap = doc->settings().closeGap;
        spin->setValue(gap < 0 ? -1 : int(std::lround(gap)));
    };
    QObject::connect(doc, &model::Document::settingsChanged, spin, sync);
    QObject::connect(doc, &model::Document::documentReset, spin, sync);
    QObject::connect(doc, &model::Document::groupsChanged, spin, sync);
    QObject::connect(state, &EditorState::currentGroupChanged, spin, sync);
    QObject::connect(state, &EditorState::currentFrameChanged, spin, sync);
    // One undo step per burst of arrow clicks (the canvas takes the focus back after each, so
    // focus cannot mark the end of a session): a change more than 1.5 s after the last starts
    // a new step.
    struct Session {
        int serial = 0;
        QElapsedTimer sinceLast;
    };
    auto session = std::make_shared<Session>();
    QObject::connect(spin, &QSpinBox::valueChanged, spin, [doc, session](int value) {
        if (!session->sinceLast.isValid() || session->sinceLast.elapsed() > 1500)
            ++session->serial;
        session->sinceLast.start();
        if (auto command =
                model::setCloseGapCommand(doc, value < 0 ? -1.0 : double(value), session->serial))
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

    // The Fill tool's options: the pen's colour (which it fills with) and the gap size.
    QToolBar *page =
        m_options->newPage(QStringLiteral("fillOptions"), {QStringLiteral("tool.fill")});
    auto *colour = new ColorButton(m_pen->settings().color, page);
    colour->setObjectName(QStringLiteral("fillColor"));
    colour->setToolTip(tr("The colour the Fill tool fills with (the pen's)"));
    connect(colour, &ColorButton::colorChanged, m_pen, [this](const QColor &c) {
        PenSettings s = m_pen->settings();
        s.color = c;
        m_pen->setSettings(s);
    });
    connect(m_pen, &PenTool::settingsChanged, colour, [this, colour] {
        const QSignalBlocker quiet(colour);
        colour->setColor(m_pen->settings().color);
    });
    page->addWidget(colour);
    page->addSeparator();
    page->addWidget(createCloseGapSpinBox(m_state, page));
}

} // namespace finbook::ui
