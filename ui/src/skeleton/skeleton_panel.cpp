#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/ui/skeleton/skeleton_panel.h>
#include <finbook/ui/window/editor_state.h>

#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>

namespace finbook::ui {

namespace {
constexpr int kSteps = 100;
}

SkeletonPanel::SkeletonPanel(EditorState *state, QWidget *parent, bool compact)
    : QWidget(parent)
    , m_state(state)
{
    QFormLayout *form = compact ? nullptr : new QFormLayout(this);
    QHBoxLayout *row = compact ? new QHBoxLayout(this) : nullptr;
    if (row)
        row->setContentsMargins(4, 0, 4, 0);
    const QString names[] = {tr("Bone complexity"), tr("Merge junctions"), tr("Prune branches"),
                             tr("Collapse short bones")};
    const QString shortNames[] = {tr("Bones"), tr("Merge"), tr("Prune"), tr("Collapse")};
    const QString tips[] = {
        tr("More bones follow the shape more closely"),
        tr("Junctions closer than this become one"),
        tr("Remove side branches shorter than this"),
        tr("Collapse inner bones shorter than this into one joint"),
    };
    const char *ids[] = {"skeleton.complexity", "skeleton.merge", "skeleton.prune",
                         "skeleton.collapse"};
    for (std::size_t i = 0; i < m_sliders.size(); ++i) {
        auto *s = new QSlider(Qt::Horizontal, this);
        s->setObjectName(QString::fromLatin1(ids[i]) +
                         (compact ? QStringLiteral(".bar") : QString()));
        s->setRange(0, kSteps);
        s->setToolTip(tr("%1: %2").arg(names[i], tips[i]));
        if (form) {
            form->addRow(names[i], s);
        } else {
            s->setFixedWidth(64);
            row->addWidget(new QLabel(shortNames[i], this));
            row->addWidget(s);
        }
        connect(s, &QSlider::valueChanged, this, &SkeletonPanel::changed);
        // A drag is one step: the next drag, or a key press, starts another.
        connect(s, &QSlider::sliderReleased, this, [this] { ++m_serial; });
        m_sliders[i] = s;
    }
    m_hint =
        new QLabel(tr("Pick the Bone tool (K) and click an object to give it a skeleton."), this);
    if (form) {
        m_hint->setWordWrap(true);
        m_hint->installEventFilter(this);
        form->addRow(m_hint);
    } else {
        m_hint->hide(); // the sliders' tooltips and the greyed sliders say it in the bar
        m_compact = true;
    }
    connect(state, &EditorState::currentGroupChanged, this, &SkeletonPanel::sync);
    connect(state, &EditorState::currentFrameChanged, this, &SkeletonPanel::sync);
    connect(state->document(), &model::Document::constraintsChanged, this, &SkeletonPanel::sync);
    connect(state->document(), &model::Document::documentReset, this, &SkeletonPanel::sync);
    sync();
}

bool SkeletonPanel::eventFilter(QObject *watched, QEvent *event)
{
    // A dock does not ask a wrapped label how tall it gets at its width: say it as the minimum
    // height, or the hint is cut off at the default window size (German, French, Japanese
    // run longer still).
    if (watched == m_hint && event->type() == QEvent::Resize) {
        const int needed = m_hint->heightForWidth(m_hint->width());
        if (needed > 0 && needed != m_hint->minimumHeight())
            m_hint->setMinimumHeight(needed);
    }
    return QWidget::eventFilter(watched, event);
}

void SkeletonPanel::sync()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    const bool has = g && !g->rig.skeleton.empty();
    const model::SkeletonSettings s = has ? g->rig.skeleton.settings : model::SkeletonSettings{};
    const double values[] = {s.complexity, s.merge, s.prune, s.collapse};
    for (std::size_t i = 0; i < m_sliders.size(); ++i) {
        const QSignalBlocker block(m_sliders[i]);
        m_sliders[i]->setEnabled(has && !g->locked);
        if (!m_sliders[i]->isSliderDown())
            m_sliders[i]->setValue(int(std::lround(values[i] * kSteps)));
    }
    m_hint->setVisible(!has && !m_compact);
}

void SkeletonPanel::changed()
{
    const model::StrokeGroup *g = m_state->currentGroup();
    if (!g || g->rig.skeleton.empty())
        return;
    model::SkeletonSettings s;
    s.complexity = m_sliders[0]->value() / double(kSteps);
    s.merge = m_sliders[1]->value() / double(kSteps);
    s.prune = m_sliders[2]->value() / double(kSteps);
    s.collapse = m_sliders[3]->value() / double(kSteps);
    const model::SkeletonRig &old = g->rig.skeleton;
    auto rebuilt = model::buildSkeletonRig(*g, s, old.joints[std::size_t(old.root)],
                                           m_state->document()->settings().closeGap);
    if (!rebuilt) {
        emit messagePosted(rebuilt.error());
        return;
    }
    model::Document *doc = m_state->document();
    const bool dragging = std::any_of(m_sliders.begin(), m_sliders.end(),
                                      [](const QSlider *x) { return x->isSliderDown(); });
    doc->undoStack()->push(
        new model::SetSkeletonSettingsCommand(doc, g->id, std::move(*rebuilt), m_serial));
    if (!dragging)
        ++m_serial;
}

} // namespace finbook::ui
