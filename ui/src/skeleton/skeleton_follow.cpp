#include <finbook/model/cage/cage_commands.h>
#include <finbook/model/skeleton/skeleton_carry.h>
#include <finbook/model/skeleton/skeleton_commands.h>
#include <finbook/ui/skeleton/skeleton_follow.h>
#include <finbook/ui/window/editor_state.h>

#include <algorithm>

namespace finbook::ui {

std::vector<model::Id> skeletonsFollowing(const EditorState &state,
                                          const std::vector<model::Id> &groupIds)
{
    std::vector<model::Id> ids;
    if (!state.showSkeleton())
        return ids;
    for (model::Id id : groupIds) {
        const model::StrokeGroup *g = state.document()->group(id);
        if (g && g->rig.kind() == model::RigKind::Skeleton && !g->rig.skeleton.isPosed() &&
            std::find(ids.begin(), ids.end(), id) == ids.end())
            ids.push_back(id);
    }
    return ids;
}

void followDrawing(EditorState &state, const std::vector<model::Id> &groupIds)
{
    if (!state.showSkeleton())
        return;
    model::Document *doc = state.document();
    std::vector<model::Id> ids = groupIds;
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    for (model::Id id : ids) {
        const model::StrokeGroup *g = doc->group(id);
        if (!g || g->rig.kind() != model::RigKind::Skeleton || g->rig.skeleton.isPosed())
            continue;
        const model::SkeletonRig &old = g->rig.skeleton;
        if (!g->hasContent()) {
            doc->undoStack()->push(new model::RemoveRigCommand(doc, id));
            continue;
        }
        auto rebuilt = model::buildSkeletonRig(*g, old.settings, old.joints[std::size_t(old.root)],
                                               doc->settings().closeGap);
        if (!rebuilt)
            continue; // e.g. a single dot: keep the bones the drawing had
        *rebuilt = model::carryHandEdits(old, *rebuilt); // hand moves and locks that still fit
        rebuilt->mode = old.mode;
        rebuilt->join = old.join; // a part stays joined to its character
        rebuilt->anchor = old.anchor;
        doc->undoStack()->push(new model::BuildSkeletonCommand(doc, id, std::move(*rebuilt)));
    }
}

} // namespace finbook::ui
