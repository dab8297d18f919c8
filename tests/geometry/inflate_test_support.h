// Shapes and measures shared by tst_inflate and `finbook-bench inflate`.
#pragma once

#include "geometry_test_support.h"

#include <finbook/geometry/inflate/inflation.h>
#include <finbook/geometry/object_shape.h>
#include <finbook/geometry/polygon_repair.h>

#include <QJsonArray>
#include <QJsonObject>

#include <Eigen/Geometry>

#include <cmath>

namespace finbook::test {

// A capsule along x centred at the origin: straight sides of length 2·halfLength, ends
// semicircles of radius halfWidth with arcPoints points each, positive shoelace area.
inline Eigen::MatrixX2d capsuleRing(double halfLength, double halfWidth, int arcPoints)
{
    Eigen::MatrixX2d ring(2 * arcPoints, 2);
    for (int i = 0; i < arcPoints; ++i) {
        const double t = -M_PI / 2 + M_PI * i / (arcPoints - 1);
        ring.row(i) << halfLength + halfWidth * std::cos(t), halfWidth * std::sin(t);
        ring.row(arcPoints + i) << -halfLength - halfWidth * std::cos(t), -halfWidth * std::sin(t);
    }
    return ring;
}

// Area-weighted normals of the triangles of the sampled surface (x, y, height), per vertex.
inline Eigen::MatrixX3d heightFieldNormals(const geometry::Inflation &inflation)
{
    Eigen::MatrixX3d normals = Eigen::MatrixX3d::Zero(inflation.V.rows(), 3);
    for (Eigen::Index f = 0; f < inflation.F.rows(); ++f) {
        Eigen::Vector3d p[3];
        for (int k = 0; k < 3; ++k) {
            const int v = inflation.F(f, k);
            p[k] << inflation.V(v, 0), inflation.V(v, 1), inflation.height(v);
        }
        const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
        for (int k = 0; k < 3; ++k)
            normals.row(inflation.F(f, k)) += n.transpose();
    }
    normals.rowwise().normalize();
    return normals;
}

// The outline measure: outline vertices, those with height < 1e-6, and those whose
// normal is within 5° of horizontal.
struct OutlineStats {
    long vertices = 0, flat = 0, vertical = 0;
};

inline OutlineStats outlineStats(const geometry::Inflation &inflation)
{
    OutlineStats stats;
    const double limit = std::sin(5.0 * M_PI / 180.0);
    for (Eigen::Index i = 0; i < inflation.V.rows(); ++i) {
        if (!inflation.outline(i))
            continue;
        ++stats.vertices;
        stats.flat += inflation.height(i) < 1e-6 ? 1 : 0;
        stats.vertical += std::abs(inflation.normal(i, 2)) <= limit ? 1 : 0;
    }
    return stats;
}

// The shape of a shared/data file: a drawing's strokes (pen width 3, as the mesh bench)
// through objectShape, as the skeleton builder does, or a silhouette's contours repaired.
inline Expected<geometry::Region, geometry::GeometryError> shapeOfFile(const QJsonObject &json)
{
    using namespace geometry;
    if (json.contains(QStringLiteral("strokes"))) {
        std::vector<StrokeInput> strokes;
        for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray())
            strokes.push_back({toMatrix(stroke.toArray()), 3.0});
        return objectShape(strokes);
    }
    const QJsonArray contours = json.value(QStringLiteral("contours")).toArray();
    Polygon polygon;
    for (qsizetype i = 0; i < contours.size(); ++i)
        (i == 0 ? polygon.outer : polygon.holes.emplace_back()) = toMatrix(contours[i].toArray());
    return repairRegion(Region{polygon});
}

} // namespace finbook::test
