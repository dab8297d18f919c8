#include <finbook/model/inbetween/inbetween_solve.h>

namespace finbook::model {

Expected<std::shared_ptr<const DeformSetup>, QString>
setupFromCache(const StrokeGroup &g, const deform::ArapOptions &options, DeformSetupCache &cache,
               double closeGap)
{
    for (const auto &s : cache)
        if (s && sameSolverOptions(s->options, options) && s->matches(g, closeGap))
            return s;
    DeformJob job;
    job.groupId = g.id;
    job.key = MeshKey::of(g, closeGap);
    job.rig = g.rig.atRest();
    job.options = options;
    // Another rest definition on the same drawing reuses the mesh.
    for (const auto &s : cache)
        if (s && s->meshed && s->key == job.key)
            job.meshed = s->meshed;
    auto built = buildDeformSetup(job);
    if (built)
        cache.push_back(*built);
    return built;
}

Expected<int, QString> solveInbetweenPoses(std::vector<Frame> &frames,
                                           const deform::ArapOptions &options,
                                           DeformSetupCache *cache, double closeGap)
{
    DeformSetupCache local;
    DeformSetupCache &setups = cache ? *cache : local;
    int solved = 0;
    for (Frame &f : frames)
        for (StrokeGroup &g : f.groups) {
            if (g.rig.empty() || g.deformed || !g.hasContent())
                continue;
            auto setup = setupFromCache(g, options, setups, closeGap);
            if (!setup)
                return unexpected(setup.error());
            auto pose = solvePose(**setup, g);
            if (!pose)
                return unexpected(pose.error());
            g.deformed = std::move(pose->strokes);
            ++solved;
        }
    return solved;
}

} // namespace finbook::model
