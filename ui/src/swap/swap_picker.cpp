#include <finbook/ui/swap/swap_actions.h>
#include <finbook/ui/swap/swap_picker.h>
#include <finbook/ui/window/editor_state.h>

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>

namespace finbook::ui {

SwapPicker::SwapPicker(EditorState *state, SwapActions *actions, QWidget *parent)
    : QWidget(parent)
    , m_state(state)
    , m_actions(actions)
    , m_label(new QLabel(tr("Drawing:"), this))
    , m_combo(new QComboBox(this))
{
    setObjectName(QStringLiteral("swapPicker"));
    m_combo->setObjectName(QStringLiteral("swapPicker.combo"));
    m_combo->setToolTip(tr("The drawing this object shows in this frame ([ and ] step through "
                           "them)"));
    m_label->setBuddy(m_combo);
    // Keys stay the canvas's: a click on the combo must not leave it holding [ and ].
    m_combo->setFocusPolicy(Qt::ClickFocus);
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(4, 2, 4, 2);
    row->addWidget(m_label);
    row->addWidget(m_combo, 1);
    connect(m_combo, &QComboBox::activated, this, &SwapPicker::picked);
    model::Document *doc = m_state->document();
    for (auto signal : {&model::Document::groupsChanged, &model::Document::frameChanged})
        connect(doc, signal, this, &SwapPicker::refresh);
    connect(doc, &model::Document::swapSetsChanged, this, &SwapPicker::refresh);
    connect(doc, &model::Document::documentReset, this, &SwapPicker::refresh);
    connect(m_state, &EditorState::currentFrameChanged, this, &SwapPicker::refresh);
    connect(m_state, &EditorState::currentGroupChanged, this, &SwapPicker::refresh);
    refresh();
}

void SwapPicker::refresh()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    const model::SwapSet *set = g ? m_state->document()->swapSet(g->swap.set) : nullptr;
    setVisible(set != nullptr);
    if (!set)
        return;
    // Every edit of the frame comes here (each step of a pin drag too): the list is rebuilt
    // only when the set's drawings changed, the choice only moved otherwise.
    bool same = m_combo->count() == int(set->drawings.size());
    for (int i = 0; same && i < m_combo->count(); ++i) {
        const model::SwapDrawing &d = set->drawings[std::size_t(i)];
        same = m_combo->itemData(i).toULongLong() == d.id && m_combo->itemText(i) == d.name;
    }
    m_refreshing = true;
    if (!same) {
        m_combo->clear();
        for (const model::SwapDrawing &d : set->drawings)
            m_combo->addItem(d.name, QVariant::fromValue(quint64(d.id)));
    }
    m_combo->setCurrentIndex(set->indexOf(g->swap.drawing));
    m_combo->setEnabled(!g->locked);
    m_refreshing = false;
}

void SwapPicker::picked(int index)
{
    const model::StrokeGroup *g = m_state->currentGroup();
    if (m_refreshing || !g || index < 0 || !g->swap.linked())
        return;
    const model::SwapLink to{g->swap.set, model::Id(m_combo->itemData(index).toULongLong())};
    if (to != g->swap)
        m_actions->show(g->id, to);
}

} // namespace finbook::ui
