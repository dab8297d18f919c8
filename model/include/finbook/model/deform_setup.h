// What an object needs before its pins can be dragged: its mesh, its strokes embedded in the
// mesh, and the ARAP precompute for its set of pinned vertices. Built off the GUI thread from
// an immutable DeformJob; solving with it (solvePose) is cheap enough for every mouse move.
#pragma once

#include <finbook/deform/arap.h>
#include <finbook/geometry/embedding.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/model/types.h>

#include <QString>

#include <functional>
#include <memory>
#include <optional>

namespace finbook::model {

// Identity of an object's rest drawing for meshing: its (immutable, shared) stroke data and
// mesh density. Undo restores the same pointers, so it finds the same mesh again.
struct MeshKey {
    std::vector<StrokeDataPtr> strokes;
    double density = kDefaultMeshDensity;
    friend bool operator==(const MeshKey &, const MeshKey &) = default;
    static MeshKey of(const StrokeGroup &group);
};

// An object's rest mesh with every rest stroke point embedded in it.
struct MeshedObject {
    geometry::ObjectMesh mesh;
    geometry::Embedding embedding;          // all rest points, stroke after stroke
    std::vector<std::size_t> strokeOffsets; // first point of each stroke; size strokes+1
};

struct DeformJob {
    Id groupId = kNoId;
    MeshKey key;
    std::shared_ptr<const MeshedObject> meshed; // reused when the key is unchanged
    Eigen::MatrixX2d pinRest;                   // k×2, rest positions of the pins (canvas px)
    deform::ArapOptions options;
};

struct DeformSetup {
    MeshKey key;
    std::shared_ptr<const MeshedObject> meshed;
    Eigen::MatrixX2d pinRest;
    Eigen::VectorXi pinVertex; // per pin: the mesh vertex it drives
    int extraPasses = 0;       // the ArapOptions::extraPasses it was prepared with
    std::shared_ptr<const deform::ArapPrecompute> arap; // null without pins

    // Whether this setup serves `group` as it is now: same drawing, pins at the same rest
    // positions in the same order (pin ids may differ).
    bool matches(const StrokeGroup &group) const;
};

// Meshes and embeds the rest strokes. Errors are sentences for the user.
Expected<std::shared_ptr<const MeshedObject>, QString> meshObject(const MeshKey &key);

// Runs a whole job (mesh when needed, snap pins, precompute). `cancelled` is polled.
Expected<std::shared_ptr<const DeformSetup>, QString>
buildDeformSetup(const DeformJob &job, const std::function<bool()> &cancelled = {});

// Solves the pose for the pins' current targets: deformed mesh vertices (n×2) and points.
struct Pose {
    Eigen::MatrixX2d vertices;
    DeformedStrokesPtr strokes;
};
Expected<Pose, QString> solvePose(const DeformSetup &setup, const StrokeGroup &group);

// Maps a point shown on a deformed object back to the rest drawing (for placing a pin on a
// posed object): the deformed triangle containing it, or the nearest, then its barycentrics.
QPointF restPointFor(const DeformSetup &setup, const Eigen::MatrixX2d &deformedVertices,
                     QPointF shown);

} // namespace finbook::model
