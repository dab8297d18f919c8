// The rest half of a shaded face (shade/fill_shading.h): its inflated mesh and the weights
// that pose it from the object's stroke points. Cached per face of a regions object.
#pragma once

#include <finbook/geometry/inflate/inflation.h>
#include <finbook/geometry/shade/pose.h>
#include <finbook/geometry/shade/tone_region.h>
#include <finbook/model/fill/fill_regions.h>

#include <memory>
#include <utility>
#include <vector>

namespace finbook::model {

struct RestShade {
    geometry::Inflation inflation;
    geometry::MeshEdges edges;                 // of inflation.F, for tracing the tones
    geometry::PoseWeights weights;             // controls: the rows of `controls`
    std::vector<std::pair<int, int>> controls; // (stroke index, point index) of each control
};
using RestShadePtr = std::shared_ptr<const RestShade>;

// At most this many stroke points pose a face (evenly spaced along the drawing).
constexpr int kMaxShadeControls = 1500;
// The shading mesh is coarser than the deformers' (tones need no more).
constexpr int kShadeTargetVertices = 600;
// Stroke points that pose each shading vertex (the nearest; poseWeights).
constexpr int kShadePoseNeighbours = 8;

// Null when the face cannot be meshed or inflated.
RestShadePtr restShade(const StrokeGroup &group, const ObjectRegionsPtr &regions, int face);

} // namespace finbook::model
