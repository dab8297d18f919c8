#include <finbook/model/commands.h>
#include <finbook/model/object_commands.h>
#include <finbook/ui/panels/object_actions.h>
#include <finbook/ui/tools/stroke_editing.h>
#include <finbook/ui/window/editor_state.h>

#include <QMenu>

#include <algorithm>

namespace finbook::ui {

namespace {
int zIndex(const model::Frame &frame, model::Id groupId)
{
    for (int i = 0; i < int(frame.groups.size()); ++i)
        if (frame.groups[std::size_t(i)].id == groupId)
            return i;
    return -1;
}
} // namespace

ObjectActions::ObjectActions(EditorState *state, QObject *parent)
    : QObject(parent)
    , m_state(state)
    , m_targets(new QMenu)
{
    m_new = makeAction(QStringLiteral("object.new"), tr("&New Object"),
                       QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
    m_remove = makeAction(QStringLiteral("object.delete"), tr("&Delete Object"), {});
    m_merge = makeAction(QStringLiteral("object.merge"), tr("&Merge Objects"),
                         QKeySequence(Qt::CTRL | Qt::Key_E));
    m_moveSelection =
        makeAction(QStringLiteral("object.moveSelection"), tr("Move &Selection to Object"), {});
    m_raise = makeAction(QStringLiteral("object.raise"), tr("Bring &Forward"),
                         QKeySequence(Qt::CTRL | Qt::Key_BracketRight));
    m_lower = makeAction(QStringLiteral("object.lower"), tr("Send &Backward"),
                         QKeySequence(Qt::CTRL | Qt::Key_BracketLeft));
    m_toggleVisible = makeAction(QStringLiteral("object.toggleVisible"), tr("&Visible"), {});
    m_toggleLocked = makeAction(QStringLiteral("object.toggleLocked"), tr("&Locked"), {});
    m_toggleVisible->setCheckable(true);
    m_toggleLocked->setCheckable(true);
    m_new->setToolTip(tr("New object above the current one"));
    m_merge->setToolTip(tr("Merge the selected objects, or the current one into the one below"));
    m_moveSelection->setToolTip(tr("Move the selected strokes to another object"));
    // Short labels for the panel's tool bar.
    m_new->setIconText(tr("New"));
    m_remove->setIconText(tr("Delete"));
    m_merge->setIconText(tr("Merge"));
    m_moveSelection->setIconText(tr("Move To"));
    m_raise->setIconText(QStringLiteral("\u2191"));
    m_lower->setIconText(QStringLiteral("\u2193"));
    m_targets->setTitle(m_moveSelection->text());
    m_moveSelection->setMenu(m_targets);

    connect(m_new, &QAction::triggered, this, &ObjectActions::addObject);
    connect(m_remove, &QAction::triggered, this, &ObjectActions::removeObject);
    connect(m_merge, &QAction::triggered, this, &ObjectActions::mergeObjects);
    connect(m_raise, &QAction::triggered, this, [this] { reorder(+1); });
    connect(m_lower, &QAction::triggered, this, [this] { reorder(-1); });
    const auto setFlag = [this](model::ObjectFlag flag, bool value) {
        model::Document *doc = m_state->document();
        if (m_state->currentGroupId() != model::kNoId)
            doc->undoStack()->push(
                new model::SetObjectFlagCommand(doc, m_state->currentGroupId(), flag, value));
    };
    connect(m_toggleVisible, &QAction::triggered, this,
            [setFlag](bool on) { setFlag(model::ObjectFlag::Visible, on); });
    connect(m_toggleLocked, &QAction::triggered, this,
            [setFlag](bool on) { setFlag(model::ObjectFlag::Locked, on); });
    connect(m_targets, &QMenu::aboutToShow, this, &ObjectActions::refreshTargets);

    model::Document *doc = m_state->document();
    connect(doc, &model::Document::groupsChanged, this, &ObjectActions::updateEnabled);
    connect(doc, &model::Document::framesRemoved, this, &ObjectActions::updateEnabled);
    connect(doc, &model::Document::documentReset, this, &ObjectActions::updateEnabled);
    connect(m_state, &EditorState::currentFrameChanged, this, &ObjectActions::updateEnabled);
    connect(m_state, &EditorState::currentGroupChanged, this, &ObjectActions::updateEnabled);
    connect(m_state, &EditorState::selectionChanged, this, &ObjectActions::updateEnabled);
    updateEnabled();
}

ObjectActions::~ObjectActions()
{
    delete m_targets;
}

QAction *ObjectActions::makeAction(const QString &name, const QString &text,
                                   const QKeySequence &shortcut)
{
    auto *action = new QAction(text, this);
    action->setObjectName(name);
    if (!shortcut.isEmpty())
        action->setShortcut(shortcut);
    m_menu.append(action);
    return action;
}

void ObjectActions::setObjectSelection(std::vector<model::Id> groupIds)
{
    m_selection = std::move(groupIds);
    updateEnabled();
}

std::vector<model::Id> ObjectActions::selectionInFrame() const
{
    std::vector<model::Id> ids;
    if (const model::Frame *frame = m_state->currentFrame())
        for (model::Id id : m_selection)
            if (zIndex(*frame, id) >= 0)
                ids.push_back(id);
    return ids;
}

QString ObjectActions::freshName() const
{
    const model::Frame *frame = m_state->currentFrame();
    for (int n = frame ? int(frame->groups.size()) + 1 : 1;; ++n) {
        const QString name = tr("Object %1").arg(n);
        if (!frame || std::none_of(frame->groups.begin(), frame->groups.end(),
                                   [&](const model::StrokeGroup &g) { return g.name == name; }))
            return name;
    }
}

void ObjectActions::addObject()
{
    const model::Frame *frame = m_state->currentFrame();
    if (!frame)
        return;
    model::Document *doc = m_state->document();
    const int above = zIndex(*frame, m_state->currentGroupId()) + 1;
    auto *command = new model::AddObjectCommand(doc, frame->id, above, freshName());
    const model::Id id = command->groupId();
    doc->undoStack()->push(command);
    m_state->setCurrentGroupId(id);
}

void ObjectActions::removeObject()
{
    const model::Frame *frame = m_state->currentFrame();
    if (!frame || frame->groups.size() < 2)
        return; // a frame keeps one object to draw into
    const int z = zIndex(*frame, m_state->currentGroupId());
    if (z < 0)
        return;
    // Carry on with the object below (or the new bottom one).
    const model::Id next = frame->groups[std::size_t(z > 0 ? z - 1 : 1)].id;
    model::Document *doc = m_state->document();
    doc->undoStack()->push(new model::RemoveObjectCommand(doc, m_state->currentGroupId()));
    m_state->setCurrentGroupId(next);
}

void ObjectActions::mergeObjects()
{
    const model::Frame *frame = m_state->currentFrame();
    if (!frame)
        return;
    std::vector<model::Id> ids = selectionInFrame();
    if (ids.size() < 2) {
        const int z = zIndex(*frame, m_state->currentGroupId());
        if (z <= 0)
            return;
        ids = {frame->groups[std::size_t(z - 1)].id, m_state->currentGroupId()};
    }
    std::sort(ids.begin(), ids.end(),
              [&](model::Id a, model::Id b) { return zIndex(*frame, a) < zIndex(*frame, b); });
    const model::Id target = ids.front();
    model::Document *doc = m_state->document();
    if (const QString refusal = model::mergeRefusal(*doc, ids); !refusal.isEmpty()) {
        emit message(refusal);
        return;
    }
    // A posed object's pose becomes its drawing first, in the same step, as for every other
    // edit of its strokes (Apply Pose keeps what the pose showed: its colours, cut-out pieces
    // and shading), so the merged drawing shows what the objects showed. Bottom up, so each
    // merged object's strokes land above the ones merged before it.
    StrokeEditing::beginRestEdit(doc, tr("Merge Objects"), ids);
    for (auto it = ids.begin() + 1; it != ids.end(); ++it)
        doc->undoStack()->push(new model::MergeObjectsCommand(doc, *it, target));
    doc->undoStack()->endMacro();
    m_selection = {target};
    m_state->setCurrentGroupId(target);
}

void ObjectActions::moveSelectionTo(model::Id targetGroupId)
{
    std::vector<model::Id> strokes = m_state->selectedStrokes();
    if (strokes.empty() || !m_state->document()->group(targetGroupId))
        return;
    model::Document *doc = m_state->document();
    // A rest edit of both ends: posed objects are applied first, and shown skeletons of the
    // objects that lose or gain strokes follow (StrokeEditing, as for the other edits).
    std::vector<model::Id> groups{targetGroupId};
    for (model::Id id : strokes)
        if (const model::StrokeLocation at = doc->locateStroke(id); at.isValid())
            groups.push_back(doc->frameAt(at).groups[std::size_t(at.group)].id);
    std::sort(groups.begin(), groups.end());
    groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
    const QString text = tr("Move Strokes to Object");
    StrokeEditing::beginRestEdit(doc, text, groups);
    const std::vector<model::StrokeGroup> before = StrokeEditing::objectsNow(doc, groups);
    doc->undoStack()->push(new model::MoveStrokesCommand(doc, std::move(strokes), targetGroupId));
    // A head moved to an object of its own shows the arms' tops that Apply Pose hid behind it.
    StrokeEditing::showUncoveredLines(doc, before);
    StrokeEditing::endRestEdit(*m_state, groups);
    m_state->setCurrentGroupId(targetGroupId);
}

void ObjectActions::reorder(int delta)
{
    const model::Frame *frame = m_state->currentFrame();
    if (!frame)
        return;
    const int z = zIndex(*frame, m_state->currentGroupId());
    const int to = z + delta;
    if (z < 0 || to < 0 || to >= int(frame->groups.size()))
        return;
    model::Document *doc = m_state->document();
    doc->undoStack()->push(new model::ReorderObjectCommand(doc, m_state->currentGroupId(), to));
}

void ObjectActions::refreshTargets()
{
    m_targets->clear();
    const model::Frame *frame = m_state->currentFrame();
    if (!frame)
        return;
    // Strokes all from one object: that object is no target.
    model::Id onlySource = model::kNoId;
    for (model::Id stroke : m_state->selectedStrokes()) {
        const model::StrokeLocation at = m_state->document()->locateStroke(stroke);
        if (!at.isValid() || at.layer != m_state->document()->currentLayerIndex() ||
            at.frame != m_state->currentFrameIndex())
            continue;
        const model::Id group = frame->groups[std::size_t(at.group)].id;
        onlySource = onlySource == model::kNoId || onlySource == group ? group : model::Id(-1);
    }
    for (auto it = frame->groups.rbegin(); it != frame->groups.rend(); ++it) {
        if (it->id == onlySource)
            continue;
        QAction *target = m_targets->addAction(it->name);
        target->setData(QVariant::fromValue<quint64>(it->id));
        const model::Id id = it->id;
        connect(target, &QAction::triggered, this, [this, id] { moveSelectionTo(id); });
    }
}

void ObjectActions::updateEnabled()
{
    const model::Frame *frame = m_state->currentFrame();
    const int count = frame ? int(frame->groups.size()) : 0;
    const int z = frame ? zIndex(*frame, m_state->currentGroupId()) : -1;
    m_new->setEnabled(frame != nullptr);
    m_remove->setEnabled(count > 1);
    m_merge->setEnabled(selectionInFrame().size() >= 2 || z > 0);
    m_moveSelection->setEnabled(count > 1 && !m_state->selectedStrokes().empty());
    m_raise->setEnabled(z >= 0 && z + 1 < count);
    m_lower->setEnabled(z > 0);
    const model::StrokeGroup *group = m_state->currentGroup();
    m_toggleVisible->setEnabled(group != nullptr);
    m_toggleLocked->setEnabled(group != nullptr);
    m_toggleVisible->setChecked(group && group->visible);
    m_toggleLocked->setChecked(group && group->locked);
}

} // namespace finbook::ui
