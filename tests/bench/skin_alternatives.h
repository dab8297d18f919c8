// The skinning weights the notes compare harmonic weights with, for `finbook-bench skin
// --compare` only: Synfig/Moho-style inverse-square distance falloff and unconstrained
// biharmonic weights (the bounded variant, BBW, needs a QP solver; its cost is in the notes),
// plus a measure of weight that crosses gaps in the shape; and the skinning candidates of
// `finbook-bench limbs` (issue 21) that lost to the app's joint zones (README).
#pragma once

#include "../deform/skin_test_support.h"

#include <finbook/deform/skeleton/skinning_weights.h>

#include <Eigen/SparseCholesky>

#include <cmath>
#include <vector>

namespace finbook::bench {

inline double segmentDistance(const Eigen::Vector2d &p, const Eigen::Vector2d &a,
                              const Eigen::Vector2d &b)
{
    const Eigen::Vector2d ab = b - a;
    const double t =
        ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    return (p - a - t * ab).norm();
}

// Euclidean distance from every vertex to every handle's segment (n×J, ∞ for non-handles).
inline Eigen::MatrixXd handleDistances(const Eigen::MatrixX2d &V,
                                       const finbook::deform::Skeleton &skeleton,
                                       const Eigen::VectorXi &handles)
{
    Eigen::MatrixXd D = Eigen::MatrixXd::Constant(V.rows(), skeleton.jointCount(), INFINITY);
    for (const int j : handles) {
        const int p = skeleton.parent(j);
        const Eigen::Vector2d b = skeleton.joints.row(j).transpose();
        const Eigen::Vector2d a = p < 0 ? b : Eigen::Vector2d(skeleton.joints.row(p).transpose());
        for (Eigen::Index v = 0; v < V.rows(); ++v)
            D(v, j) = segmentDistance(V.row(v).transpose(), a, b);
    }
    return D;
}

// w_j ∝ 1 / (d_j² + 1 px²), normalized: weights by distance alone.
inline Eigen::MatrixXd inverseSquareWeights(const Eigen::MatrixXd &D)
{
    Eigen::MatrixXd W = (D.array().square() + 1.0).inverse().matrix();
    for (Eigen::Index v = 0; v < W.rows(); ++v)
        W.row(v) /= W.row(v).sum();
    return W;
}

// Unconstrained biharmonic weights with the same boundary conditions: minimize xᵀ L M⁻¹ L x
// (cotangent L, lumped mass M) per bone. Smooth at the bones but not bounded: the overshoot
// below 0 and above 1 is what BBW's constraints remove at 30–200× the cost.
inline Eigen::MatrixXd biharmonicWeights(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                         const Eigen::VectorXi &owner, Eigen::Index joints)
{
    using Sparse = Eigen::SparseMatrix<double>;
    std::vector<Eigen::Triplet<double>> t;
    Eigen::VectorXd mass = Eigen::VectorXd::Zero(V.rows());
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const Eigen::RowVector2d e1 = V.row(F(f, 1)) - V.row(F(f, 0));
        const Eigen::RowVector2d e2 = V.row(F(f, 2)) - V.row(F(f, 0));
        const double area = 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
        for (int k = 0; k < 3; ++k) {
            const int o = F(f, k), i = F(f, (k + 1) % 3), j = F(f, (k + 2) % 3);
            mass(o) += area / 3.0;
            const Eigen::RowVector2d u = V.row(i) - V.row(o), w = V.row(j) - V.row(o);
            const double c = 0.5 * u.dot(w) / (2.0 * area);
            t.emplace_back(i, j, -c);
            t.emplace_back(j, i, -c);
            t.emplace_back(i, i, c);
            t.emplace_back(j, j, c);
        }
    }
    Sparse L(V.rows(), V.rows());
    L.setFromTriplets(t.begin(), t.end());
    const Sparse Q = L * mass.cwiseInverse().asDiagonal() * L;
    std::vector<int> freeIndex(std::size_t(V.rows()), -1), free;
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (owner(v) < 0) {
            freeIndex[std::size_t(v)] = int(free.size());
            free.push_back(int(v));
        }
    }
    std::vector<Eigen::Triplet<double>> qff;
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(Eigen::Index(free.size()), joints);
    for (Eigen::Index col = 0; col < Q.outerSize(); ++col) {
        for (Sparse::InnerIterator it(Q, col); it; ++it) {
            const int r = freeIndex[std::size_t(it.row())];
            if (r < 0)
                continue;
            const int c = freeIndex[std::size_t(it.col())];
            if (c >= 0)
                qff.emplace_back(r, c, it.value());
            else
                B(r, owner(it.col())) -= it.value();
        }
    }
    Sparse Qff(Eigen::Index(free.size()), Eigen::Index(free.size()));
    Qff.setFromTriplets(qff.begin(), qff.end());
    Eigen::SimplicialLDLT<Sparse> factor(Qff);
    const Eigen::MatrixXd X = factor.solve(B);
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(V.rows(), joints);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (owner(v) >= 0)
            W(v, owner(v)) = 1.0;
        else
            W.row(v) = X.row(freeIndex[std::size_t(v)]);
    }
    return W;
}

