// What an object needs before its rig can be dragged, for every rig kind: the precompute for
// its drawing and its rig's rest definition (pins: mesh, embedding and ARAP factorization;
// cage: harmonic coordinates of the stroke points). Built off the GUI thread from an immutable
// DeformJob; solving with it (solvePose) is cheap enough for every mouse move. The kinds'
// own halves live in pins/ and cage/.
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

// Identity of an object's rest drawing for meshing: its (immutable, shared) stroke data, mesh
// density and the document's Close gaps distance (the shape is its regions closed as the Fill
// tool closes them, and its ink). Undo restores the same pointers, so it finds the same mesh
// again.
struct MeshKey {
    std::vector<StrokeDataPtr> strokes;
    double density = kDefaultMeshDensity;
    double closeGap = -1.0; // DocumentSettings::closeGap: < 0 automatic
    // A picture object's picture (picture/picture_object.h): its texture mesh is the object's
    // mesh, and its vertices are rest points after the strokes' (restPoints).
    std::shared_ptr<const ObjectPicture> picture;
    // Pictures compare by what they are (the same pixels and texture mesh at the same place),
    // not by which object holds them: each object of an opened file holds its own.
    friend bool operator==(const MeshKey &a, const MeshKey &b);
    static MeshKey of(const StrokeGroup &group, double closeGap);
};

// An object's rest mesh with every rest stroke point embedded in it.
struct MeshedObject {
    geometry::ObjectMesh mesh;
    geometry::Embedding embedding;          // all rest points, stroke after stroke
    std::vector<std::size_t> strokeOffsets; // first point of each stroke; size strokes+1
};

// What a precompute needs, as an immutable snapshot: the drawing, the rig's rest definition
// (its targets are ignored: they only re-solve) and the solver options.
struct DeformJob {
    Id groupId = kNoId;
    MeshKey key;
    std::shared_ptr<const MeshedObject> meshed; // reused when the key is unchanged
    Rig rig;                                    // rest definition; RigKind::None = mesh only
    deform::ArapOptions options;
};

struct PinSetup;      // pins/pin_setup.h
struct CageSetup;     // cage/cage_setup.h
struct SkeletonSetup; // skeleton/skeleton_setup.h

// An object's deformer, ready to solve: the precompute of its rig kind for one drawing and
// one rest definition. Immutable and shared (a duplicated frame shares its source's setup).
struct DeformSetup {
    MeshKey key;
    Rig rest;                    // the rest definition it was built for (targets at rest)
    deform::ArapOptions options; // the solver options it was built with
    std::shared_ptr<const MeshedObject> meshed;    // the object's mesh (pins, mesh only)
    std::shared_ptr<const PinSetup> pins;          // RigKind::Pins
    std::shared_ptr<const CageSetup> cage;         // RigKind::Cage
    std::shared_ptr<const SkeletonSetup> skeleton; // RigKind::Skeleton

    RigKind kind() const { return rest.kind(); }
    // The mesh the deformer moves, for Show Mesh and for mapping clicks back to rest: the
    // object's own mesh, or the interior mesh of the cage. V n×2 at rest, F m×3.
    const Eigen::MatrixX2d &meshVertices() const;
    const Eigen::MatrixX3i &meshTriangles() const;

    // Whether this setup serves `group` as it is now: same drawing, same Close gaps, same rest
    // definition (pin ids may differ).
    bool matches(const StrokeGroup &group, double closeGap) const;
};

// Meshes and embeds the rest strokes. Errors are sentences for the user.
Expected<std::shared_ptr<const MeshedObject>, QString> meshObject(const MeshKey &key);

// Runs a whole job (mesh when the kind needs one, then the kind's precompute). `cancelled` is
// polled between stages.
Expected<std::shared_ptr<const DeformSetup>, QString>
buildDeformSetup(const DeformJob &job, const std::function<bool()> &cancelled = {});

// Whether two ARAP option sets give the same poses (method and extra passes).
bool sameSolverOptions(const deform::ArapOptions &a, const deform::ArapOptions &b);

// How good a pose must be. Preview: the paper's two steps only, for many poses at once (frames
// just inserted) until their converged poses arrive. Drag: what fits a mouse move (a fixed
// number of refinement passes, chosen at precompute time). Final: converged, for every pose
// that is kept, saved, exported or baked. Only pins refine; cages are exact either way.
enum class PoseStage { Preview, Drag, Final };

// Solves the pose for the rig's current targets: the deformed mesh vertices (n×2, rows of
// meshVertices()) and the deformed strokes. A pure function of the setup, the targets and the
// stage, and for a Drag pose of pins of `dragStart` when given: the pose the drag showed last
// for this setup (meshVertices() rows), which the event continues from (deform::
// arapSolveFrom); other stages and kinds ignore it. `cancelled` is polled between refinement
// passes.
struct Pose {
    Eigen::MatrixX2d vertices;
    DeformedStrokesPtr strokes;
};
Expected<Pose, QString> solvePose(const DeformSetup &setup, const StrokeGroup &group,
                                  PoseStage stage = PoseStage::Final,
                                  const std::function<bool()> &cancelled = {},
                                  const Eigen::MatrixX2d *dragStart = nullptr);

// Deformed strokes from one deformed position per rest point (rows in stroke order, as
// MeshedObject::strokeOffsets counts them, then the picture's vertices); pressures are the
// rest ones.
DeformedStrokesPtr strokesFromPoints(const StrokeGroup &group, const Eigen::MatrixX2d &points);

// The rest strokes as the geometry layer takes them (points and widths).
std::vector<geometry::StrokeInput> strokeInputs(const MeshKey &key);

// All rest points of an object, stroke after stroke, then a picture object's texture mesh
// vertices (uv + origin); offsets gets each stroke's first row (size strokes + 1: its last
// entry is where the picture's vertices begin).
Eigen::MatrixX2d restPoints(const MeshKey &key, std::vector<std::size_t> &offsets);

// Maps a point shown on a deformed object back to the rest drawing (for placing a pin on a
// posed object): the deformed triangle containing it, or the nearest, then its barycentrics.
QPointF restPointFor(const DeformSetup &setup, const Eigen::MatrixX2d &deformedVertices,
                     QPointF shown);

} // namespace finbook::model
