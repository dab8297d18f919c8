// Inflating a face at rest and weighing its stroke controls (rest_shade.h).
#include "rest_shade.h"

#include <finbook/geometry/inflate/layers.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/model/stroke_input.h>

#include <list>
#include <mutex>

namespace finbook::model {

namespace {
struct Entry {
    const ObjectRegions *regions = nullptr;
    std::weak_ptr<const ObjectRegions> alive;
    int face = -1;
    double density = 0.0;
    RestShadePtr shade; // null: tried and failed
};
constexpr std::size_t kEntries = 128; // about 100 kB each
std::mutex g_mutex;
std::list<Entry> g_shades;

// The region the face inflates as (geometry/inflate/layers.h): the topmost single stroke's
// loop around it (an arm over the body inflates as the arm, the body beside it as the whole
// body), else the face itself. Only the strokes on the face's boundary are tried, each with
// the strokes it continues in: Apply Pose cuts a line where a cut-out piece hid it into
// parts that follow each other in the list, each beginning where the one before ends
// (bakedStrokes), and together they close the loop the line closed.
geometry::Region layerOf(const StrokeGroup &group, const ObjectRegions &regions, int face)
{
    const geometry::Regions &all = regions.regions();
    const geometry::Face &f = all.faces[std::size_t(face)];
    const auto &strokes = group.strokes;
    const auto continues = [&](std::size_t i) { // stroke i + 1 begins where stroke i ends
        if (i + 1 >= strokes.size() || !strokes[i].data || !strokes[i + 1].data ||
            strokes[i].data->points.empty() || strokes[i + 1].data->points.empty())
            return false;
        const StrokePoint &end = strokes[i].data->points.back();
        const StrokePoint &begin = strokes[i + 1].data->points.front();
        return end.x == begin.x && end.y == begin.y;
    };
    std::vector<geometry::StrokeInput> boundary;
    std::vector<int> boundaryInput; // per entry of `boundary`, its input on the face's boundary
    std::vector<bool> taken(strokes.size(), false);
    for (const int input : f.strokes) {
        const int stroke = regions.strokeOfInput(input);
        if (stroke < 0 || std::size_t(stroke) >= strokes.size() ||
            !strokes[std::size_t(stroke)].data || taken[std::size_t(stroke)])
            continue;
        std::size_t first = std::size_t(stroke), last = std::size_t(stroke);
        while (first > 0 && continues(first - 1))
            --first;
        while (continues(last))
            ++last;
        std::vector<StrokePoint> points;
        for (std::size_t k = first; k <= last; ++k) {
            taken[k] = true;
            const auto &part = strokes[k].data->points;
            points.insert(points.end(), part.begin() + (k > first ? 1 : 0), part.end());
        }
        boundary.push_back(strokeInput(points, strokes[std::size_t(stroke)].data->width));
        boundaryInput.push_back(input);
    }
    std::vector<geometry::Layer> layers = geometry::strokeLayers(boundary, all.closeGap);
    for (geometry::Layer &layer : layers)
        layer.stroke = boundaryInput[std::size_t(layer.stroke)];
    return geometry::layerRegion(layers, all, face);
}

RestShadePtr computeShade(const StrokeGroup &group, const ObjectRegions &regions, int face)
{
    geometry::MeshOptions options;
    options.density = group.meshDensity > 0.0 ? std::min(group.meshDensity, 100.0) : 1.0;
    options.targetVertices = kShadeTargetVertices;
    auto mesh = geometry::buildObjectMesh(layerOf(group, regions, face), options);
    if (!mesh) // the face by itself, then
        mesh = geometry::buildObjectMesh(
            geometry::Region{regions.regions().faces[std::size_t(face)].polygon}, options);
    if (!mesh)
        return nullptr;
    auto inflation = geometry::inflateObjectMesh(*mesh);
    if (!inflation)
        return nullptr;
    auto shade = std::make_shared<RestShade>();
    shade->inflation = std::move(*inflation);
    shade->edges = geometry::meshEdges(shade->inflation.F);
    std::size_t total = 0;
    for (const Stroke &s : group.strokes)
        total += s.data ? s.data->points.size() : 0;
    const std::size_t stride = std::max<std::size_t>(1, total / kMaxShadeControls + 1);
    std::size_t k = 0;
    for (std::size_t s = 0; s < group.strokes.size(); ++s) {
        if (!group.strokes[s].data)
            continue;
        for (std::size_t p = 0; p < group.strokes[s].data->points.size(); ++p, ++k)
            if (k % stride == 0)
                shade->controls.emplace_back(int(s), int(p));
    }
    Eigen::MatrixX2d controls(Eigen::Index(shade->controls.size()), 2);
    for (std::size_t c = 0; c < shade->controls.size(); ++c) {
        const StrokePoint &p = group.strokes[std::size_t(shade->controls[c].first)]
                                   .data->points[std::size_t(shade->controls[c].second)];
        controls.row(Eigen::Index(c)) << p.x, p.y;
    }
    shade->weights = geometry::poseWeights(shade->inflation.V, controls, kShadePoseNeighbours);
    return shade;
}
} // namespace

RestShadePtr restShade(const StrokeGroup &group, const ObjectRegionsPtr &regions, int face)
{
    {
        std::lock_guard lock(g_mutex);
        for (auto it = g_shades.begin(); it != g_shades.end(); ++it)
            if (it->regions == regions.get() && it->face == face &&
                it->density == group.meshDensity && !it->alive.expired()) {
                g_shades.splice(g_shades.begin(), g_shades, it);
                return g_shades.front().shade;
            }
    }
    // Computed outside the lock, as objectRegions does.
    RestShadePtr shade = computeShade(group, *regions, face);
    std::lock_guard lock(g_mutex);
    g_shades.push_front({regions.get(), regions, face, group.meshDensity, shade});
    if (g_shades.size() > kEntries)
        g_shades.pop_back();
    return shade;
}

} // namespace finbook::model
