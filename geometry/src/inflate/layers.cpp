// Layers of one object: the regions single strokes close (inflate/layers.h).
#include <finbook/geometry/inflate/layers.h>

#include <algorithm>

namespace finbook::geometry {

std::vector<Layer> strokeLayers(const std::vector<StrokeInput> &strokes, double closeGap)
{
    std::vector<Layer> layers;
    RegionsOptions options;
    options.closeGap = closeGap >= 0.0 ? closeGap : -1.0;
    for (std::size_t s = 0; s < strokes.size(); ++s) {
        auto own = computeRegions({strokes[s]}, options);
        if (!own || own->faces.empty())
            continue;
        Layer layer;
        layer.stroke = int(s);
        for (Face &face : own->faces)
            layer.region.push_back(std::move(face.polygon));
        layers.push_back(std::move(layer));
    }
    return layers;
}

int faceLayer(const std::vector<Layer> &layers, const Regions &regions, int face)
{
    if (face < 0 || std::size_t(face) >= regions.faces.size())
        return -1;
    const Face &f = regions.faces[std::size_t(face)];
    int best = -1;
    for (std::size_t l = 0; l < layers.size(); ++l) {
        const Layer &layer = layers[l];
        if (!std::binary_search(f.strokes.begin(), f.strokes.end(), layer.stroke))
            continue;
        if (!regionContains(layer.region, f.seed.x(), f.seed.y()))
            continue;
        if (best < 0 || layer.stroke > layers[std::size_t(best)].stroke)
            best = int(l);
    }
    return best;
}

Region layerRegion(const std::vector<Layer> &layers, const Regions &regions, int face)
{
    const int layer = faceLayer(layers, regions, face);
    if (face < 0 || std::size_t(face) >= regions.faces.size())
        return {};
    const Face &f = regions.faces[std::size_t(face)];
    if (layer >= 0)
        // A stroke that crosses itself closes several faces: the one around this face.
        for (const Polygon &polygon : layers[std::size_t(layer)].region)
            if (regionContains(Region{polygon}, f.seed.x(), f.seed.y()))
                return Region{polygon};
    return Region{f.polygon};
}

} // namespace finbook::geometry
