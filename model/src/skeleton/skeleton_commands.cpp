#include "../command_text.h"

#include <finbook/model/skeleton/skeleton_commands.h>

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
    else // the mode is the user's choice, not the sliders'
        m_new.skeleton.mode = g->rig.skeleton.mode;
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

} // namespace finbook::model
