#include "../rig/rig_prompt.h"
#include "cage_paint.h"

#include <finbook/model/cage/cage_commands.h>
#include <finbook/model/cage/cage_setup.h>
#include <finbook/ui/cage/cage_actions.h>
#include <finbook/ui/cage/tool_cage.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <QApplication>
#include <QPainter>
#include <QSettings>
#include <QSpinBox>

#include <algorithm>

namespace finbook::ui {

namespace {
const QString kCornersKey = QStringLiteral("cage/fitCorners");
} // namespace

CageActions::CageActions(EditorState *state, model::DeformController *controller, CageTool *tool,
                         QObject *parent)
    : QObject(parent)
    , m_state(state)
    , m_controller(controller)
    , m_tool(tool)
    , m_corners(std::clamp(QSettings().value(kCornersKey, model::kDefaultFitCageCorners).toInt(),
                           model::kMinFitCageCorners, model::kMaxFitCageCorners))
{
    m_fit = new QAction(tr("&Fit Cage"), this);
    m_fit->setObjectName(QStringLiteral("cage.fit"));
    m_fit->setStatusTip(tr("Put a coarse cage around the current object in one step"));
    m_fit->setShortcut(QKeySequence(tr("Shift+C")));
    m_editShape = new QAction(tr("Edit Cage &Shape"), this);
    m_editShape->setObjectName(QStringLiteral("cage.editShape"));
    m_editShape->setCheckable(true);
    m_editShape->setStatusTip(
        tr("Change the cage itself (move, add or delete corners) instead of posing with it"));
    connect(m_fit, &QAction::triggered, this, [this] { fitCage(); });
    connect(m_editShape, &QAction::toggled, m_tool, &CageTool::setEditingShape);
    connect(m_tool, &CageTool::editingShapeChanged, m_editShape, &QAction::setChecked);
    connect(state, &EditorState::currentGroupChanged, this, &CageActions::updateEnabled);
    connect(state, &EditorState::currentFrameChanged, this, &CageActions::updateEnabled);
    connect(state->document(), &model::Document::frameChanged, this, &CageActions::updateEnabled);
    updateEnabled();
}

void CageActions::setFitCorners(int corners)
{
    corners = std::clamp(corners, model::kMinFitCageCorners, model::kMaxFitCageCorners);
    if (corners == m_corners)
        return;
    m_corners = corners;
    QSettings().setValue(kCornersKey, corners);
    emit fitCornersChanged(corners);
}

QSpinBox *CageActions::createCornersSpinBox(QWidget *parent)
{
    auto *spin = new QSpinBox(parent);
    spin->setObjectName(QStringLiteral("cage.fitCorners"));
    spin->setRange(model::kMinFitCageCorners, model::kMaxFitCageCorners);
    spin->setValue(m_corners);
    spin->setPrefix(tr("Corners "));
    spin->setToolTip(tr("About how many corners Fit Cage gives the cage"));
    spin->setKeyboardTracking(false);
    connect(spin, &QSpinBox::valueChanged, this, &CageActions::setFitCorners);
    connect(this, &CageActions::fitCornersChanged, spin, [spin](int corners) {
        const QSignalBlocker block(spin);
        spin->setValue(corners);
    });
    return spin;
}

bool CageActions::fitCage()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    if (!g || !g->hasContent() || g->locked) {
        emit messagePosted(tr("Choose an unlocked object with strokes to fit a cage to."));
        return false;
    }
    auto cage = model::fitCage(*g, m_corners, m_state->document()->settings().closeGap);
    if (!cage) {
        emit messagePosted(cage.error());
        return false;
    }
    if (!confirmDiscardingPose(QApplication::activeWindow(), *g))
        return false;
    model::Document *doc = m_state->document();
    doc->undoStack()->push(new model::PlaceCageCommand(doc, g->id, std::move(*cage)));
    m_controller->prepare(g->id);
    return true;
}

void CageActions::updateEnabled()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    m_fit->setEnabled(g && g->hasContent() && !g->locked);
}

CageOverlay::CageOverlay(EditorState *state, CageTool *tool)
    : m_state(state)
    , m_tool(tool)
{}

void CageOverlay::paint(QPainter &painter, const QTransform &canvasToWidget)
{
    const model::Frame *f =
        m_tool->canvas() ? m_tool->canvas()->shownFrame() : m_state->currentFrame();
    if (!f)
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setBrush(Qt::NoBrush);
    const model::Id current = m_state->currentGroupId();
    for (const model::StrokeGroup &g : f->groups) {
        if (!g.visible || g.rig.kind() != model::RigKind::Cage)
            continue;
        const bool focus = g.id == current;
        const QColor ink = focus ? QColor(40, 120, 220) : QColor(130, 130, 130);
        // Rest outline faint, posed cage bold (in Edit Shape the rest cage is the bold one).
        const bool shape = focus && m_tool->editingShape();
        painter.setPen(QPen(QColor(ink.red(), ink.green(), ink.blue(), 90), 1, Qt::DashLine));
        painter.drawPolygon(
            mappedPolygon(canvasToWidget, shape ? g.rig.cage.posed : g.rig.cage.rest));
        // A posed cage that crosses itself still deforms; it is tinted as a warning.
        const bool crossed = model::cageCrossesItself(g.rig.cage.posed);
        painter.setPen(QPen(crossed ? QColor(220, 50, 40) : ink, focus ? 2.0 : 1.2));
        painter.drawPolygon(
            mappedPolygon(canvasToWidget, shape ? g.rig.cage.rest : g.rig.cage.posed));
    }
    painter.restore();
}

} // namespace finbook::ui
