// Internal: a picture object's cut-out pose as drawn (DeformedStrokes::pictureLayers; issue 51).
//
// Cut-out skinning cuts the object's mesh at the joints and turns each piece rigidly over the one
// above it (deform/skeleton/cut_out.h). A picture object's mesh is its texture mesh itself, so
// the cut mesh, posed, is the picture cut into pieces: each triangle keeps its texture
// coordinates and moves with its own piece, and a vertex on a cut is one vertex per piece. Drawn
// through the uncut mesh, the triangles across a cut would stretch over the turn instead.
//
// A turned limb leaves a wedge on the outer side of the bend that neither piece covers. Each
// cut's socket fills it from the picture's own pixels: the cut's round end (the disk at its
// joint inside the outline), textured from the limb's half of that disk at rest (mirrored across
// the cut on the other half) and turned with the limb's bone, drawn under every piece so it
// shows only in the gaps.
#pragma once

#include <finbook/deform/skeleton/cut_out.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/types.h>

#include <Eigen/Core>

namespace finbook::model {

// Segments of a socket's disk (its outline is off the circle by at most r·(1 − cos(π/32)), a
// twentieth of a pixel for a 40 px joint).
inline constexpr int kSocketSegments = 32;

// `picture`'s layers in the cut-out pose: `cut` is the cut of the picture's own texture mesh
// (cut.source rows index picture.mesh->uv), `U` its posed vertices (cut.V rows), `rest` the
// skinning skeleton at rest and `posed` the same posed. Sockets first (cuts' order), then the
// roots' piece's triangles, then each cut's piece's (parents before children), each in the
// order of cut.F. Empty when the inputs do not fit together.
PictureLayers cutOutPictureLayers(const ObjectPicture &picture, const deform::CutMesh &cut,
                                  const Eigen::MatrixX2d &U, const deform::Skeleton &rest,
                                  const deform::PosedSkeleton &posed);

} // namespace finbook::model