// Weight that crosses a gap: weight a vertex takes from a bone whose held vertices are near
// through the air but far through the shape (distance inside the mesh > 2 × straight
// distance + 3 edges; held vertices rather than the bone itself, because the test skeleton's
// straight bones cut corners of curled limbs).
// Counted on the largest component, where the test skeleton lives (smaller lobes follow their
// nearest bone by design). Returns the mean over its vertices; `worst` gets the largest.
inline double crossGapWeight(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                             const Eigen::VectorXi &owner, const Eigen::VectorXi &handles,
                             const Eigen::MatrixXd &W, double &worst)
{
    const finbook::test::MeshGraph g = finbook::test::meshGraph(V, F);
    double h = 0.0;
    for (Eigen::Index f = 0; f < F.rows(); ++f)
        h += (V.row(F(f, 0)) - V.row(F(f, 1))).norm() / double(F.rows());
    Eigen::VectorXd crossing = Eigen::VectorXd::Zero(V.rows());
    const auto length = [](int, int, double l) { return l; };
    // The largest component: the vertices reached from the vertex that reaches most.
    std::vector<double> largest;
    std::vector<bool> seen(std::size_t(V.rows()), false);
    std::size_t bestCount = 0;
    for (int v = 0; v < int(V.rows()); ++v) {
        if (seen[std::size_t(v)])
            continue;
        std::vector<double> d = finbook::test::dijkstra(g, {v}, length);
        std::size_t count = 0;
        for (std::size_t w = 0; w < d.size(); ++w)
            if (std::isfinite(d[w])) {
                seen[w] = true;
                ++count;
            }
        if (count > bestCount) {
            bestCount = count;
            largest = std::move(d);
        }
    }
    for (const int j : handles) {
        std::vector<int> sources;
        for (Eigen::Index v = 0; v < V.rows(); ++v)
            if (owner(v) == j)
                sources.push_back(int(v));
        if (sources.empty())
            continue;
        const std::vector<double> inside = finbook::test::dijkstra(g, sources, length);
        for (Eigen::Index v = 0; v < V.rows(); ++v) {
            double air = INFINITY;
            for (const int u : sources)
                air = std::min(air, (V.row(v) - V.row(u)).squaredNorm());
            if (inside[std::size_t(v)] > 2.0 * std::sqrt(air) + 3.0 * h)
                crossing(v) += std::max(0.0, W(v, j));
        }
    }
    worst = 0.0;
    double sum = 0.0;
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (std::isfinite(largest[std::size_t(v)])) {
            worst = std::max(worst, crossing(v));
            sum += crossing(v);
        }
    }
    return sum / double(std::max<std::size_t>(bestCount, 1));
}

// Rigid pieces, soft joints: the joint zones of deform::withJointZones, and besides the bones'
// own vertices every vertex one bone clearly dominates (its weight ≥ dominance) is held by that
// bone alone (its W row one-hot) outside the zones: bodies and limbs move as pieces exactly with
// their bones, and the rigid mode's ARAP solve places only the flesh where weights blend. For
// rigidSkinPrecompute.
inline finbook::deform::SkinningWeights rigidPieces(const finbook::deform::SkinningWeights &weights,
                                                    const Eigen::MatrixX2d &V,
                                                    const finbook::deform::Skeleton &skeleton,
                                                    const Eigen::VectorXd &radius, double jointFree,
                                                    double dominance)
{
    finbook::deform::SkinningWeights held = weights;
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        Eigen::Index best = 0;
        if (held.owner(v) < 0 && weights.W.row(v).maxCoeff(&best) >= dominance)
            held.owner(v) = int(best);
    }
    finbook::deform::SkinningWeights out =
        finbook::deform::withJointZones(held, V, skeleton, radius, jointFree);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (out.owner(v) >= 0 && weights.owner(v) < 0) {
            out.W.row(v).setZero();
            out.W(v, out.owner(v)) = 1.0;
        }
    }
    return out;
}

// A cut-out puppet on the uncut mesh: every vertex follows only the bone with its largest
// weight (W one-hot), so the shape is cut into pieces where the harmonic weights cross over
// (at the narrowest part between bones) and each piece turns rigidly with its bone. The body
// beyond a limb's base does not move at all; the triangles across a cut stretch, and flip on
// the inner side of a bend (a real cut-out would split them and draw the limb over the body).
inline finbook::deform::SkinningWeights hardCut(const finbook::deform::SkinningWeights &weights)
{
    finbook::deform::SkinningWeights out = weights;
    for (Eigen::Index v = 0; v < out.W.rows(); ++v) {
        Eigen::Index best = 0;
        out.W.row(v).maxCoeff(&best);
        out.W.row(v).setZero();
        out.W(v, best) = 1.0;
    }
    return out;
}

