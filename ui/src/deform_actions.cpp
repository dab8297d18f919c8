#include <finbook/model/pin_commands.h>
#include <finbook/ui/deform_actions.h>
#include <finbook/ui/editor_state.h>

#include <QActionGroup>
#include <QDoubleSpinBox>
#include <QMenu>
#include <QSettings>

namespace finbook::ui {

DeformActions::DeformActions(EditorState *state, QObject *parent)
    : QObject(parent)
    , m_state(state)
    , m_controller(state->document())
{
    m_reset = new QAction(tr("&Reset Pose"), this);
    m_reset->setObjectName(QStringLiteral("deform.reset"));
    m_reset->setStatusTip(tr("Move every pin of the current object back to where it was put"));
    m_bake = new QAction(tr("&Apply Pose to Drawing"), this);
    m_bake->setObjectName(QStringLiteral("deform.apply"));
    m_bake->setStatusTip(tr("Make the bent drawing the object's new strokes and remove its pins"));
    m_removePins = new QAction(tr("Remove All &Pins"), this);
    m_removePins->setObjectName(QStringLiteral("deform.removePins"));

    model::Document *doc = state->document();
    connect(m_reset, &QAction::triggered, this, [this, doc] {
        doc->undoStack()->push(new model::ResetDeformationCommand(doc, m_state->currentGroupId()));
    });
    connect(m_bake, &QAction::triggered, this, [this, doc] {
        doc->undoStack()->push(new model::BakeDeformationCommand(doc, m_state->currentGroupId()));
    });
    connect(m_removePins, &QAction::triggered, this, [this, doc] {
        const model::StrokeGroup *g = m_state->currentGroup();
        if (!g || g->pins.empty())
            return;
        doc->undoStack()->beginMacro(tr("Remove All Pins"));
        for (const model::Pin &p : std::vector<model::Pin>(g->pins))
            doc->undoStack()->push(new model::RemovePinCommand(doc, g->id, p.id));
        doc->undoStack()->endMacro();
    });
    connect(&m_controller, &model::DeformController::errorOccurred, this,
            [this](model::Id, const QString &message) { emit messagePosted(message); });
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
    const int saved = QSettings().value(QStringLiteral("deform/extraPasses"), 0).toInt();
    m_controller.setExtraPasses(saved);
    const struct {
        int passes;
        QString text;
    } choices[] = {{0, tr("As in the Paper (Two Steps)")},
                   {1, tr("Stiffer (+1 Pass)")},
                   {3, tr("Stiffest (+3 Passes)")}};
    for (const auto &choice : choices) {
        QAction *a = menu->addAction(choice.text);
        a->setCheckable(true);
        a->setChecked(choice.passes == m_controller.extraPasses());
        group->addAction(a);
        const int passes = choice.passes;
        connect(a, &QAction::triggered, this, [this, passes] {
            m_controller.setExtraPasses(passes);
            QSettings().setValue(QStringLiteral("deform/extraPasses"), passes);
        });
    }
    return menu;
}

void DeformActions::updateEnabled()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    const bool pinned = g && !g->pins.empty() && !g->locked;
    m_reset->setEnabled(pinned);
    m_bake->setEnabled(pinned && g->isDeformed());
    m_removePins->setEnabled(pinned);
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
