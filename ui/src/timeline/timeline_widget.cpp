#include <finbook/model/frame_list_model.h>
#include <finbook/ui/timeline/frame_actions.h>
#include <finbook/ui/timeline/playback_controller.h>
#include <finbook/ui/timeline/thumbnail_cache.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/timeline/timeline_widget.h>
#include <finbook/ui/window/editor_state.h>

#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace finbook::ui {

TimelineWidget::TimelineWidget(EditorState *state, FrameActions *frameActions,
                               PlaybackController *playback, QWidget *parent)
    : QWidget(parent)
    , m_state(state)
    , m_model(new model::FrameListModel(state->document(), this))
    , m_thumbnails(new ThumbnailCache(state->document(), this))
    , m_view(new TimelineView(state, m_model, m_thumbnails, this))
{
    setObjectName(QStringLiteral("timeline"));
    m_view->setObjectName(QStringLiteral("timeline.view"));
    if (frameActions)
        m_view->setMenuActions(frameActions->menuActions());
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(createHeader(playback));
    layout->addWidget(m_view, 1);

    connect(m_state, &EditorState::onionSkinChanged, this, &TimelineWidget::showOnionSkin);
    connect(m_state, &EditorState::currentFrameChanged, this, &TimelineWidget::showCounter);
    model::Document *doc = m_state->document();
    connect(doc, &model::Document::framesInserted, this, &TimelineWidget::showCounter);
    connect(doc, &model::Document::framesRemoved, this, &TimelineWidget::showCounter);
    connect(doc, &model::Document::documentReset, this, &TimelineWidget::showCounter);
    connect(doc, &model::Document::settingsChanged, this, &TimelineWidget::showCounter);
    showOnionSkin();
    showCounter();
}

void TimelineWidget::addAboveFrames(QWidget *rows)
{
    rows->setParent(this);
    auto *box = static_cast<QVBoxLayout *>(layout());
    box->insertWidget(box->indexOf(m_view), rows);
}

void TimelineWidget::addBelowFrames(QWidget *row)
{
    row->setParent(this);
    layout()->addWidget(row);
}

QSize TimelineWidget::minimumSizeHint() const
{
    return {200, layout()->minimumSize().height()};
}

QSize TimelineWidget::sizeHint() const
{
    return {800, minimumSizeHint().height() + 30};
}

QWidget *TimelineWidget::createHeader(PlaybackController *playback)
{
    auto *header = new QWidget(this);
    auto *row = new QHBoxLayout(header);
    row->setContentsMargins(4, 2, 4, 2);
    row->setSpacing(4);
    if (playback) {
        for (QAction *action : {playback->toggleAction(), playback->loopAction()}) {
            auto *button = new QToolButton(header);
            button->setDefaultAction(action);
            button->setAutoRaise(true);
            row->addWidget(button);
        }
    }
    m_counter = new QLabel(header);
    m_counter->setObjectName(QStringLiteral("timeline.counter"));
    row->addWidget(m_counter);
    row->addStretch(1);

    m_onion = new QToolButton(header);
    m_onion->setObjectName(QStringLiteral("timeline.onionSkin"));
    m_onion->setText(tr("Onion Skin"));
    m_onion->setToolTip(tr("Show neighbouring frames faintly while drawing"));
    m_onion->setCheckable(true);
    m_onion->setAutoRaise(true);
    row->addWidget(m_onion);
    const auto addSpin = [&](const QString &name, const QString &label, const QString &tip) {
        auto *text = new QLabel(label, header);
        auto *spin = new QSpinBox(header);
        spin->setObjectName(name);
        spin->setRange(0, 5);
        spin->setToolTip(tip);
        text->setBuddy(spin);
        row->addWidget(text);
        row->addWidget(spin);
        connect(spin, &QSpinBox::valueChanged, this, &TimelineWidget::editOnionSkin);
        return spin;
    };
    m_before = addSpin(QStringLiteral("timeline.onionBefore"), tr("Before:"),
                       tr("How many earlier frames the onion skin shows"));
    m_after = addSpin(QStringLiteral("timeline.onionAfter"), tr("After:"),
                      tr("How many later frames the onion skin shows"));
    connect(m_onion, &QToolButton::toggled, this, &TimelineWidget::editOnionSkin);
    return header;
}

void TimelineWidget::showOnionSkin()
{
    const OnionSkin &onion = m_state->onionSkin();
    const QSignalBlocker blockToggle(m_onion);
    const QSignalBlocker blockBefore(m_before);
    const QSignalBlocker blockAfter(m_after);
    m_onion->setChecked(onion.enabled);
    // Only when different: setValue() rewrites the text the user may be typing.
    if (m_before->value() != onion.before)
        m_before->setValue(onion.before);
    if (m_after->value() != onion.after)
        m_after->setValue(onion.after);
}

void TimelineWidget::editOnionSkin()
{
    OnionSkin onion = m_state->onionSkin();
    onion.enabled = m_onion->isChecked();
    onion.before = m_before->value();
    onion.after = m_after->value();
    m_state->setOnionSkin(onion);
}

void TimelineWidget::showCounter()
{
    const model::Document *doc = m_state->document();
    m_counter->setText(tr("Frame %1 of %2 \u00b7 %3 fps")
                           .arg(m_state->currentFrameIndex() + 1)
                           .arg(doc->frameCount())
                           .arg(doc->settings().fps));
}

} // namespace finbook::ui
