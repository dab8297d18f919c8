// The Bone tool's joint and bone commands: locks, Reset Bone Pose, the context menu, and the
// Edit Joints mode (move, insert, delete rest joints).
#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/model/skeleton/skeleton_join_commands.h>
#include <finbook/model/skeleton/skeleton_joint_edit.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/skeleton/tool_bone.h>
#include <finbook/ui/window/editor_state.h>

#include <QKeyEvent>
#include <QMenu>

namespace finbook::ui {

void BoneTool::push(QUndoCommand *command)
{
    state()->document()->undoStack()->push(command);
    canvas()->update();
}

void BoneTool::select(const Hit &hit)
{
    if (hit.groupId == m_selected.groupId && hit.joint == m_selected.joint &&
        hit.part == m_selected.part)
        return;
    m_selected = hit;
    emit selectionChanged();
    canvas()->update();
}

BoneTool::Hit BoneTool::selection() const
{
    // Only a bone of the frame on show: ids are unique across frames, and Reset Bone Pose must
    // not reach into a frame the animator has moved away from.
    const model::Document *doc = state()->document();
    const model::StrokeGroup *g = doc->group(m_selected.groupId);
    if (!g || m_selected.joint < 0 || m_selected.joint >= g->rig.skeleton.jointCount() ||
        doc->frameAt(doc->locateGroup(m_selected.groupId)).id != state()->currentFrameId())
        return {};
    return m_selected;
}

bool BoneTool::isLocked(model::Id groupId, int joint) const
{
    const model::StrokeGroup *g = state()->document()->group(groupId);
    return g && g->rig.skeleton.isLocked(joint);
}

void BoneTool::toggleLock(const Hit &hit)
{
    if (hit.part != Part::Joint)
        return;
    model::Document *doc = state()->document();
    push(new model::SetJointLockCommand(doc, hit.groupId, hit.joint,
                                        !isLocked(hit.groupId, hit.joint)));
}

BoneTool::Hit BoneTool::lockTarget() const
{
    if (m_editJoints)
        return {};
    if (m_hover.part == Part::Joint && state()->document()->group(m_hover.groupId))
        return m_hover;
    const Hit selected = selection();
    return selected.part == Part::Joint ? selected : Hit{};
}

bool BoneTool::claimsKey(const QKeyEvent &event) const
{
    // L locks the joint under the mouse (or the joint last clicked): Alt-click is taken by
    // many Linux window managers for moving windows. Claimed only over a joint, so L stays
    // free for a window shortcut the user may give it elsewhere.
    return event.key() == kLockKey &&
           !(event.modifiers() & ~Qt::KeyboardModifiers(Qt::KeypadModifier)) &&
           lockTarget().part == Part::Joint;
}

bool BoneTool::keyPress(QKeyEvent *event)
{
    if (!claimsKey(*event))
        return false;
    if (!event->isAutoRepeat())
        toggleLock(lockTarget());
    return true;
}

bool BoneTool::canResetSelectedBone() const
{
    const Hit hit = selection();
    if (hit.part == Part::None)
        return false;
    const model::StrokeGroup *g = state()->document()->group(hit.groupId);
    const model::SkeletonRig &s = g->rig.skeleton;
    const std::size_t j = std::size_t(hit.joint);
    return !g->locked && ((j < s.angles.size() && s.angles[j] != 0.0) ||
                          (s.parent[j] < 0 && s.rootOffset != QPointF()));
}

void BoneTool::resetSelectedBone()
{
    if (!canResetSelectedBone())
        return;
    push(
        new model::ResetBonePoseCommand(state()->document(), m_selected.groupId, m_selected.joint));
}

void BoneTool::setEditJoints(bool on)
{
    if (on == m_editJoints)
        return;
    m_editJoints = on;
    m_drag = {};
    if (canvas()) {
        canvas()->postMessage(
            on ? tr("Edit Joints: drag a joint to move it, click a bone to insert a joint.")
               : QString());
        canvas()->update();
    }
    emit editJointsChanged(on);
}

void BoneTool::pressEditing(const Hit &hit, QPointF at)
{
    const model::StrokeGroup *g = state()->document()->group(hit.groupId);
    if (!g)
        return;
    state()->setCurrentGroupId(hit.groupId);
    if (g->rig.skeleton.isPosed()) {
        canvas()->postMessage(
            tr("Reset the pose or apply it to the drawing before editing joints."));
        return;
    }
    if (hit.part == Part::Bone) {
        insertJoint(hit, at);
        return;
    }
    ++m_dragSerial;
    m_drag.groupId = hit.groupId;
    m_drag.joint = hit.joint;
    m_drag.kind = DragKind::MoveJoint;
    m_drag.grabbed = at;
    m_drag.jointRest = g->rig.skeleton.joints[std::size_t(hit.joint)];
}

void BoneTool::insertJoint(const Hit &hit, QPointF at)
{
    model::Document *doc = state()->document();
    const model::StrokeGroup *g = doc->group(hit.groupId);
    if (!g)
        return;
    auto inserted = model::withJointInserted(g->rig.skeleton, hit.joint, at);
    if (!inserted) {
        canvas()->postMessage(inserted.error());
        return;
    }
    auto *command = new model::InsertJointCommand(doc, hit.groupId, hit.joint, at);
    const int joint = command->insertedJoint();
    push(command);
    select({hit.groupId, Part::Joint, joint});
    m_controller->prepare(hit.groupId);
}

void BoneTool::deleteJoint(const Hit &hit)
{
    model::Document *doc = state()->document();
    const model::StrokeGroup *g = doc->group(hit.groupId);
    if (!g)
        return;
    if (auto deleted = model::withJointDeleted(g->rig.skeleton, hit.joint); !deleted) {
        canvas()->postMessage(deleted.error());
        return;
    }
    push(new model::DeleteJointCommand(doc, hit.groupId, hit.joint));
    select({});
    m_controller->prepare(hit.groupId);
}

void BoneTool::secondaryClick(const ToolEvent &event)
{
    const Hit hit = hitAt(event);
    if (hit.part == Part::None)
        return;
    select(hit);
    QMenu menu(canvas());
    const auto add = [&menu](const QString &text, const char *name) {
        QAction *a = menu.addAction(text);
        a->setObjectName(QString::fromLatin1(name));
        return a;
    };
    QAction *lock = nullptr;
    if (hit.part == Part::Joint) {
        lock = add(isLocked(hit.groupId, hit.joint) ? tr("Unlock Joint") : tr("Lock Joint"),
                   "bone.lock");
        lock->setShortcut(QKeySequence(kLockKey)); // shown only: keyPress() does the work
        lock->setShortcutContext(Qt::WidgetShortcut);
    }
    QAction *reset = add(tr("Reset Bone Pose"), "bone.resetBone");
    reset->setEnabled(canResetSelectedBone());
    menu.addSeparator();
    QAction *edit = add(tr("Edit Joints"), "bone.editJoints");
    edit->setCheckable(true);
    edit->setChecked(m_editJoints);
    QAction *insert = nullptr, *remove = nullptr, *makeRoot = nullptr;
    if (m_editJoints && hit.part == Part::Bone)
        insert = add(tr("Insert Joint Here"), "bone.insertJoint");
    if (m_editJoints && hit.part == Part::Joint)
        remove = add(tr("Delete Joint"), "bone.deleteJoint");
    model::Document *doc = state()->document();
    const model::StrokeGroup *g = doc->group(hit.groupId);
    if (hit.part == Part::Joint && g && g->rig.skeleton.root != hit.joint) {
        makeRoot = add(tr("Make Root Joint"), "bone.makeRootJoint");
        makeRoot->setEnabled(!g->rig.skeleton.isPosed());
    }
    menu.addSeparator();
    const model::Frame *frame = state()->currentFrame();
    QAction *detach = nullptr, *characterRoot = nullptr;
    if (g && g->rig.skeleton.hangs()) {
        const model::StrokeGroup *parent = doc->group(g->rig.skeleton.join.parent);
        detach =
            add(tr("Detach from %1").arg(parent ? parent->name : QString()), "bone.detachPart");
    }
    if (g && frame && g->rig.skeleton.hangs())
        characterRoot = add(tr("Make Character Root"), "bone.characterRoot");
    QAction *joinAll = add(tr("Join Overlapping Parts"), "bone.joinParts");
    const QPoint global = canvas()->mapToGlobal(event.widgetPos.toPoint());
    QAction *chosen = m_menuExec ? m_menuExec(menu, global) : menu.exec(global);
    if (!chosen || !chosen->isEnabled())
        return;
    if (chosen == lock)
        toggleLock(hit);
    else if (chosen == reset)
        resetSelectedBone();
    else if (chosen == edit)
        setEditJoints(!m_editJoints);
    else if (chosen == insert)
        insertJoint(hit, event.pos);
    else if (chosen == remove)
        deleteJoint(hit);
    else if (chosen == makeRoot)
        setRootJoint(hit);
    else if (chosen == detach)
        push(new model::DetachPartCommand(doc, hit.groupId));
    else if (chosen == characterRoot)
        push(new model::MakeCharacterRootCommand(doc, hit.groupId));
    else if (chosen == joinAll)
        joinOverlappingParts();
}

void BoneTool::setRootJoint(const Hit &hit)
{
    model::Document *doc = state()->document();
    const model::StrokeGroup *g = doc->group(hit.groupId);
    if (!g)
        return;
    auto rerooted = model::withRootJoint(g->rig.skeleton, hit.joint);
    if (!rerooted) {
        canvas()->postMessage(rerooted.error());
        return;
    }
    model::Rig rig = g->rig;
    rig.skeleton = std::move(*rerooted);
    const int root = rig.skeleton.root;
    push(new model::SetRigCommand(doc, hit.groupId, std::move(rig), tr("Make Root Joint")));
    select({hit.groupId, Part::Joint, root});
    m_controller->prepare(hit.groupId);
}

void BoneTool::joinOverlappingParts()
{
    model::Document *doc = state()->document();
    auto *command = new model::JoinOverlappingPartsCommand(doc, state()->currentFrameId());
    const int joined = command->joined();
    if (command->isObsolete()) {
        delete command;
        canvas()->postMessage(tr("No part overlaps another part's skeleton."));
        return;
    }
    push(command);
    canvas()->postMessage(tr("Joined %n part(s).", nullptr, joined));
}

} // namespace finbook::ui
