// Cut-out joints (issue 21): the mesh cut apart at the joints where a limb bends, so each
// piece turns rigidly over the one above it, as a cut-out puppet's paper limbs do, instead
// of bending flesh that folds once the turn passes about 45°.
//
// A joint is cut from the outline point nearest it on one side of its child bone, through the
// joint, to the nearest on the other side (where its inscribed circle touches the outline, so
// the cut piece keeps a round end), when both lie within `reach` inscribed radii and on
// opposite sides of the joint, and that cut separates the mesh: what lies past it (flooded
// from the child bone's side without crossing it) does not reach back round to the parent's
// side.
// At a junction (two or more children, or the root) each limb hanging from it (a chain of
// bones out to a tip) is cut the same way, its contacts taken between its bone and the
// neighbouring bones on either side, so the limb turns there as a piece over the body; at the
// root one limb, the heaviest, stays with the body when every child is such a limb. Tips and
// joints in the middle of a wide shape are not cut; the skinning blends across them as before.
// Cut pieces nest: an elbow's piece lies inside its shoulder's.
// A shape with a hole is parted where its skeleton broke the loop round the hole (a tip with
// a joint near it through the shape but far along the bones, the loop between them going
// round a hole): no cut's piece reaches past that line, so each side of a ring is a limb of
// its own. Triangles two cuts leave between them, parted from the rest of their piece, join
// the neighbouring piece they share most edges with, so no island of a piece floats free.
//
// Each cut has a round end: the disk round its joint that touches the outline. It lies inside
// the drawing and turns onto itself with either piece; painted under a turned limb in the
// limb's colour (a socket) it closes the gap on the outer side of the bend, as a cut-out
// puppet's round joint does.
//
// The cut mesh keeps every triangle, in the same order (so a point embedded in the mesh keeps
// its triangle and barycentric coordinates); a vertex whose triangles lie in different pieces
// is copied once per piece. Skinned with cutOutWeights, every piece follows only its own bones:
// a piece with one bone moves exactly with it, and the drawing's lines across a cut run
// straight from one piece to the next (a chord of the joint's round end).
#pragma once

#include <finbook/deform/deform_error.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/deform/skeleton/skinning_weights.h>
#include <finbook/geometry/expected.h>

#include <Eigen/Core>

#include <vector>

namespace finbook::deform {

struct CutOutOptions {
    // A cut's ends may lie at most this many inscribed radii from its joint.
    double reach = 1.75;
    // ...but one of them may lie up to this many when the other is within `reach`: a limb
    // leaving the body at a slant (a tail off the rump) meets the body's outline far off on
    // its outer side.
    double farReach = 3.0;
    // Each end is looked for on its side of the child bone within this angle of it
    // (radians): not behind the joint, where the outline of a limb leaving at a slant runs
    // on along the body.
    double sideAngle = 0.75 * 3.14159265358979323846;
};

struct JointCut {
    int joint = -1;                              // the joint cut (its child bone's pivot)
    int child = -1;                              // the child joint whose bone the piece starts
    Eigen::Vector2d a = Eigen::Vector2d::Zero(); // the cut runs from a through the joint to b
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    double round = 0.0; // the joint's round end: its distance to the outline (the socket's disk)
};

struct CutMesh {
    Eigen::MatrixX2d V;     // rest vertices: the input's, then the copies along the cuts
    Eigen::MatrixX3i F;     // the input's triangles, same order, copies where pieces differ
    Eigen::VectorXi source; // V row → input vertex (the first n rows are the input's)
    // Per triangle: the cut joint whose piece holds it (the deepest cut above it), −1 for the
    // piece around the skeleton's roots.
    Eigen::VectorXi piece;
    std::vector<JointCut> cuts; // in the skeleton's topological order (parents first)
    // Per cut piece (cuts' order), its outline: loops of V rows as its triangles run (the
    // shape's outline and the cuts), for drawing the piece over the ones before it.
    std::vector<std::vector<std::vector<int>>> outlines;
    // The roots' piece's outline, as `outlines` (empty when nothing was cut).
    std::vector<std::vector<int>> rootOutline;
    // Per cut, the piece above it (−1 the roots').
    std::vector<int> parentPiece;
    int pieceCount() const { return int(cuts.size()) + 1; }
};

// V n×2, F m×3 as for computeSkinningWeights; radius J inscribed radii (joints with radius ≤ 0
// are not cut). Never fails on valid input: a skeleton with no cuttable joint gives the mesh
// unchanged (no cuts, every triangle in piece −1). Errors: SizeMismatch (radius not J
// entries), InvalidIndex (F out of range).
Expected<CutMesh, DeformError> cutAtJoints(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                           const Skeleton &skeleton, const Eigen::VectorXd &radius,
                                           const CutOutOptions &options = {});

// The piece each joint's bone belongs to (−1 for the roots' piece): bone j lies in the piece
// of the cut that starts with it, else in its parent's bone's piece. J entries.
Eigen::VectorXi bonePieces(const Skeleton &skeleton, const CutMesh &cut);

// Weights of the cut mesh: each vertex keeps only the handles of its piece, renormalised (a
// vertex whose weight lay wholly on other pieces' bones takes its piece's first bone), and a
// boundary condition (owner) on another piece's bone is dropped. `weights` are those of the
// uncut mesh the cut was made from.
SkinningWeights cutOutWeights(const SkinningWeights &weights, const Skeleton &skeleton,
                              const CutMesh &cut);

} // namespace finbook::deform
