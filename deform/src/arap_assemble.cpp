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
        const Complex mu = (z[c] - z[a]) / (z[b] - z[a]);
        Eigen::Vector3cd w;
        w(a) = mu - 1.0;
        w(b) = -mu;
        w(c) = 1.0;
        form += w.conjugate() * w.transpose();
    }
    return form;
}

struct Triplets {
    std::vector<Eigen::Triplet<Complex>> g00, g01;
    std::vector<Eigen::Triplet<double>> h00, h01;
};

// Splits one triangle's local forms into the free-free (upper triangle only, which is all
// SimplicialLLT<Upper> reads) and free-handle blocks. Step 2's form is the graph Laplacian of
// the triangle's three edges: 2 on the diagonal, −1 off it.
void scatter(const int I[3], Eigen::Index nf, const Eigen::Matrix3cd &form, Triplets &out)
{
    for (int r = 0; r < 3; ++r) {
        if (I[r] >= nf)
            continue;
        for (int s = 0; s < 3; ++s) {
            const double laplacian = r == s ? 2.0 : -1.0;
            if (I[s] >= nf) {
                out.g01.emplace_back(I[r], I[s] - nf, form(r, s));
                out.h01.emplace_back(I[r], I[s] - nf, laplacian);
            } else if (I[r] <= I[s]) {
                out.g00.emplace_back(I[r], I[s], form(r, s));
                out.h00.emplace_back(I[r], I[s], laplacian);
            }
        }
    }
}

// ‖A‖∞ of the full self-adjoint matrix whose upper triangle is stored.
template <class Scalar> double selfAdjointNorm(const Eigen::SparseMatrix<Scalar> &upper)
{
    Eigen::VectorXd rowSum = Eigen::VectorXd::Zero(upper.rows());
    for (Eigen::Index col = 0; col < upper.outerSize(); ++col) {
        for (typename Eigen::SparseMatrix<Scalar>::InnerIterator it(upper, col); it; ++it) {
            rowSum(it.row()) += std::abs(it.value());
            if (it.row() != it.col())
                rowSum(it.col()) += std::abs(it.value());
        }
    }
    return rowSum.size() > 0 ? rowSum.maxCoeff() : 0.0;
}

} // namespace

void assembleArapSystems(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                         const std::vector<Eigen::Index> &triangles,
                         const std::vector<int> &internal, ArapPrecompute &d)
{
    const auto m = static_cast<Eigen::Index>(triangles.size());
    const Eigen::Index nf = d.freeCount, handles = d.handleEntry.size();
    d.triangles.resize(m, 3);
    d.restCentered.resize(m, 3);
    d.collapseThreshold.resize(m);
    Triplets tr;
    for (auto *list : {&tr.g00, &tr.g01})
        list->reserve(std::size_t(m) * 6);
    tr.h00.reserve(std::size_t(m) * 6);
    tr.h01.reserve(std::size_t(m) * 6);
    for (Eigen::Index k = 0; k < m; ++k) {
        int I[3];
        Complex z[3];
        for (int r = 0; r < 3; ++r) {
            const int v = F(triangles[std::size_t(k)], r);
            I[r] = internal[std::size_t(v)];
            z[r] = Complex(V(v, 0), V(v, 1));
            d.triangles(k, r) = I[r];
        }
        const Complex centroid = (z[0] + z[1] + z[2]) / 3.0;
        for (int r = 0; r < 3; ++r)
            d.restCentered(k, r) = z[r] - centroid;
        d.collapseThreshold(k) = kCollapseFraction * d.restCentered.row(k).squaredNorm();
        scatter(I, nf, similarityForm(z), tr);
    }
    d.stepOneMatrix.resize(nf, nf);
    d.stepOneMatrix.setFromTriplets(tr.g00.begin(), tr.g00.end());
    d.stepOneCoupling.resize(nf, handles);
    d.stepOneCoupling.setFromTriplets(tr.g01.begin(), tr.g01.end());
    d.stepTwoMatrix.resize(nf, nf);
    d.stepTwoMatrix.setFromTriplets(tr.h00.begin(), tr.h00.end());
    d.stepTwoCoupling.resize(nf, handles);
    d.stepTwoCoupling.setFromTriplets(tr.h01.begin(), tr.h01.end());
    d.stepOneNorm = selfAdjointNorm(d.stepOneMatrix);
    d.stepTwoNorm = selfAdjointNorm(d.stepTwoMatrix);
}

} // namespace finbook::deform::detail
