#include <finbook/model/commands.h>
#include <finbook/ui/timeline/frame_actions.h>
#include <finbook/ui/window/editor_state.h>

#include <algorithm>

namespace finbook::ui {

FrameActions::FrameActions(EditorState *state, QObject *parent)
    : QObject(parent)
    , m_state(state)
{
    m_insertBefore = makeAction(QStringLiteral("frame.insertBefore"), tr("Insert Frame &Before"),
                                QKeySequence(Qt::CTRL | Qt::Key_F5));
    m_insertAfter = makeAction(QStringLiteral("frame.insertAfter"), tr("&Insert Frame After"),
                               QKeySequence(Qt::Key_F5));
    m_duplicate = makeAction(QStringLiteral("frame.duplicate"), tr("&Duplicate Frame"),
                             QKeySequence(Qt::Key_F6));
    m_inbetweens = makeAction(QStringLiteral("frame.inbetweens"), tr("Generate In-be&tweens…"),
                              QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F6));
    m_remove = makeAction(QStringLiteral("frame.delete"), tr("Delete Fra&me"),
                          QKeySequence(Qt::SHIFT | Qt::Key_F5));
    addSeparator();
    m_moveLeft = makeAction(QStringLiteral("frame.moveLeft"), tr("Move Frame &Left"),
                            QKeySequence(Qt::ALT | Qt::Key_Left));
    m_moveRight = makeAction(QStringLiteral("frame.moveRight"), tr("Move Frame &Right"),
                             QKeySequence(Qt::ALT | Qt::Key_Right));
    addSeparator();
    m_holdMore = makeAction(QStringLiteral("frame.holdMore"), tr("Hold Lon&ger"),
                            QKeySequence(Qt::ALT | Qt::Key_Equal));
    m_holdLess = makeAction(QStringLiteral("frame.holdLess"), tr("Hold &Shorter"),
                            QKeySequence(Qt::ALT | Qt::Key_Minus));
    addSeparator();
    m_previous = makeAction(QStringLiteral("frame.previous"), tr("&Previous Frame"),
                            QKeySequence(Qt::Key_Comma));
    m_next =
        makeAction(QStringLiteral("frame.next"), tr("&Next Frame"), QKeySequence(Qt::Key_Period));

    connect(m_insertBefore, &QAction::triggered, this,
            [this] { insertFrame(m_state->currentFrameIndex()); });
    connect(m_insertAfter, &QAction::triggered, this,
            [this] { insertFrame(m_state->currentFrameIndex() + 1); });
    connect(m_duplicate, &QAction::triggered, this, &FrameActions::duplicateFrame);
    connect(m_inbetweens, &QAction::triggered, this, &FrameActions::requestInbetweens);
    connect(m_remove, &QAction::triggered, this, &FrameActions::removeFrame);
    connect(m_moveLeft, &QAction::triggered, this, [this] { moveFrame(-1); });
    connect(m_moveRight, &QAction::triggered, this, [this] { moveFrame(+1); });
    connect(m_holdMore, &QAction::triggered, this, [this] { changeHold(+1); });
    connect(m_holdLess, &QAction::triggered, this, [this] { changeHold(-1); });
    connect(m_previous, &QAction::triggered, m_state, &EditorState::previousFrame);
    connect(m_next, &QAction::triggered, m_state, &EditorState::nextFrame);

    model::Document *doc = m_state->document();
    connect(doc, &model::Document::framesInserted, this, &FrameActions::updateEnabled);
    connect(doc, &model::Document::framesRemoved, this, &FrameActions::updateEnabled);
    connect(doc, &model::Document::frameMoved, this, &FrameActions::updateEnabled);
    connect(doc, &model::Document::frameChanged, this, &FrameActions::updateEnabled);
    connect(doc, &model::Document::documentReset, this, &FrameActions::updateEnabled);
    connect(m_state, &EditorState::currentFrameChanged, this, &FrameActions::updateEnabled);
    connect(m_state, &EditorState::frameSelectionChanged, this, &FrameActions::updateEnabled);
    updateEnabled();
}

