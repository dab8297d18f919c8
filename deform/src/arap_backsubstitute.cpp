#include "arap_internal.h"

#include <finbook/deform/arap.h>

namespace finbook::deform {

namespace detail {
namespace {

// What both kernels walk: stepTwoLower (compressed columns, the diagonal first in each) and
// the reciprocal pivots.
struct StepTwoFactor {
    const int *start;
    const int *row;
    const double *value;
    const double *pivotInverse;
    Eigen::Index n;
};

StepTwoFactor stepTwoFactor(const ArapPrecompute &data)
{
    const auto &L = data.stepTwoLower;
    return {L.outerIndexPtr(), L.innerIndexPtr(), L.valuePtr(), data.stepTwoPivotInverse.data(),
            L.cols()};
}

} // namespace
} // namespace detail

// Eigen's sparse triangular solve with a real factor and a complex right-hand side promotes
// the pivot to complex and divides through __divdc3 on every row; written out, each row is
// a multiply by the stored reciprocal pivot and real × complex updates (stepTwoLower is
// column-major with the diagonal first in each column).
void arapStepTwoBacksubstitute(const ArapPrecompute &data, Eigen::Ref<Eigen::VectorXcd> x)
{
    const auto [start, row, value, pivotInverse, n] = detail::stepTwoFactor(data);
    detail::Complex *y = x.data();
    for (Eigen::Index j = 0; j < n; ++j) { // L y = b, column by column
        const detail::Complex yj = y[j] * pivotInverse[j];
        y[j] = yj;
        for (int p = start[j] + 1; p < start[j + 1]; ++p)
            y[row[p]] -= value[p] * yj;
    }
    for (Eigen::Index j = n - 1; j >= 0; --j) { // Lᵀ x = y, row by row of Lᵀ
        detail::Complex sum = y[j];
        for (int p = start[j] + 1; p < start[j + 1]; ++p)
            sum -= value[p] * y[row[p]];
        y[j] = sum * pivotInverse[j];
    }
}

namespace detail {

void backsubstituteBlock(const ArapPrecompute &data, Complex *x)
{
    constexpr int B = kBlockWidth;
    const auto [start, row, value, pivotInverse, n] = detail::stepTwoFactor(data);
    for (Eigen::Index j = 0; j < n; ++j) { // L y = b
        // Where all B are still zero the column adds nothing: right-hand sides with entries
        // in a few regions (coarse clusters) only travel up the elimination tree from them.
        bool zero = true;
        for (int b = 0; b < B; ++b)
            zero = zero && x[j * B + b] == Complex(0.0, 0.0);
        if (zero)
            continue;
        Complex yj[B];
        for (int b = 0; b < B; ++b)
            yj[b] = x[j * B + b] = x[j * B + b] * pivotInverse[j];
        for (int p = start[j] + 1; p < start[j + 1]; ++p) {
            Complex *target = x + Eigen::Index(row[p]) * B;
            for (int b = 0; b < B; ++b)
                target[b] -= value[p] * yj[b];
        }
    }
    for (Eigen::Index j = n - 1; j >= 0; --j) { // Lᵀ x = y
        Complex sum[B];
        for (int b = 0; b < B; ++b)
            sum[b] = x[j * B + b];
        for (int p = start[j] + 1; p < start[j + 1]; ++p) {
            const Complex *source = x + Eigen::Index(row[p]) * B;
            for (int b = 0; b < B; ++b)
                sum[b] -= value[p] * source[b];
        }
        for (int b = 0; b < B; ++b)
            x[j * B + b] = sum[b] * pivotInverse[j];
    }
}

} // namespace detail

} // namespace finbook::deform
