// Precompute and solve for the ARAP tests: a failure is printed and yields null / an empty
// matrix, so the test's own checks say what went wrong.
#pragma once

#include <finbook/deform/arap.h>

#include <QTest>

#include <memory>

namespace finbook::test {

inline std::shared_ptr<const deform::ArapPrecompute> precompute(const Eigen::MatrixX2d &V,
                                                                const Eigen::MatrixX3i &F,
                                                                const Eigen::VectorXi &b,
                                                                deform::ArapOptions options = {})
{
    auto result = deform::arapPrecompute(V, F, b, options);
    if (!result)
        qWarning("precompute failed: %s", result.error().message.c_str());
    return result ? *result : nullptr;
}

inline Eigen::MatrixX2d solved(const deform::ArapPrecompute &data, const Eigen::MatrixX2d &bc,
                               deform::ArapStage stage, deform::ArapSolveReport *report = nullptr)
{
    Eigen::MatrixX2d U;
    auto result = deform::arapSolve(data, bc, U, stage);
    if (!result)
        qWarning("solve failed: %s", result.error().message.c_str());
    if (result && report)
        *report = *result;
    return result ? U : Eigen::MatrixX2d();
}

} // namespace finbook::test
