// What the fit's translation units share: the precomputed source and target, and the steps
// of the fit (coarse alignment, rigid ICP, ARAP ICP, the residual report).
#pragma once

#include "mesh_system.h"
#include "point_grid.h"

#include <finbook/deform/between/rigid_fit.h>

#include <Eigen/Core>

#include <array>
#include <complex>
#include <optional>
#include <vector>

namespace finbook::deform::between {

struct RigidFitSource {
    Eigen::MatrixX2d V;    // n×2 rest
    Eigen::MatrixX3i F;    // m×3
    Eigen::VectorXi I;     // k: the samples' triangles
    Eigen::MatrixX3d B;    // k×3: their barycentric weights
    Eigen::MatrixX2d N;    // k×2 unit normals (rest)
    Eigen::MatrixX2d rest; // k×2 rest sample positions
    // Per triangle and corner k: ½ cot of the angle at k (the weight of the opposite edge,
    // the standard ARAP energy's) and the rest corner as x+iy.
    Eigen::MatrixX3d edgeWeight;
    Eigen::MatrixX3cd corner;
    double restSquaredNorm = 0.0; // Σ_t Σ_k w_k |rest edge opposite k|² (global scale fit)
    double sampleDiagonal = 0.0;  // of the rest samples' bounding box
    double area = 0.0;            // of the mesh (rest)
    // What options' dimensionless stiffness is multiplied by in the system, whose data term
    // has total weight n: D²·n / area (see RigidFitOptions::stiffness).
    double stiffnessUnit = 1.0;
    detail::MeshSystem system; // analysed, not factored: every fit copies it
    // Hinges between pieces meshed apart (rigidFitPrecompute), as the system's links; per hinge
    // the vertices of the piece its second vertex lies in, and that piece's samples.
    std::vector<std::array<int, 2>> hinges;
    std::vector<std::vector<int>> hingedVertices, hingedSamples;

    int vertexCount() const { return int(V.rows()); }
    int sampleCount() const { return int(I.size()); }
};

struct RigidFitTarget {
    Eigen::MatrixX2d P; // k×2
    Eigen::MatrixX2d N; // k×2 unit (or zero) normals
    detail::PointGrid grid;
    double diagonal = 0.0;
};

namespace detail {

using Complex = std::complex<double>;

// x ↦ linear·x + translation.
struct Similarity {
    Eigen::Matrix2d linear = Eigen::Matrix2d::Identity();
    Eigen::Vector2d translation = Eigen::Vector2d::Zero();
    Eigen::MatrixX2d apply(const Eigen::MatrixX2d &P) const
    {
        return (P * linear.transpose()).rowwise() + translation.transpose();
    }
};

// Σ_k B(s,k)·X(F(I(s),k)) for every sample (k×2).
Eigen::MatrixX2d samplePositions(const RigidFitSource &source, const Eigen::MatrixX2d &U);
Eigen::MatrixX2d pinPositions(const RigidFitSource &source, const FitPins &pins,
                              const Eigen::MatrixX2d &U);

// Best rotation (and scale, when allowScale) with translation taking the rows of X onto
// those of Y, weights w (Umeyama 1991; no reflection). Identity when degenerate.
Similarity procrustes(const Eigen::MatrixX2d &X, const Eigen::MatrixX2d &Y,
                      const Eigen::VectorXd &w, bool allowScale);

// Mean nearest-point distance from A's points to B's plus from B's to A's.
double symmetricChamfer(const Eigen::MatrixX2d &A, const RigidFitTarget &target);

// Coarse alignment of the rest samples to B (moments, then pins), then rigid ICP.
// `unturned` (optional) gets the candidate that does not turn A (the chosen one when pins
// place A).
Similarity coarseAlignment(const RigidFitSource &source, const RigidFitTarget &target,
                           const FitPins &pins, const RigidFitOptions &options, double &chamfer,
                           Similarity *unturned = nullptr);
Similarity rigidIcp(const RigidFitSource &source, const RigidFitTarget &target, const FitPins &pins,
                    const RigidFitOptions &options, Similarity start);

// One more start for rigidFit: rigid ICP (of a few of A's samples) from `start` turned by each
// twelfth of a full turn about the centroids, and the placement whose lines lie closest
// (symmetric chamfer), when it lies closer than fromStart (rigid ICP from start itself) by a
// clear margin and turns A by at most a quarter turn. The moments' axes can turn a drawing
// whose limbs B poses otherwise by half a turn, and rigid ICP from there stays upside down.
std::optional<Similarity> turnSwept(const RigidFitSource &source, const RigidFitTarget &target,
                                    const RigidFitOptions &options, const Similarity &start,
                                    const Similarity &fromStart);

// The articulated coarse step (rigidFit with a FitSkeleton): the n×2 vertices to start the
// ARAP stages from, `global` applied and then each bone's part turned about its base joint,
// judged by the samples of everything below it (Subtrees, ±90°), or the body placed first by its
// own samples and each bone judged by its own (BodyFirst, ±120°). A skeleton without a bone
// gives global.apply(V).
enum class ArticulatedStart { Subtrees, BodyFirst };
Eigen::MatrixX2d articulatedStart(const RigidFitSource &source, const RigidFitTarget &target,
                                  const Similarity &global, const FitSkeleton &skeleton,
                                  const RigidFitOptions &options, ArticulatedStart style);
// Each piece hinged to another (RigidFitSource::hinges), in the hinges' order: moved onto its
// hinge where U has the other piece, then turned about it by the angle in ±180° that lays its
// own samples best on B (capped nearest-agreeing distances, as articulatedStart judges a bone;
// ties to the smaller turn). A piece is a rigid part drawn over another, with a known pivot, so
// it can be searched all the way round: an arm B shows across the chest is found from one
// hanging at the side.
Eigen::MatrixX2d turnHingedPieces(const RigidFitSource &source, const RigidFitTarget &target,
                                  Eigen::MatrixX2d U, const RigidFitOptions &options);
// Pins valid for this source: triangles in range, finite weights and targets.
bool pinsValid(const RigidFitSource &source, const FitPins &pins);

// Fills residual, percentiles, coverage, worst samples and status/message of r from r.U.
void reportResidual(const RigidFitSource &source, const RigidFitTarget &target,
                    const RigidFitOptions &options, RigidFitResult &r);

// Nearest-agreeing pairs for the current sample positions X (k×2) and normals M (k×2):
// A→B (sample s ↦ B point) and, when symmetric, B→A (B point ↦ sample), with far pairs
// dropped. Each pair: sample, target position, weight (each direction's weights add up to 1,
// or ½ each when symmetric). abCount: the A→B pairs, which come first.
struct Pairs {
    std::vector<int> sample;
    std::vector<Eigen::Vector2d> target;
    std::vector<double> weight;
    int abCount = 0;
};
Pairs findPairs(const RigidFitSource &source, const RigidFitTarget &target,
                const Eigen::MatrixX2d &X, const Eigen::MatrixX2d &M,
                const RigidFitOptions &options);

double percentileOf(std::vector<double> values, double p);

} // namespace detail
} // namespace finbook::deform::between
