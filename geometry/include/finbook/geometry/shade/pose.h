// Posing a rest-space field with a drawing (issue 27's shading): the object's stroke points
// at rest and as shown are the only record of its pose every renderer has (pins, cage and
// skeleton all pose them), so a point of the inflated rest mesh follows the moving-least-
// squares rigid map of the nearest stroke points (Schaefer et al. 2006, weights 1/(d² + ε²)):
// its position moves with them and its normal turns by their best-fit rotation. A limb that
// moves rigidly is mapped exactly (translation and rotation); across a bent joint the map
// blends the two sides' rotations.
//
// Precompute (rest only, once per rest mesh) + apply (per pose: O(n·k), no search).
#pragma once

#include <Eigen/Core>

namespace finbook::geometry {

// Rest data for applyPose: for each of the n points its k nearest controls and their weights,
// one column per point (the layout applyPose walks).
//   index   k×n  control rows (−1 = unused when there are fewer than k controls)
//   weight  k×n  normalized weights (each column sums to 1 when it has a control)
//   offset  n×2  the point minus the weighted rest centroid of its controls
//   rest    m×2  the rest controls (their weighted centroid and spread are re-read per pose)
struct PoseWeights {
    Eigen::MatrixXi index;
    Eigen::MatrixXd weight;
    Eigen::MatrixX2d offset;
    Eigen::MatrixX2d rest;
};

// points n×2 and controls m×2 in rest canvas px. Non-finite controls are ignored. With no
// finite control every point keeps its place (identity). `k` ≥ 1, `epsilon` > 0 (px) keeps
// the weight of a control on the point finite.
PoseWeights poseWeights(const Eigen::MatrixX2d &points, const Eigen::MatrixX2d &controls,
                        int k = 16, double epsilon = 1.0);

// The posed points and the local rotation (radians, in canvas axes: the angle that turns x
// toward y; `turn` holds its cosine and sine) for the controls shown at `posed` (m×2, rows of
// weights.rest). A posed control that is not finite counts as not moved. Promise: finite
// output for finite input.
struct PosedPoints {
    Eigen::MatrixX2d V;
    Eigen::VectorXd angle;
    Eigen::MatrixX2d turn; // n×2: cos, sin of angle
};
// `withAngle` false leaves `angle` empty (one atan2 a point saved; `turn` is always filled).
PosedPoints applyPose(const PoseWeights &weights, const Eigen::MatrixX2d &posed,
                      bool withAngle = true);

// The normals (n×3) turned in the drawing's plane by the angles (n): x, y rotate, z stays.
Eigen::MatrixX3d rotateNormals(const Eigen::MatrixX3d &normals, const Eigen::VectorXd &angle);
// The same with the cosines and sines given (PosedPoints::turn, n×2).
Eigen::MatrixX3d rotateNormals(const Eigen::MatrixX3d &normals, const Eigen::MatrixX2d &turn);

} // namespace finbook::geometry
