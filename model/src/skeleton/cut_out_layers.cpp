#include <finbook/model/inbetween/inbetween_solve.h>
#include <finbook/model/skeleton/cut_out_layers.h>

#include <cmath>

namespace finbook::model {

bool lacksCutOutLayers(const StrokeGroup &group)
{
    const Rig &rig = group.rig;
    return rig.kind() == RigKind::Skeleton && rig.skeleton.mode == SkinningMode::CutOut &&
           rig.skeleton.isPosed() && group.deformed && group.deformed->pieces.empty() &&
           (!group.strokes.empty() || group.picture);
}

bool restoresLayers(const DeformedStrokes &a, const DeformedStrokes &b)
{
    if (a.pieces.empty() || a.strokes.size() != b.strokes.size() ||
        a.pictureVertices.size() != b.pictureVertices.size())
        return false;
    for (std::size_t i = 0; i < a.pictureVertices.size(); ++i) {
        const QPointF d = a.pictureVertices[i] - b.pictureVertices[i];
        if (!(std::hypot(d.x(), d.y()) <= kCutOutLayersTolerance))
            return false;
    }
    for (std::size_t s = 0; s < a.strokes.size(); ++s) {
        if (a.strokes[s].size() != b.strokes[s].size())
            return false;
        for (std::size_t i = 0; i < a.strokes[s].size(); ++i) {
            const StrokePoint &p = a.strokes[s][i], &q = b.strokes[s][i];
            if (!(std::hypot(double(p.x) - q.x, double(p.y) - q.y) <= kCutOutLayersTolerance))
                return false;
        }
    }
    return true;
}

int restoreCutOutLayers(std::vector<Frame> &frames, double closeGap)
{
    DeformSetupCache setups;
    int restored = 0;
    for (Frame &frame : frames)
        for (StrokeGroup &group : frame.groups) {
            if (!lacksCutOutLayers(group))
                continue;
            auto setup = setupFromCache(group, {}, setups, closeGap);
            if (!setup)
                continue;
            auto pose = solvePose(**setup, group, PoseStage::Final);
            if (!pose || !pose->strokes || !restoresLayers(*pose->strokes, *group.deformed))
                continue;
            group.deformed = std::move(pose->strokes);
            ++restored;
        }
    return restored;
}

} // namespace finbook::model
