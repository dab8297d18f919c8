#include "../command_text.h"

#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/model/skeleton/skeleton_joint_edit.h>

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {

Rig skeletonOnly(SkeletonRig skeleton)
{
    Rig rig;
    rig.skeleton = std::move(skeleton);
    return rig;
}

// The object's rig with the skeleton's pose (or mode) replaced; an object without a skeleton
// gives an empty rig, which PoseRigCommand refuses.
Rig posedRig(const Document *doc, Id groupId, const std::vector<double> &angles, QPointF offset)
{
    const StrokeGroup *g = doc->group(groupId);
    if (!g || g->rig.kind() != RigKind::Skeleton)
        return {};
    Rig rig = g->rig;
    rig.skeleton.angles = angles;
    rig.skeleton.rootOffset = offset;
    return rig;
}

Rig withMode(const Document *doc, Id groupId, SkinningMode mode)
{
    const StrokeGroup *g = doc->group(groupId);
    if (!g || g->rig.kind() != RigKind::Skeleton)
        return {};
    Rig rig = g->rig;
    rig.skeleton.mode = mode;
    return rig;
}

// The object's rig with its skeleton replaced by `edit(skeleton)`, or an empty rig (which
// makes the command obsolete) when there is no skeleton or the edit is refused.
template <typename Edit> Rig editedRig(const Document *doc, Id groupId, Edit edit)
{
    const StrokeGroup *g = doc->group(groupId);
    if (!g || g->rig.kind() != RigKind::Skeleton)
        return {};
    Rig rig = g->rig;
    std::optional<SkeletonRig> edited = edit(rig.skeleton);
    if (!edited)
        return {};
    rig.skeleton = std::move(*edited);
    return rig;
}

template <typename T> std::optional<SkeletonRig> valueOr(Expected<T, QString> e)
{
    if (!e)
        return std::nullopt;
    if constexpr (std::is_same_v<T, SkeletonRig>)
        return std::move(*e);
    else
        return std::move(e->rig);
}

bool finitePose(const std::vector<double> &angles, QPointF offset)
{
    return std::isfinite(offset.x()) && std::isfinite(offset.y()) &&
           std::all_of(angles.begin(), angles.end(), [](double a) { return std::isfinite(a); });
}

} // namespace

BuildSkeletonCommand::BuildSkeletonCommand(Document *doc, Id groupId, SkeletonRig built,
                                           QUndoCommand *parent)
    : SetRigCommand(doc, groupId, skeletonOnly(std::move(built)), Command::tr("Build Skeleton"),
                    parent)
{
    if (!m_new.skeleton.isValid() || m_new.skeleton.empty())
        setObsolete(true);
}

SetSkeletonSettingsCommand::SetSkeletonSettingsCommand(Document *doc, Id groupId,
                                                       SkeletonRig rebuilt, int editSerial,
                                                       QUndoCommand *parent)
    : SetRigCommand(doc, groupId, skeletonOnly(std::move(rebuilt)),
                    Command::tr("Change Skeleton Settings"), parent)
    , m_serial(editSerial)
{
    const StrokeGroup *g = doc->group(groupId);
    if (!g || g->rig.kind() != RigKind::Skeleton || !m_new.skeleton.isValid() ||
        m_new.skeleton.empty())
        setObsolete(true);
    else { // the mode and the part's join are the user's choices, not the sliders'
        m_new.skeleton.mode = g->rig.skeleton.mode;
        m_new.skeleton.join = g->rig.skeleton.join;
        m_new.skeleton.anchor = g->rig.skeleton.anchor;
    }
}

bool SetSkeletonSettingsCommand::mergeWith(const QUndoCommand *other)
{
    const auto *o = static_cast<const SetSkeletonSettingsCommand *>(other);
    if (o->m_groupId != m_groupId || o->m_serial != m_serial || o->isObsolete() || isObsolete())
        return false;
    m_new = o->m_new;
    // Back where the drag started: nothing to undo.
    setObsolete(m_new == m_old);
    return true;
}

PoseBonesCommand::PoseBonesCommand(Document *doc, Id groupId, std::vector<double> angles,
                                   QPointF rootOffset, int dragSerial, QUndoCommand *parent)
    : PoseRigCommand(doc, groupId, posedRig(doc, groupId, angles, rootOffset), dragSerial,
                     Command::tr("Pose Bones"), parent)
{
    const StrokeGroup *g = doc->group(groupId);
    if (!g || angles.size() != g->rig.skeleton.joints.size() || !finitePose(angles, rootOffset))
        setObsolete(true);
}

