// Light, Lambert and rim terms (shade/shading.h).
#include <finbook/geometry/shade/shading.h>

#include <algorithm>
#include <cmath>

namespace finbook::geometry {

Eigen::Vector3d lightDirection(double azimuthDegrees, double elevationDegrees)
{
    if (!std::isfinite(azimuthDegrees) || !std::isfinite(elevationDegrees)) {
        azimuthDegrees = 135.0;
        elevationDegrees = 45.0;
    }
    const double a = azimuthDegrees * M_PI / 180.0;
    const double e = std::clamp(elevationDegrees, 0.0, 90.0) * M_PI / 180.0;
    // Counter-clockwise on screen is toward −y in canvas axes (y down).
    return Eigen::Vector3d(std::cos(e) * std::cos(a), -std::cos(e) * std::sin(a), std::sin(e));
}

Eigen::VectorXd diffuseTerm(const Eigen::MatrixX3d &normals, const Eigen::Vector3d &light)
{
    return (normals * light).cwiseMax(0.0).cwiseMin(1.0);
}

Eigen::VectorXd rimTerm(const Eigen::MatrixX3d &normals, const Eigen::Vector3d &light)
{
    Eigen::Vector2d side(light.x(), light.y());
    const double length = side.norm();
    Eigen::VectorXd rim(normals.rows());
    for (Eigen::Index i = 0; i < normals.rows(); ++i) {
        const double away = std::clamp(1.0 - normals(i, 2), 0.0, 1.0);
        // A light straight from the viewer has no far side: the rim runs all round.
        const double opposite =
            length > 1e-9
                ? std::clamp(-(normals(i, 0) * side.x() + normals(i, 1) * side.y()) / length, 0.0,
                             1.0)
                : 1.0;
        rim(i) = away * std::sqrt(opposite);
    }
    return rim;
}

} // namespace finbook::geometry
