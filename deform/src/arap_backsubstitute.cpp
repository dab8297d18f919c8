#include "arap_internal.h"

#include <finbook/deform/arap.h>

namespace finbook::deform {

// Eigen's sparse triangular solve with a real factor and a complex right-hand side promotes
// the pivot to complex and divides through __divdc3 on every row; written out, each row is
// a multiply by the stored reciprocal pivot and real × complex updates (the L of SimplicialLLT
// is column-major with the diagonal first in each column).
void arapStepTwoBacksubstitute(const ArapPrecompute &data, Eigen::Ref<Eigen::VectorXcd> x)
{
    const auto &L = data.stepTwoFactor.matrixL().nestedExpression();
    const int *start = L.outerIndexPtr();
    const int *row = L.innerIndexPtr();
    const double *value = L.valuePtr();
    const double *pivotInverse = data.stepTwoPivotInverse.data();
    const Eigen::Index n = L.cols();
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

} // namespace finbook::deform
