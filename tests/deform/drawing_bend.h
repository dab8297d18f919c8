// A drawing of ../shared/data meshed as the app meshes it, and the bend that
// `finbook-bench arap --quality` measures ARAP on: shared by that bench and the ARAP tests
// that check a figure of it.
#pragma once

#include "../geometry/geometry_test_support.h"

#include <finbook/geometry/object_mesh.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace finbook::test {

constexpr double kBendPinFraction = 0.06;
constexpr double kDrawingPenWidth = 3.0; // Quick, Draw! strokes carry no width

// Pins every vertex of V with x within 6 % of (high − low) above `low` held where it is, and
// every vertex within 6 % below `high` turned by `degrees` about `centre`.
struct BendPins {
    Eigen::VectorXi b;
    Eigen::MatrixX2d bc;
};

inline BendPins bendBands(const Eigen::MatrixX2d &V, double low, double high,
                          const Eigen::RowVector2d &centre, double degrees)
{
    const double width = high - low;
    std::vector<int> left, right;
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
        if (V(v, 0) <= low + kBendPinFraction * width)
            left.push_back(int(v));
        else if (V(v, 0) >= high - kBendPinFraction * width)
            right.push_back(int(v));
    }
    const double angle = degrees * M_PI / 180.0;
    Eigen::Matrix2d R;
    R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    BendPins bend;
    bend.b.resize(Eigen::Index(left.size() + right.size()));
    bend.bc.resize(bend.b.size(), 2);
    Eigen::Index row = 0;
    for (const int v : left) {
        bend.b(row) = v;
        bend.bc.row(row++) = V.row(v);
    }
    for (const int v : right) {
        bend.b(row) = v;
        bend.bc.row(row++) = centre + (V.row(v) - centre) * R.transpose();
    }
    return bend;
}

// The bench's bend: the right band swings round the centroid of the held left one.
inline BendPins bendPins(const Eigen::MatrixX2d &V, double degrees)
{
    const double low = V.col(0).minCoeff(), high = V.col(0).maxCoeff();
    Eigen::RowVector2d centre = Eigen::RowVector2d::Zero();
    int left = 0;
    for (Eigen::Index v = 0; v < V.rows(); ++v)
        if (V(v, 0) <= low + kBendPinFraction * (high - low)) {
            centre += V.row(v);
            ++left;
        }
    return bendBands(V, low, high, centre / double(std::max(1, left)), degrees);
}

// Meshes a file of ../shared/data (Quick, Draw! "strokes" or shape "contours") with the
// geometry layer's defaults, as the app would; nullopt with `error` set when it cannot.
// `density` is MeshOptions::density: 3.65 gives about 13× the vertices (about 20k).
inline std::optional<std::pair<Eigen::MatrixX2d, Eigen::MatrixX3i>>
meshDrawing(const QString &path, QString &error, double density = 1.0)
{
    geometry::MeshOptions options;
    options.density = density;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        error = QStringLiteral("unreadable");
        return std::nullopt;
    }
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    finbook::Expected<geometry::ObjectMesh, geometry::GeometryError> mesh =
        unexpected(geometry::GeometryError{});
    if (json.contains(QStringLiteral("strokes"))) {
        std::vector<geometry::StrokeInput> strokes;
        for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray())
            strokes.push_back({toMatrix(stroke.toArray()), kDrawingPenWidth});
        mesh = geometry::buildObjectMesh(strokes, options);
    } else if (json.contains(QStringLiteral("contours"))) {
        geometry::Polygon polygon;
        const QJsonArray contours = json.value(QStringLiteral("contours")).toArray();
        for (qsizetype i = 0; i < contours.size(); ++i)
            (i == 0 ? polygon.outer : polygon.holes.emplace_back()) =
                toMatrix(contours[i].toArray());
        mesh = geometry::buildObjectMesh(geometry::Region{polygon}, options);
    } else {
        error = QStringLiteral("neither strokes nor contours");
        return std::nullopt;
    }
    if (!mesh) {
        error = QString::fromStdString(mesh.error().message);
        return std::nullopt;
    }
    return std::make_pair(mesh->V, mesh->F);
}

} // namespace finbook::test
