// An object's regions (geometry/regions.h) as the model sees them: computed from its rest
// strokes, cached by their content (rest stroke data is immutable and shared, so the list of
// data pointers is the strokes' revision), never undo state. Safe on any thread: export renders
// on a worker.
#pragma once

#include <finbook/geometry/regions.h>
#include <finbook/model/types.h>

#include <QPainterPath>
#include <QPolygonF>

#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace finbook::model {

class ObjectRegions {
public:
    ObjectRegions(geometry::Regions regions, std::vector<Id> strokeIds,
                  std::vector<int> strokeIndex);

    const geometry::Regions &regions() const { return m_regions; }
    int faceCount() const { return int(m_regions.faces.size()); }
    // The ids of the strokes bounding `face`, sorted.
    const std::vector<Id> &faceStrokeIds(int face) const { return m_faceIds[std::size_t(face)]; }
    // The face's rest outline (outer ring and holes; non-zero rule, holes run the other way).
    const QPainterPath &restPath(int face) const { return m_restPaths[std::size_t(face)]; }
    // The index into the object's strokes of input `input` of the regions (a face's strokes,
    // a closure's), or -1: the regions leave out empty strokes and hidden lines.
    int strokeOfInput(int input) const
    {
        return input >= 0 && std::size_t(input) < m_strokeIndex.size()
                   ? m_strokeIndex[std::size_t(input)]
                   : -1;
    }
    // Innermost face holding rest point p, or -1.
    int faceAt(QPointF p) const;

    // The face's outline as the object shows now: each outline edge that runs along a boundary
    // stroke (within its simplification) is tied to that stroke once, from the point nearest
    // its start to the point nearest its end (stroke, segment, t), and follows the stroke's
    // displayed (posed) points between them; an edge along a gap closure joins its corners,
    // each tied to the nearest point of a boundary stroke. The fill then meets its ink exactly,
    // bends included, under any deformer (pins, cage, skeleton) and in in-betweens.
    QPainterPath displayedPath(const StrokeGroup &group, int face) const;
    // The gap-closing segments, each end following the stroke it lies on, as shown.
    std::vector<QLineF> displayedClosures(const StrokeGroup &group) const;

    struct Anchor {
        int stroke = -1; // index into the object's strokes; -1 = keep the rest position
        int segment = 0;
        float t = 0.0f;
    };
    // One edge of a face's outline as shown: it starts at `start` and, when it runs along a
    // stroke (`along` ≥ 0, an index into the object's strokes), passes through that stroke's
    // shown points between `start` and `end` (both on it), so the fill follows the posed line
    // between the outline's corners, not a chord across its bend; `wraps`: the walk goes
    // round a closed stroke's joint.
    struct Edge {
        Anchor start, end;
        int along = -1;
        bool wraps = false;
    };

private:
    const std::vector<std::vector<Edge>> &edges(const StrokeGroup &group, int face) const;

    geometry::Regions m_regions;
    std::vector<std::vector<Id>> m_faceIds;
    std::vector<QPainterPath> m_restPaths;
    std::vector<int> m_strokeIndex; // input index → index into the object's strokes
    mutable std::mutex m_mutex;
    mutable std::unordered_map<int, std::vector<std::vector<Edge>>> m_edges; // per ring
};

using ObjectRegionsPtr = std::shared_ptr<const ObjectRegions>;

// The colour of a line's part that a cut-out piece hid when the pose was applied (bakedStrokes,
// HiddenLines::KeepUnseen): no renderer draws it (alpha 0) and it bounds no region (the regions
// leave it out, unlike a gap closer's line of no ink), but the line it belongs to stays whole,
// so that the loop the line closed still inflates as one (rest_shade.h).
constexpr QRgb kHiddenLineColor = 0x00ffffff;

// The lines of no ink (alpha 0: the hidden parts of lines, kHiddenLineColor, and the lines that
// close gaps, fill_resolve.h's kGapCloserColor) go with the inked lines they join. Of `picked`
// (ids of `group`'s strokes, as a lasso picks them), a line of no ink stays picked only if
// every inked line its ends lie on is picked too, and one not picked joins when all of them
// are; one whose ends lie on no inked line keeps its pick. So a lasso round a head that a
// cut-out pose, once applied, laid over the body does not take along the hidden part of the
// body's outline under it or a line of no ink that closes the body at the neck, which would
// open the body and lose its fill; a lasso round the whole figure still takes every one.
std::vector<Id> withLinesOfNoInk(const StrokeGroup &group, std::vector<Id> picked);
// The lines of `group` as the animator drew them: Apply Pose splits a line that a cut-out piece
// hid in part into its parts, shown and hidden (kHiddenLineColor), each beginning where the one
// before ends. Here each part is joined again with the parts that share an end with it across a
// hidden part; every other stroke is a line of its own. Indices into group.strokes, in order.
std::vector<std::vector<std::size_t>> linesOfParts(const StrokeGroup &group);

// The gap the document asks for, as geometry::RegionsOptions reads it (< 0 = automatic).
geometry::RegionsOptions regionsOptions(double closeGap);

// The regions of the object's rest strokes with gaps closed as `closeGap` says. Never null:
// an object whose regions cannot be computed (no strokes, absurd coordinates) has none.
ObjectRegionsPtr objectRegions(const StrokeGroup &group, double closeGap);

} // namespace finbook::model
