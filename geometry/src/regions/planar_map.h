// Internal: the planar arrangement of labelled segments (CGAL Arrangement_2, exact
// constructions), kept behind a pimpl so CGAL's headers stay in planar_map.cpp.
#pragma once

#include <finbook/geometry/region.h>

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace finbook::geometry::detail {

struct LabelledSegment {
    Eigen::Vector2d a, b;
    int label = -1; // ≥ 0: an input stroke; < 0: a link (snap or gap closure)
};

struct MapFace {
    Polygon polygon;         // outer A > 0, holes A < 0; dangling edges left out
    std::vector<int> labels; // labels ≥ 0 on its boundary, sorted, unique
    double area = 0.0;
    double perimeter = 0.0;
};

class PlanarMap {
public:
    PlanarMap();
    ~PlanarMap();
    PlanarMap(const PlanarMap &) = delete;
    PlanarMap &operator=(const PlanarMap &) = delete;

    // Sweeps all segments in at once (zero-length ones are skipped).
    void insertAll(const std::vector<LabelledSegment> &segments);
    // Adds one segment to the existing map.
    void insert(const LabelledSegment &segment);

    // Whether p lies in the interior of a bounded face (not on an edge or vertex).
    bool inBoundedFace(const Eigen::Vector2d &p) const;

    // The bounded face that would contain `probe` were `segments` added (the map itself is
    // left as it is), and the length of that face's outline it would share with faces that
    // are bounded already and at least `minNeighbourArea` large; nothing when `probe` would
    // not lie inside a bounded face.
    struct Trial {
        MapFace face;
        double sharedWithBounded = 0.0;
    };
    std::optional<Trial> trialFace(const std::vector<LabelledSegment> &segments,
                                   const Eigen::Vector2d &probe, double minNeighbourArea) const;

    // Calls join(a, b) for every two labels that meet: share an edge (overlap) or a vertex.
    void forEachContact(const std::function<void(int, int)> &join) const;

    // Merges faces thinner than `minWidth` (2·area/perimeter) or smaller than `minArea` into
    // the neighbour they share most boundary with (the outside counts: then they vanish).
    void mergeSlivers(double minWidth, double minArea);

    std::vector<MapFace> faces() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace finbook::geometry::detail
