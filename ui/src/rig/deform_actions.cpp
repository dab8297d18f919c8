#include "rig_prompt.h"

#include <finbook/model/cage/cage_commands.h>
#include <finbook/model/pins/pin_commands.h>
#include <finbook/model/skeleton/skeleton_join_commands.h>
#include <finbook/ui/rig/deform_actions.h>
#include <finbook/ui/window/editor_state.h>

#include <QActionGroup>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QMenu>
#include <QSettings>

#include <algorithm>
#include <utility>
#include <vector>

namespace finbook::ui {

DeformActions::DeformActions(EditorState *state, QObject *parent)
    : QObject(parent)
    , m_state(state)
    , m_controller(state->document())
{
    m_reset = new QAction(tr("&Reset Pose"), this);
    m_reset->setObjectName(QStringLiteral("deform.reset"));
    m_reset->setStatusTip(
        tr("Move the current object's pins, cage corners or bones back to their rest positions"));
    m_bake = new QAction(tr("&Apply Pose to Drawing"), this);
    m_bake->setObjectName(QStringLiteral("deform.apply"));
    m_bake->setStatusTip(tr("Make the posed drawing the object's new strokes; the pins, cage or "
                            "skeleton stay where they are"));
    m_removePins = new QAction(tr("Remo&ve Rig"), this);
    m_removePins->setObjectName(QStringLiteral("deform.removePins"));
    m_removePins->setStatusTip(
        tr("Take the pins, the cage or the skeleton off the current object"));

    model::Document *doc = state->document();
    connect(m_reset, &QAction::triggered, this, [this, doc] {
        doc->undoStack()->push(new model::ResetPoseCommand(doc, m_state->currentGroupId()));
    });
    connect(m_bake, &QAction::triggered, this, [this, doc] {
        m_controller.settle(); // what becomes the drawing is the converged pose
        // A posed picture becomes a new picture, resampled once: the window says so.
        std::vector<std::pair<model::Id, const void *>> pictures;
        if (const model::Frame *frame = m_state->currentFrame())
            for (const model::StrokeGroup &g : frame->groups)
                if (g.picture)
                    pictures.emplace_back(g.id, g.picture.get());
        doc->undoStack()->push(model::makeApplyPoseCommand(doc, m_state->currentGroupId()));
        const bool resampled = std::any_of(pictures.begin(), pictures.end(), [doc](const auto &p) {
            const model::StrokeGroup *g = doc->group(p.first);
            return g && g->picture.get() != p.second;
        });
        if (resampled)
            emit messagePosted(tr("The posed picture is now the object's picture: resampled once, "
                                  "it is a little softer. Undo brings back the original."));
    });
    connect(m_removePins, &QAction::triggered, this, [this, doc] {
        const model::StrokeGroup *g = m_state->currentGroup();
        if (g && !g->rig.empty() &&
            confirmDiscardingPose(QApplication::activeWindow(), *g, ui::RigChange::Remove))
            doc->undoStack()->push(new model::RemoveRigCommand(doc, g->id));
    });
    connect(&m_controller, &model::DeformController::errorOccurred, this,
            [this](model::Id, const QString &message) { emit messagePosted(message); });
    // Folds the pins force stay in the pose (deform/arap.h): the window says so for the object
    // being worked on, and Show Mesh draws the turned-over triangles red.
    connect(&m_controller, &model::DeformController::foldsForced, this,
            [this](model::Id groupId, int triangles) {
                if (groupId == m_state->currentGroupId())
                    emit messagePosted(
                        tr("The pins fold the drawing: %n triangle(s) of its mesh turned over "
                           "where the pins leave no room (View → Show Mesh shows them red)",
                           nullptr, triangles));
            });
    connect(&m_controller, &model::DeformController::busyChanged, this, [this](bool busy) {
        emit messagePosted(busy ? tr("Preparing the deformation…") : QString());
    });
    connect(state, &EditorState::currentGroupChanged, this, &DeformActions::updateEnabled);
    connect(state, &EditorState::currentFrameChanged, this, &DeformActions::updateEnabled);
    connect(doc, &model::Document::frameChanged, this, &DeformActions::updateEnabled);
    updateEnabled();
}

QMenu *DeformActions::createRigidityMenu(QWidget *parent)
{
    auto *menu = new QMenu(tr("R&igidity"), parent);
    auto *group = new QActionGroup(menu);
    // -1: converged (the default); 0, 1, 3: the paper's two steps plus that many passes.
    const int saved = QSettings().value(QStringLiteral("deform/rigidity"), -1).toInt();
    const auto apply = [this](int choice) {
        if (choice < 0)
            m_controller.setConverged();
        else
            m_controller.setExtraPasses(choice);
    };
    apply(saved);
    const struct {
        int choice;
        QString text;
    } choices[] = {{-1, tr("Converged (Most Rigid)")},
                   {0, tr("As in the Paper (Two Steps)")},
                   {1, tr("Stiffer (+1 Pass)")},
                   {3, tr("Stiffest (+3 Passes)")}};
    for (const auto &choice : choices) {
        QAction *a = menu->addAction(choice.text);
        a->setCheckable(true);
        a->setChecked(choice.choice == saved);
        group->addAction(a);
        const int value = choice.choice;
        connect(a, &QAction::triggered, this, [apply, value] {
            apply(value);
            QSettings().setValue(QStringLiteral("deform/rigidity"), value);
        });
    }
    return menu;
}

void DeformActions::updateEnabled()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    // Any rig kind: pins, a cage or a skeleton (Remove Rig was left enabled for pins only).
    const bool rigged = g && !g->rig.empty() && !g->locked;
    const bool posed = rigged && g->rig.isPosed();
    m_reset->setEnabled(posed);
    m_bake->setEnabled(posed && g->isDeformed());
    m_removePins->setEnabled(rigged);
}

QDoubleSpinBox *DeformActions::createDensitySpinBox(QWidget *parent)
{
    auto *spin = new QDoubleSpinBox(parent);
    spin->setObjectName(QStringLiteral("deform.meshDensity"));
    spin->setRange(model::kMinMeshDensity, model::kMaxMeshDensity);
    spin->setSingleStep(0.25);
    spin->setDecimals(2);
    spin->setPrefix(tr("Mesh density "));
    spin->setToolTip(tr("How fine the current object's deformation mesh is (1 = default)"));
    spin->setKeyboardTracking(false);
    auto sync = [this, spin] {
        const model::StrokeGroup *g = m_state->currentGroup();
        const QSignalBlocker block(spin);
        spin->setEnabled(g != nullptr);
        spin->setValue(g ? g->meshDensity : model::kDefaultMeshDensity);
    };
    connect(m_state, &EditorState::currentGroupChanged, spin, sync);
    connect(m_state, &EditorState::currentFrameChanged, spin, sync);
    connect(m_state->document(), &model::Document::groupsChanged, spin, sync);
    connect(spin, &QDoubleSpinBox::editingFinished, this, [this] { ++m_densitySerial; });
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        model::Document *doc = m_state->document();
        doc->undoStack()->push(new model::SetMeshDensityCommand(doc, m_state->currentGroupId(),
                                                                value, m_densitySerial));
    });
    sync();
    return spin;
}

} // namespace finbook::ui
