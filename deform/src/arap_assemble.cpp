#include "arap_internal.h"

#include <Eigen/SparseCore>

namespace finbook::deform::detail {
namespace {

// Step-1 triangles shrunk below this fraction of their rest size count as collapsed (see
// bestRotation): far below anything a drag produces, far above round-off of a collapse.
constexpr double kCollapseFraction = 1e-8;

// Step-1 form of one triangle: the sum over its three corner orders (a, b, c) of conj(w)·wᵀ,
// where w·z = z_c − (1 − μ) z_a − μ z_b is the corner's deviation from a similarity copy and
// μ = (z_c − z_a)/(z_b − z_a) is the paper's local coordinate x − iy as one complex number.
Eigen::Matrix3cd similarityForm(const Complex z[3])
{
    Eigen::Matrix3cd form = Eigen::Matrix3cd::Zero();
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const Complex edge = z[b] - z[a];
        // Written out: std::complex division goes through the slow, overflow-careful __divdc3.
        const Complex mu = (z[c] - z[a]) * std::conj(edge) / squaredMagnitude(edge);
        Eigen::Vector3cd w;
        w(a) = mu - 1.0;
        w(b) = -mu;
        w(c) = 1.0;
        form += w.conjugate() * w.transpose();
    }
    return form;
}

// Position of entry (row, col) in the value array of a compressed matrix; columns of these
// vertex-adjacency matrices hold a handful of entries, so a linear scan is fastest.
Eigen::Index entryIndex(const Eigen::SparseMatrix<Complex> &m, int row, int col)
{
    Eigen::Index k = m.outerIndexPtr()[col];
    while (m.innerIndexPtr()[k] != row)
        ++k;
    return k;
}

// Adds one triangle's step-1 form to G00 (upper triangle, H00's pattern) and the free-handle
// couplings of both steps. Step 2's form is the triangle's edge-weighted Laplacian: −w off
// the diagonal (w of the edge (r, s), opposite the third corner).
void scatter(const int I[3], const Eigen::Matrix3cd &form, const double w[3], ArapPrecompute &d,
             std::vector<Eigen::Triplet<Complex>> &g01, std::vector<Eigen::Triplet<double>> &h01)
{
    const Eigen::Index nf = d.freeCount;
    for (int r = 0; r < 3; ++r) {
        if (I[r] >= nf)
            continue;
        for (int s = 0; s < 3; ++s) {
            if (I[s] >= nf) {
                g01.emplace_back(I[r], I[s] - nf, form(r, s));
                h01.emplace_back(I[r], I[s] - nf, -w[3 - r - s]); // r ≠ s: one is free
            } else if (I[r] <= I[s]) {
                d.stepOneMatrix.valuePtr()[entryIndex(d.stepOneMatrix, I[r], I[s])] += form(r, s);
            }
        }
    }
}

// Triangles bucketed by their lowest internal vertex index, so that the per-event loop walks
// the solution vector roughly in order instead of jumping across it.
std::vector<Eigen::Index> localityOrder(const std::vector<Eigen::Index> &triangles,
                                        const Eigen::MatrixX3i &F, const std::vector<int> &internal)
{
    const std::size_t n = internal.size();
    std::vector<Eigen::Index> start(n + 1, 0), sorted(triangles.size());
    auto lowest = [&](Eigen::Index t) {
        return std::size_t(std::min({internal[F(t, 0)], internal[F(t, 1)], internal[F(t, 2)]}));
    };
    for (const Eigen::Index t : triangles)
        ++start[lowest(t) + 1];
    for (std::size_t v = 0; v < n; ++v)
        start[v + 1] += start[v];
    for (const Eigen::Index t : triangles)
        sorted[std::size_t(start[lowest(t)]++)] = t;
    return sorted;
}

// Inverts the triangle → corner relation for the free vertices (counting sort), so that step
// 2 can gather each right-hand-side row instead of scattering into shared rows.
void buildCorners(ArapPrecompute &d)
{
    const auto nf = static_cast<int>(d.freeCount);
    const auto m = static_cast<int>(d.triangles.rows());
    d.cornerStart = Eigen::VectorXi::Zero(nf + 1);
    for (int t = 0; t < m; ++t) {
        for (int k = 0; k < 3; ++k) {
            if (d.triangles(t, k) < nf)
                ++d.cornerStart(d.triangles(t, k) + 1);
        }
    }
    for (int v = 0; v < nf; ++v)
        d.cornerStart(v + 1) += d.cornerStart(v);
    d.cornerTriangle.resize(d.cornerStart(nf));
    d.cornerRest.resize(d.cornerStart(nf));
    Eigen::VectorXi next = d.cornerStart.head(nf);
    for (int t = 0; t < m; ++t) {
        for (int k = 0; k < 3; ++k) {
            const int v = d.triangles(t, k);
            if (v < nf) {
                d.cornerTriangle(next(v)) = t;
                d.cornerRest(next(v)++) = d.restWeighted(t, k);
            }
        }
    }
}

// Triangles around every solved vertex (free and handles), by counting sort.
void buildVertexTriangles(ArapPrecompute &d)
{
    const auto solved = static_cast<int>(d.freeCount + d.handleEntry.size());
    const auto m = static_cast<int>(d.triangles.rows());
    d.vertexStart = Eigen::VectorXi::Zero(solved + 1);
    for (int t = 0; t < m; ++t)
        for (int k = 0; k < 3; ++k)
            ++d.vertexStart(d.triangles(t, k) + 1);
    for (int v = 0; v < solved; ++v)
        d.vertexStart(v + 1) += d.vertexStart(v);
    d.vertexTriangle.resize(d.vertexStart(solved));
    Eigen::VectorXi next = d.vertexStart.head(solved);
    for (int t = 0; t < m; ++t)
        for (int k = 0; k < 3; ++k)
            d.vertexTriangle(next(d.triangles(t, k))++) = t;
}

// Edges whose assembled weight is negative: positive off-diagonal entries of H00 (upper
// half) and of H01. An edge facing two angles that add up to exactly 180° (its quad's corners
// on one circle, as a CDT makes them on a regular layout) weighs 0, computed as round-off of
// either sign: entries within kZeroWeight of the largest diagonal entry are 0, not negative.
int countNegativeWeights(const ArapPrecompute &d)
{
    constexpr double kZeroWeight = 1e-12;
    const Eigen::VectorXd diagonal = d.stepTwoMatrix.diagonal();
    const double zero = diagonal.size() > 0 ? kZeroWeight * diagonal.cwiseAbs().maxCoeff() : 0.0;
    int count = 0;
    for (const auto *m : {&d.stepTwoMatrix, &d.stepTwoCoupling}) {
        for (Eigen::Index col = 0; col < m->outerSize(); ++col) {
            for (ArapPrecompute::RealMatrix::InnerIterator it(*m, col); it; ++it) {
                const bool offDiagonal = m == &d.stepTwoCoupling || it.row() < it.col();
                count += offDiagonal && it.value() > zero ? 1 : 0;
            }
        }
    }
    return count;
}

// Per-triangle rest data of row k (see ArapPrecompute::edgeWeight, restWeighted).
void restData(const Complex z[3], const double w[3], Eigen::Index k, ArapPrecompute &d)
{
    const Complex centroid = (z[0] + z[1] + z[2]) / 3.0;
    double norm = 0.0;
    for (int r = 0; r < 3; ++r) {
        d.restCentered(k, r) = z[r] - centroid;
        d.edgeWeight(k, r) = w[r];
        const int a = (r + 1) % 3, b = (r + 2) % 3;
        // Uniform weights: exactly the centred corners, so the paper's method keeps its bits.
        d.restWeighted(k, r) = d.options.method == ArapMethod::Refined
                                   ? (w[b] * (z[r] - z[a]) + w[a] * (z[r] - z[b])) / 3.0
                                   : d.restCentered(k, r);
        norm += w[r] * squaredMagnitude(z[b] - z[a]);
    }
    d.restSquaredNorm(k) = norm;
    d.collapseThreshold(k) = kCollapseFraction * d.restWeighted.row(k).squaredNorm();
    const Complex e1 = z[1] - z[0], e2 = z[2] - z[0];
    d.restDoubleArea(k) = e1.real() * e2.imag() - e1.imag() * e2.real();
}

} // namespace

