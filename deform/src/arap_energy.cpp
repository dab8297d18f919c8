#include "arap_internal.h"

#include <finbook/deform/arap.h>

#include <Eigen/LU>

#include <cmath>

namespace finbook::deform {

double arapEnergy(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, const Eigen::MatrixX2d &U)
{
    using detail::Complex;
    double energy = 0.0;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        Complex r[3], p[3];
        for (int k = 0; k < 3; ++k) {
            r[k] = Complex(V(F(t, k), 0), V(F(t, k), 1));
            p[k] = Complex(U(F(t, k), 0), U(F(t, k), 1));
        }
        const Complex restCentroid = (r[0] + r[1] + r[2]) / 3.0;
        const Complex centroid = (p[0] + p[1] + p[2]) / 3.0;
        for (int k = 0; k < 3; ++k) {
            r[k] -= restCentroid;
            p[k] -= centroid;
        }
        // Any rotation is optimal for a fully collapsed triangle; 0 keeps identity then.
        const Complex rotation = detail::bestRotation(r, p, 0.0);
        for (int k = 0; k < 3; ++k) {
            const int j = (k + 1) % 3;
            energy += detail::squaredMagnitude((p[j] - p[k]) - rotation * (r[j] - r[k]));
        }
    }
    return energy;
}

double arapCotangentEnergy(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                           const Eigen::MatrixX2d &U)
{
    double energy = 0.0;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        Eigen::Matrix2d rest, deformed; // edges 0→1 and 0→2 as columns
        for (int k = 1; k < 3; ++k) {
            rest.col(k - 1) = (V.row(F(t, k)) - V.row(F(t, 0))).transpose();
            deformed.col(k - 1) = (U.row(F(t, k)) - U.row(F(t, 0))).transpose();
        }
        const double det = rest.determinant();
        const Eigen::Matrix2d J = deformed * rest.inverse();
        // max over rotations R of tr(RᵀJ) is |(J00 + J11, J10 − J01)|, so
        // ‖J − R‖² = ‖J‖² + 2 − 2·that for the closest rotation.
        const double trace = std::hypot(J(0, 0) + J(1, 1), J(1, 0) - J(0, 1));
        energy += 0.5 * std::abs(det) * (J.squaredNorm() + 2.0 - 2.0 * trace);
    }
    return energy;
}

std::vector<int> arapFlippedTriangleRows(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                                         const Eigen::MatrixX2d &U)
{
    const auto doubleArea = [](const Eigen::MatrixX2d &P, const Eigen::RowVector3i &t) {
        const Eigen::RowVector2d e1 = P.row(t(1)) - P.row(t(0)), e2 = P.row(t(2)) - P.row(t(0));
        return e1.x() * e2.y() - e1.y() * e2.x();
    };
    std::vector<int> rows;
    for (Eigen::Index t = 0; t < F.rows(); ++t)
        if (doubleArea(V, F.row(t)) * doubleArea(U, F.row(t)) < 0.0)
            rows.push_back(int(t));
    return rows;
}

int arapFlippedTriangles(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                         const Eigen::MatrixX2d &U)
{
    return int(arapFlippedTriangleRows(V, F, U).size());
}

} // namespace finbook::deform
