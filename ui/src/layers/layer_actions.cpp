#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/scene/shot.h>
#include <finbook/ui/layers/cel_editing.h>
#include <finbook/ui/layers/layer_actions.h>
#include <finbook/ui/layers/layer_properties_dialog.h>
#include <finbook/ui/window/editor_state.h>

namespace finbook::ui {

namespace {
// "Layer 4": the first number no layer's name uses yet.
QString freshLayerName(const model::Document &doc)
{
    for (int n = doc.layerCount() + 1;; ++n) {
        const QString name = LayerActions::tr("Layer %1").arg(n);
        bool used = false;
        for (const model::Layer &l : doc.layers())
            used = used || l.properties.name == name;
        if (!used)
            return name;
    }
}
} // namespace

LayerActions::LayerActions(EditorState *state, QWidget *dialogParent, QObject *parent)
    : QObject(parent)
    , m_state(state)
    , m_dialogParent(dialogParent)
{
    model::Document *doc = state->document();
    const auto push = [doc](QUndoCommand *command) { doc->undoStack()->push(command); };
    connect(makeAction(QStringLiteral("layer.new"), tr("&New Layer")), &QAction::triggered, this,
            [doc, push] {
                auto *add = new model::AddLayerCommand(doc, doc->currentLayerIndex() + 1,
                                                       freshLayerName(*doc));
                push(add);
                doc->setCurrentLayer(add->layerId());
            });
    connect(makeAction(QStringLiteral("layer.duplicate"), tr("&Duplicate Layer")),
            &QAction::triggered, this, [doc, push] {
                auto *copy = new model::DuplicateLayerCommand(doc, doc->currentLayerId());
                push(copy);
                if (doc->layer(copy->layerId()))
                    doc->setCurrentLayer(copy->layerId());
            });
    connect(makeAction(QStringLiteral("layer.delete"), tr("De&lete Layer")), &QAction::triggered,
            this, [doc, push] {
                if (doc->layerCount() > 1)
                    push(new model::RemoveLayerCommand(doc, doc->currentLayerId()));
            });
    addSeparator();
    const auto move = [doc, push](int delta) {
        const int to = doc->currentLayerIndex() + delta;
        if (to >= 0 && to < doc->layerCount())
            push(new model::MoveLayerCommand(doc, doc->currentLayerId(), to));
    };
    connect(makeAction(QStringLiteral("layer.moveUp"), tr("Move Layer &Up")), &QAction::triggered,
            this, [move] { move(+1); });
    connect(makeAction(QStringLiteral("layer.moveDown"), tr("Move Layer D&own")),
            &QAction::triggered, this, [move] { move(-1); });
    const auto pick = [doc](int delta) {
        const int to = doc->currentLayerIndex() + delta;
        if (to >= 0 && to < doc->layerCount())
            doc->setCurrentLayer(doc->layerAt(to).id);
    };
    connect(makeAction(QStringLiteral("layer.above"), tr("Layer &Above")), &QAction::triggered,
            this, [pick] { pick(+1); });
    connect(makeAction(QStringLiteral("layer.below"), tr("Layer &Below")), &QAction::triggered,
            this, [pick] { pick(-1); });
    addSeparator();
    QAction *visible = makeAction(QStringLiteral("layer.visible"), tr("&Show Layer"));
    visible->setCheckable(true);
    connect(visible, &QAction::triggered, this, [this](bool on) { setFlag(false, on); });
    QAction *locked = makeAction(QStringLiteral("layer.locked"), tr("Loc&k Layer"));
    locked->setCheckable(true);
    connect(locked, &QAction::triggered, this, [this](bool on) { setFlag(true, on); });
    connect(makeAction(QStringLiteral("layer.properties"), tr("Layer &Properties...")),
            &QAction::triggered, this, &LayerActions::editProperties);
    addSeparator();
    // On the picked cels' layers, as many ticks as they span; else one tick on this layer.
    connect(makeAction(QStringLiteral("layer.insertTime"), tr("&Insert Time")), &QAction::triggered,
            this, [this] { CelEditing::insertTime(*m_state); });
    connect(makeAction(QStringLiteral("layer.deleteTime"), tr("Delete &Time")), &QAction::triggered,
            this, [this] { CelEditing::deleteTime(*m_state); });
    for (auto signal : {&model::Document::layersChanged, &model::Document::currentLayerChanged,
                        &model::Document::documentReset})
        connect(doc, signal, this, &LayerActions::updateEnabled);
    updateEnabled();
}

QAction *LayerActions::makeAction(const QString &name, const QString &text)
{
    auto *a = new QAction(text, this);
    a->setObjectName(name);
    m_menu << a;
    return a;
}

void LayerActions::addSeparator()
{
    auto *separator = new QAction(this);
    separator->setSeparator(true);
    m_menu << separator;
}

QAction *LayerActions::action(const QString &objectName) const
{
    for (QAction *a : m_menu)
        if (a->objectName() == objectName)
            return a;
    return nullptr;
}

void LayerActions::setFlag(bool locked, bool value)
{
    model::Document *doc = m_state->document();
    model::LayerProperties p = doc->currentLayer().properties;
    if ((locked ? p.locked : p.visible) == value)
        return;
    (locked ? p.locked : p.visible) = value;
    const QString text = locked ? (value ? tr("Lock Layer") : tr("Unlock Layer"))
                                : (value ? tr("Show Layer") : tr("Hide Layer"));
    doc->undoStack()->push(
        new model::SetLayerPropertiesCommand(doc, doc->currentLayerId(), p, text));
}

void LayerActions::editProperties()
{
    model::Document *doc = m_state->document();
    LayerPropertiesDialog dialog(doc->currentLayer().properties, m_dialogParent);
    if (dialog.exec() != QDialog::Accepted || dialog.properties() == doc->currentLayer().properties)
        return;
    doc->undoStack()->push(new model::SetLayerPropertiesCommand(
        doc, doc->currentLayerId(), dialog.properties(), tr("Change Layer Properties")));
}

void LayerActions::updateEnabled()
{
    const model::Document *doc = m_state->document();
    const int current = doc->currentLayerIndex(), count = doc->layerCount();
    action(QStringLiteral("layer.delete"))->setEnabled(count > 1);
    action(QStringLiteral("layer.moveUp"))->setEnabled(current + 1 < count);
    action(QStringLiteral("layer.above"))->setEnabled(current + 1 < count);
    action(QStringLiteral("layer.moveDown"))->setEnabled(current > 0);
    action(QStringLiteral("layer.below"))->setEnabled(current > 0);
    action(QStringLiteral("layer.new"))->setEnabled(count < model::kMaxLayers);
    action(QStringLiteral("layer.duplicate"))->setEnabled(count < model::kMaxLayers);
    action(QStringLiteral("layer.visible"))->setChecked(doc->currentLayer().properties.visible);
    action(QStringLiteral("layer.locked"))->setChecked(doc->currentLayer().properties.locked);
}

} // namespace finbook::ui