void assembleArapSystems(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                         const std::vector<Eigen::Index> &triangles,
                         const std::vector<int> &internal, ArapPrecompute &d)
{
    const auto m = static_cast<Eigen::Index>(triangles.size());
    d.triangles.resize(m, 3);
    d.restCentered.resize(m, 3);
    d.edgeWeight.resize(m, 3);
    d.restWeighted.resize(m, 3);
    d.collapseThreshold.resize(m);
    d.restSquaredNorm.resize(m);
    d.restDoubleArea.resize(m);
    const Eigen::SparseMatrix<double> upper = d.stepTwoMatrix.triangularView<Eigen::Upper>();
    d.stepOneMatrix = upper.cast<Complex>();
    d.stepOneMatrix.coeffs().setZero();
    std::vector<Eigen::Triplet<Complex>> g01;
    std::vector<Eigen::Triplet<double>> h01;
    const std::vector<Eigen::Index> sorted = localityOrder(triangles, F, internal);
    for (Eigen::Index k = 0; k < m; ++k) {
        int I[3];
        Complex z[3];
        for (int r = 0; r < 3; ++r) {
            const int v = F(sorted[std::size_t(k)], r);
            I[r] = internal[std::size_t(v)];
            z[r] = Complex(V(v, 0), V(v, 1));
            d.triangles(k, r) = I[r];
        }
        double w[3];
        edgeWeights(z, d.options.method == ArapMethod::Refined, w);
        restData(z, w, k, d);
        scatter(I, similarityForm(z), w, d, g01, h01);
    }
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size();
    d.stepOneCoupling.resize(nf, handles);
    d.stepOneCoupling.setFromTriplets(g01.begin(), g01.end());
    d.stepTwoCoupling.resize(nf, handles);
    d.stepTwoCoupling.setFromTriplets(h01.begin(), h01.end());
    d.stepOneNorm = selfAdjointNorm(d.stepOneMatrix);
    d.negativeWeightEdges = countNegativeWeights(d);
    buildCorners(d);
    buildVertexTriangles(d);
}

} // namespace finbook::deform::detail