// Skeleton-driven ARAP (issue 21, second pass): outside the joints the shape moves in rigid
// pieces with its bones and only each joint's flesh is solved as rigidly as possible between
// them. Held: every vertex whose largest weight is ≥ dominance (one bone clearly owns it) and
// that lies outside every joint zone, a disk around a joint where bones meet of childZone radii
// on the side of the bones leaving it (the limb that bends) and parentZone radii on the side of
// the bone arriving (the body around a shoulder). thinnest: a joint's radius is the smallest of
// its own and its neighbours' (a junction where a thin limb leaves gets the limb's joint, not
// the body's width). softLimbs: the flesh of limb bones (a bone whose subtree is one chain to a
// tip) is held only along the bone, outside 1 radius of its joints, as the app's rigid_zones
// does; only the body is held in pieces. Held rows are one-hot, so each pin follows exactly its
// bone. A bone left with nothing keeps what its boundary held.
struct SkeletonArapOptions {
    double childZone = 2.0, parentZone = 1.5, dominance = 0.5;
    bool thinnest = false, softLimbs = false;
};

inline finbook::deform::SkinningWeights
skeletonArapHolds(const finbook::deform::SkinningWeights &weights, const Eigen::MatrixX2d &V,
                  const finbook::deform::Skeleton &skeleton, const Eigen::VectorXd &radius,
                  const SkeletonArapOptions &options)
{
    finbook::deform::SkinningWeights out = weights;
    const Eigen::Index J = skeleton.jointCount();
    if (radius.size() != J || weights.W.cols() != J || weights.owner.size() != V.rows())
        return out;
    std::vector<int> degree(std::size_t(J), 0), childCount(std::size_t(J), 0);
    for (Eigen::Index j = 0; j < J; ++j) {
        if (skeleton.parent(j) >= 0) {
            ++degree[std::size_t(j)];
            ++degree[std::size_t(skeleton.parent(j))];
            ++childCount[std::size_t(skeleton.parent(j))];
        }
    }
    // chain[j]: the subtree below j is one chain of bones to a tip (children have larger
    // indices than parents is not guaranteed, so iterate to a fixed point).
    std::vector<char> chain(std::size_t(J), 0);
    for (bool changed = true; changed;) {
        changed = false;
        for (Eigen::Index j = 0; j < J; ++j) {
            char c = childCount[std::size_t(j)] == 0 ? 1 : 0;
            if (childCount[std::size_t(j)] == 1) {
                for (Eigen::Index k = 0; k < J; ++k)
                    if (skeleton.parent(k) == j)
                        c = chain[std::size_t(k)];
            }
            if (c != chain[std::size_t(j)]) {
                chain[std::size_t(j)] = c;
                changed = true;
            }
        }
    }
    Eigen::VectorXd zone = radius;
    for (Eigen::Index j = 0; options.thinnest && j < J; ++j) {
        const int p = skeleton.parent(j);
        if (p >= 0) {
            zone(j) = std::min(zone(j), radius(p));
            zone(p) = std::min(zone(p), radius(j));
        }
    }
    std::vector<int> held(std::size_t(J), 0);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        Eigen::Index best = 0;
        const double w = weights.W.row(v).maxCoeff(&best);
        int bone = weights.owner(v) >= 0 ? weights.owner(v) : int(best);
        const bool soft = options.softLimbs && chain[std::size_t(bone)];
        if (weights.owner(v) < 0 && (soft || !(w >= options.dominance)))
            bone = -1;
        for (Eigen::Index j = 0; bone >= 0 && j < J; ++j) {
            if (degree[std::size_t(j)] < 2)
                continue;
            const double factor = soft                         ? 1.0
                                  : skeleton.parent(bone) == j ? options.childZone
                                                               : options.parentZone;
            const double r = factor * (soft ? radius(j) : zone(j));
            if ((V.row(v) - skeleton.joints.row(j)).squaredNorm() < r * r)
                bone = -1;
        }
        out.owner(v) = bone;
        if (bone >= 0)
            ++held[std::size_t(bone)];
    }
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        const int o = weights.owner(v);
        if (o >= 0 && held[std::size_t(o)] == 0)
            out.owner(v) = o;
    }
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (out.owner(v) >= 0) {
            out.W.row(v).setZero();
            out.W(v, out.owner(v)) = 1.0;
        }
    }
    return out;
}

} // namespace finbook::bench