SetSkinningModeCommand::SetSkinningModeCommand(Document *doc, Id groupId, SkinningMode mode,
                                               QUndoCommand *parent)
    : SetRigCommand(doc, groupId, withMode(doc, groupId, mode), Command::tr("Change Skinning"),
                    parent)
{
    const StrokeGroup *g = doc->group(groupId);
    if (!g || g->rig.kind() != RigKind::Skeleton || g->rig.skeleton.mode == mode)
        setObsolete(true);
}

SetJointLockCommand::SetJointLockCommand(Document *doc, Id groupId, int joint, bool locked,
                                         QUndoCommand *parent)
    : SetRigCommand(doc, groupId,
                    editedRig(doc, groupId,
                              [&](const SkeletonRig &s) -> std::optional<SkeletonRig> {
                                  if (joint < 0 || joint >= s.jointCount())
                                      return std::nullopt;
                                  return s.withLock(joint, locked);
                              }),
                    locked ? Command::tr("Lock Joint") : Command::tr("Unlock Joint"), parent)
{
    if (m_new.empty())
        setObsolete(true);
}

ResetBonePoseCommand::ResetBonePoseCommand(Document *doc, Id groupId, int joint,
                                           QUndoCommand *parent)
    : SetRigCommand(doc, groupId,
                    editedRig(doc, groupId,
                              [&](const SkeletonRig &s) -> std::optional<SkeletonRig> {
                                  if (joint < 0 || joint >= s.jointCount())
                                      return std::nullopt;
                                  const bool root = s.parent[std::size_t(joint)] < 0;
                                  const bool turned = std::size_t(joint) < s.angles.size() &&
                                                      s.angles[std::size_t(joint)] != 0.0;
                                  if (!turned && !(root && s.rootOffset != QPointF()))
                                      return std::nullopt; // already at rest
                                  SkeletonRig r = s;
                                  r.angles.resize(r.joints.size(), 0.0);
                                  r.angles[std::size_t(joint)] = 0.0;
                                  if (root)
                                      r.rootOffset = QPointF();
                                  if (!r.isPosed()) // canonical rest, as Reset Pose gives
                                      r = r.atRest();
                                  return r;
                              }),
                    Command::tr("Reset Bone Pose"), parent)
{
    if (m_new.empty())
        setObsolete(true);
}

MoveJointCommand::MoveJointCommand(Document *doc, Id groupId, int joint, QPointF at, int dragSerial,
                                   QUndoCommand *parent)
    : SetRigCommand(
          doc, groupId,
          editedRig(doc, groupId,
                    [&](const SkeletonRig &s) { return valueOr(withJointMoved(s, joint, at)); }),
          Command::tr("Move Joint"), parent)
    , m_serial(dragSerial)
{
    if (m_new.empty())
        setObsolete(true);
}

bool MoveJointCommand::mergeWith(const QUndoCommand *other)
{
    const auto *o = static_cast<const MoveJointCommand *>(other);
    if (o->m_groupId != m_groupId || o->m_serial != m_serial || o->isObsolete() || isObsolete())
        return false;
    m_new = o->m_new;
    setObsolete(m_new == m_old); // back where the drag started
    return true;
}

InsertJointCommand::InsertJointCommand(Document *doc, Id groupId, int bone, QPointF at,
                                       QUndoCommand *parent)
    : SetRigCommand(
          doc, groupId,
          editedRig(doc, groupId,
                    [&](const SkeletonRig &s) { return valueOr(withJointInserted(s, bone, at)); }),
          Command::tr("Insert Joint"), parent)
{
    if (m_new.empty())
        setObsolete(true);
    else
        m_joint = bone; // withJointInserted gives the new joint the split bone's index
}

DeleteJointCommand::DeleteJointCommand(Document *doc, Id groupId, int joint, QUndoCommand *parent)
    : SetRigCommand(
          doc, groupId,
          editedRig(doc, groupId,
                    [&](const SkeletonRig &s) { return valueOr(withJointDeleted(s, joint)); }),
          Command::tr("Delete Joint"), parent)
{
    if (m_new.empty())
        setObsolete(true);
}

} // namespace finbook::model