QAction *FrameActions::makeAction(const QString &name, const QString &text,
                                  const QKeySequence &shortcut)
{
    auto *action = new QAction(text, this);
    action->setObjectName(name);
    action->setShortcut(shortcut);
    m_menu.append(action);
    return action;
}

void FrameActions::addSeparator()
{
    auto *separator = new QAction(this);
    separator->setSeparator(true);
    m_menu.append(separator);
}

void FrameActions::insertFrame(int index)
{
    model::Document *doc = m_state->document();
    doc->undoStack()->push(new model::InsertFrameCommand(doc, index));
    m_state->setCurrentFrameIndex(std::clamp(index, 0, doc->frameCount() - 1));
}

void FrameActions::duplicateFrame()
{
    model::Document *doc = m_state->document();
    const model::Id source = m_state->currentFrameId();
    if (source == model::kNoId)
        return;
    const int at = m_state->currentFrameIndex() + 1;
    doc->undoStack()->push(new model::DuplicateFrameCommand(doc, source, at));
    m_state->setCurrentFrameIndex(at);
}

void FrameActions::requestInbetweens()
{
    const std::vector<int> picked = m_state->selectedFrames();
    if (picked.size() < 2)
        return;
    const model::Document *doc = m_state->document();
    emit inbetweensRequested(doc->frameAt(picked.front()).id, doc->frameAt(picked.back()).id);
}

void FrameActions::removeFrame()
{
    model::Document *doc = m_state->document();
    if (doc->frameCount() <= 1)
        return; // a flipbook always keeps one page to draw on
    // The frames selected in the timeline go together when the current frame is one of them
    // (one undo step); a flipbook keeps at least its first selected page.
    std::vector<int> picked = m_state->selectedFrames();
    const int current = m_state->currentFrameIndex();
    if (picked.size() < 2 || std::find(picked.begin(), picked.end(), current) == picked.end()) {
        doc->undoStack()->push(new model::DeleteFrameCommand(doc, m_state->currentFrameId()));
        return;
    }
    if (int(picked.size()) >= doc->frameCount())
        picked.erase(picked.begin());
    std::vector<model::Id> ids;
    for (int row : picked)
        ids.push_back(doc->frameAt(row).id);
    doc->undoStack()->beginMacro(tr("Delete %n Frame(s)", nullptr, int(ids.size())));
    for (model::Id id : ids)
        doc->undoStack()->push(new model::DeleteFrameCommand(doc, id));
    doc->undoStack()->endMacro();
}

void FrameActions::moveFrame(int delta)
{
    model::Document *doc = m_state->document();
    const int from = m_state->currentFrameIndex();
    const int to = from + delta;
    if (to < 0 || to >= doc->frameCount())
        return;
    // The current frame travels with the move (EditorState follows frameMoved).
    doc->undoStack()->push(new model::MoveFrameCommand(doc, from, to));
}

void FrameActions::changeHold(int delta)
{
    const model::Frame *frame = m_state->currentFrame();
    if (!frame)
        return;
    const int hold = std::clamp(frame->hold + delta, 1, model::kMaxHold);
    if (hold == frame->hold)
        return;
    model::Document *doc = m_state->document();
    doc->undoStack()->push(new model::SetFrameHoldCommand(doc, frame->id, hold));
}

void FrameActions::updateEnabled()
{
    const int count = m_state->document()->frameCount();
    const int current = m_state->currentFrameIndex();
    const model::Frame *frame = m_state->currentFrame();
    m_duplicate->setEnabled(frame != nullptr);
    m_inbetweens->setEnabled(m_state->selectedFrames().size() >= 2);
    m_remove->setEnabled(count > 1);
    m_moveLeft->setEnabled(current > 0);
    m_moveRight->setEnabled(current + 1 < count);
    m_holdMore->setEnabled(frame && frame->hold < model::kMaxHold);
    m_holdLess->setEnabled(frame && frame->hold > 1);
    m_previous->setEnabled(current > 0);
    m_next->setEnabled(current + 1 < count);
}

} // namespace finbook::ui
