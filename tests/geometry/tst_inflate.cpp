// Inflation of an object's shape (inflate/inflation.h): round cross-sections against the
// analytic ones, the outline's zero height and vertical tangent, unit finite normals, clear
// errors for degenerate meshes, every real shape of shared/data.
#include "geometry_test_support.h"
#include "inflate_test_support.h"

#include <finbook/geometry/inflate/inflation.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/object_shape.h>
#include <finbook/geometry/polygon_repair.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

constexpr double kRadius = 100.0;

Inflation inflated(const Region &region, double density = 1.0)
{
    MeshOptions options;
    options.density = density;
    auto result = inflateRegion(region, options);
    if (!result)
        qFatal("inflateRegion failed: %s", result.error().message.c_str());
    return std::move(*result);
}

QString dataDir()
{
    const QByteArray env = qgetenv("FINBOOK_DATA_DIR");
    return env.isEmpty() ? QStringLiteral(FINBOOK_DATA_DIR) : QString::fromLocal8Bit(env);
}

// Angle in degrees between two 3-vectors.
double angleDegrees(const Eigen::RowVector3d &a, const Eigen::RowVector3d &b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
}

// Every value finite, heights ≥ 0 and within the ball, normals unit and facing up.
void checkInflation(const Inflation &inflation)
{
    const Eigen::Index n = inflation.V.rows();
    QCOMPARE(inflation.height.size(), n);
    QCOMPARE(inflation.normal.rows(), n);
    QVERIFY(inflation.height.allFinite() && inflation.normal.allFinite());
    QVERIFY(inflation.depth.allFinite() && inflation.radius.allFinite());
    QVERIFY(inflation.height.minCoeff() >= 0.0);
    QVERIFY((inflation.height - inflation.radius).maxCoeff() <=
            1e-9 * (1.0 + inflation.radius.maxCoeff()));
    QVERIFY((inflation.normal.rowwise().norm().array() - 1.0).abs().maxCoeff() <= 1e-12);
    QVERIFY(inflation.normal.col(2).minCoeff() >= 0.0);
}

} // namespace

class TestInflate : public QObject {
    Q_OBJECT
private slots:
    void discIsHemisphere();
    void discNormalsMatchTheSurface();
    void capsuleCrossSectionIsRound();
    void annulusInflatesToATube();
    void pixelStaircaseInflatesLikeItsLine();
    void outlineIsFlatAndVertical();
    void scalesWithTheDrawing();
    void singleTriangleStaysFinite();
    void lobesTouchingAtAPointStayFinite();
    void degenerateInputGivesErrors();
    void realShapes_data();
    void realShapes();
};

void TestInflate::discIsHemisphere()
{
    const Inflation disc = inflated(Region{Polygon{circle(128, kRadius), {}}});
    QVERIFY(disc.V.rows() > 500);
    double worst = 0.0, sum = 0.0;
    for (Eigen::Index i = 0; i < disc.V.rows(); ++i) {
        const double rho = disc.V.row(i).norm();
        const double expected = std::sqrt(std::max(0.0, kRadius * kRadius - rho * rho));
        worst = std::max(worst, std::abs(disc.height(i) - expected));
        sum += std::abs(disc.height(i) - expected);
    }
    qInfo("disc: %ld vertices, max |h - sqrt(R²-ρ²)| = %.3f%% of R, mean %.4f%%",
          long(disc.V.rows()), 100.0 * worst / kRadius, 100.0 * sum / disc.V.rows() / kRadius);
    QVERIFY(worst <= 0.03 * kRadius);
    QVERIFY(sum / double(disc.V.rows()) <= 0.005 * kRadius);
    QVERIFY(std::abs(disc.height.maxCoeff() - kRadius) <= 0.01 * kRadius);
    // A hemisphere holds 2/3 π R³; the mesh's linear interpolation loses a little at the rim.
    const double hemisphere = 2.0 / 3.0 * M_PI * std::pow(kRadius, 3);
    const double volume = inflatedVolume(disc);
    qInfo("disc volume %.0f, hemisphere %.0f (%.2f%%)", volume, hemisphere,
          100.0 * (volume - hemisphere) / hemisphere);
    QVERIFY(std::abs(volume - hemisphere) <= 0.03 * hemisphere);
}

void TestInflate::discNormalsMatchTheSurface()
{
    const Inflation disc = inflated(Region{Polygon{circle(128, kRadius), {}}});
    // Against the sphere's normal, and against the triangles of the sampled height field away
    // from the rim (where the tangent turns vertical and no linear triangle can follow it).
    const Eigen::MatrixX3d faceNormals = heightFieldNormals(disc);
    Inflation exact = disc;
    for (Eigen::Index i = 0; i < disc.V.rows(); ++i)
        exact.height(i) = std::sqrt(std::max(0.0, kRadius * kRadius - disc.V.row(i).squaredNorm()));
    const Eigen::MatrixX3d exactFaceNormals = heightFieldNormals(exact);
    std::vector<double> toMesh, exactToMesh;
    for (Eigen::Index i = 0; i < disc.V.rows(); ++i) {
        const Eigen::RowVector3d sphere(disc.V(i, 0), disc.V(i, 1), disc.height(i));
        QVERIFY(angleDegrees(disc.normal.row(i), sphere) <= 3.0);
        if (disc.depth(i) > 0.2 * kRadius) {
            toMesh.push_back(angleDegrees(disc.normal.row(i), faceNormals.row(i)));
            exactToMesh.push_back(angleDegrees(sphere, exactFaceNormals.row(i)));
        }
    }
    std::sort(toMesh.begin(), toMesh.end());
    std::sort(exactToMesh.begin(), exactToMesh.end());
    qInfo("exact hemisphere sampled on the same mesh: median %.2f°, max %.2f°",
          exactToMesh[exactToMesh.size() / 2], exactToMesh.back());
    qInfo("normal vs sampled surface: median %.2f°, max %.2f° over %zu vertices",
          toMesh[toMesh.size() / 2], toMesh.back(), toMesh.size());
    QVERIFY(toMesh[toMesh.size() / 2] <= 1.0);
    QVERIFY(toMesh.back() <= 8.0);
}

void TestInflate::capsuleCrossSectionIsRound()
{
    const double halfWidth = 40.0, halfLength = 150.0;
    const Inflation capsule = inflated(Region{Polygon{capsuleRing(halfLength, halfWidth, 32), {}}});
    int checked = 0;
    double worst = 0.0, worstAngle = 0.0;
    for (Eigen::Index i = 0; i < capsule.V.rows(); ++i) {
        const double x = capsule.V(i, 0), y = capsule.V(i, 1);
        if (std::abs(x) > halfLength - halfWidth)
            continue; // near the caps the nearest outline point may lie on an arc
        const double expected = std::sqrt(std::max(0.0, halfWidth * halfWidth - y * y));
        worst = std::max(worst, std::abs(capsule.height(i) - expected));
        const Eigen::RowVector3d tube(0.0, y, capsule.height(i));
        worstAngle = std::max(worstAngle, angleDegrees(capsule.normal.row(i), tube));
        ++checked;
    }
    qInfo("capsule: %d vertices in the middle, max |h - sqrt(w²-y²)| = %.3f%% of w, normals "
          "within %.2f° of the tube's",
          checked, 100.0 * worst / halfWidth, worstAngle);
    QVERIFY(checked > 100);
    QVERIFY(worst <= 0.02 * halfWidth);
    QVERIFY(worstAngle <= 1.0);
    // Round, not pointed: as high as half wide, and the caps are hemispheres of the same size.
    QVERIFY(std::abs(capsule.height.maxCoeff() - halfWidth) <= 0.02 * halfWidth);
}

void TestInflate::annulusInflatesToATube()
{
    const double outer = kRadius, inner = 40.0;
    const Eigen::MatrixX2d hole = circle(64, inner).colwise().reverse();
    const Inflation ring = inflated(Region{Polygon{circle(128, outer), {hole}}});
    const double tube = (outer - inner) / 2.0, centre = (outer + inner) / 2.0;
    double worst = 0.0;
    for (Eigen::Index i = 0; i < ring.V.rows(); ++i) {
        const double off = ring.V.row(i).norm() - centre;
        const double expected = std::sqrt(std::max(0.0, tube * tube - off * off));
        worst = std::max(worst, std::abs(ring.height(i) - expected));
    }
    qInfo("annulus: max |h - tube| = %.3f%% of the tube radius", 100.0 * worst / tube);
    QVERIFY(worst <= 0.05 * tube);
    const OutlineStats stats = outlineStats(ring);
    QVERIFY(stats.vertices >= 128 + 64);
    QCOMPARE(stats.flat, stats.vertices);
    QCOMPARE(stats.vertical, stats.vertices);
}

void TestInflate::pixelStaircaseInflatesLikeItsLine()
{
    // A diagonal band traced in 1 px steps, as a bitmap's contour is: between the staircases
    // along y = x − c and y = x + c. It must inflate like the smooth band (a round tube of
    // half-width c/√2), not ribbed by a medial branch at every step.
    const int steps = 160;
    const double c = 30.0;
    std::vector<std::pair<double, double>> points;
    for (int i = 0; i < steps; ++i) {
        points.emplace_back(i, i - c);
        points.emplace_back(i + 1, i - c);
    }
    for (int i = steps; i > 0; --i) {
        points.emplace_back(i, i + c);
        points.emplace_back(i - 1, i + c);
    }
    Eigen::MatrixX2d ring(Eigen::Index(points.size()), 2);
    for (std::size_t i = 0; i < points.size(); ++i)
        ring.row(Eigen::Index(i)) << points[i].first, points[i].second;
    const Inflation band = inflated(Region{Polygon{ring, {}}});
    // The steps' mean line lies half a step outside each staircase's corners.
    const double halfWidth = (c + 0.5) / std::sqrt(2.0);
    std::vector<double> errors;
    for (Eigen::Index i = 0; i < band.V.rows(); ++i) {
        const double along = (band.V(i, 0) + band.V(i, 1)) / std::sqrt(2.0);
        if (band.outline(i) || std::abs(along - steps / std::sqrt(2.0)) > steps / 4.0)
            continue; // inside (the steps' corners are half a step off the line), off the ends
        const double across = (band.V(i, 1) - band.V(i, 0)) / std::sqrt(2.0);
        const double expected = std::sqrt(std::max(0.0, halfWidth * halfWidth - across * across));
        errors.push_back(std::abs(band.height(i) - expected) / halfWidth);
    }
    std::sort(errors.begin(), errors.end());
    qInfo("staircase band: %zu vertices, |h - tube| median %.2f%%, p90 %.2f%%, max %.2f%% of the "
          "half-width",
          errors.size(), 100.0 * errors[errors.size() / 2], 100.0 * errors[errors.size() * 9 / 10],
          100.0 * errors.back());
    QVERIFY(errors.size() > 100);
    QVERIFY(errors[errors.size() / 2] <= 0.03);
    QVERIFY(errors[errors.size() * 9 / 10] <= 0.08);
}

void TestInflate::outlineIsFlatAndVertical()
{
    const std::vector<Region> shapes{
        Region{Polygon{circle(128, kRadius), {}}},
        Region{Polygon{capsuleRing(150.0, 40.0, 32), {}}},
        Region{Polygon{rows({{0, 0}, {200, 0}, {200, 60}, {60, 60}, {60, 200}, {0, 200}}), {}}},
        Region{Polygon{ellipse(90, 120, 30), {}}, Polygon{circle(40, 20, {300, 0}), {}}},
    };
    for (const Region &shape : shapes) {
        const Inflation inflation = inflated(shape);
        const OutlineStats stats = outlineStats(inflation);
        qInfo("%ld outline vertices: %.1f%% flat (h < 1e-6), %.1f%% within 5° of horizontal",
              long(stats.vertices), 100.0 * stats.flat / stats.vertices,
              100.0 * stats.vertical / stats.vertices);
        QVERIFY(stats.vertices > 0);
        QCOMPARE(stats.flat, stats.vertices);
        QCOMPARE(stats.vertical, stats.vertices);
        checkInflation(inflation);
    }
}

void TestInflate::scalesWithTheDrawing()
{
    // Shape-only: the same drawing at 1/1000 the size inflates to 1/1000 the height.
    const Eigen::MatrixX2d big = ellipse(96, 120, 50);
    const Inflation a = inflated(Region{Polygon{big, {}}});
    auto small = inflateMesh(a.V * 1e-3, a.F);
    QVERIFY(small.hasValue());
    QVERIFY((small->height - a.height * 1e-3).cwiseAbs().maxCoeff() <= 1e-9 * a.height.maxCoeff());
    QVERIFY((small->normal - a.normal).cwiseAbs().maxCoeff() <= 1e-9);
}

void TestInflate::singleTriangleStaysFinite()
{
    Eigen::MatrixX2d V = rows({{0, 0}, {10, 0}, {0, 10}});
    Eigen::MatrixX3i F(1, 3);
    F << 0, 1, 2;
    const auto result = inflateMesh(V, F);
    QVERIFY(result.hasValue());
    checkInflation(*result);
    QCOMPARE(result->height.maxCoeff(), 0.0);
    QCOMPARE(inflatedVolume(*result), 0.0);
}

void TestInflate::lobesTouchingAtAPointStayFinite()
{
    // Two discs meshed apart and joined at one shared vertex (a region "simple up to touching
    // points"): that vertex has four outline edges and no single inward direction.
    const Inflation left = inflated(Region{Polygon{circle(48, 40.0, {-40.0, 0.0}), {}}});
    Eigen::MatrixX2d V(2 * left.V.rows(), 2);
    V.topRows(left.V.rows()) = left.V;
    V.bottomRows(left.V.rows()) = -left.V; // the mirror image touches at the origin
    Eigen::MatrixX3i F(2 * left.F.rows(), 3);
    F.topRows(left.F.rows()) = left.F;
    F.bottomRows(left.F.rows()) = left.F.array() + int(left.V.rows());
    // Weld the mirrored copy of the touching vertex (the one at the origin) to the original.
    Eigen::Index touch = 0;
    left.V.rowwise().squaredNorm().minCoeff(&touch);
    QVERIFY(left.V.row(touch).norm() < 1e-9);
    for (Eigen::Index i = 0; i < F.size(); ++i)
        if (F.data()[i] == int(left.V.rows() + touch))
            F.data()[i] = int(touch);
    V.row(left.V.rows() + touch) << 100.0, 100.0; // now unused, far away
    Eigen::MatrixX3i used = F;
    const auto result = inflateMesh(V, used);
    QVERIFY2(result.hasValue(), result.hasValue() ? "" : result.error().message.c_str());
    checkInflation(*result);
    QCOMPARE(result->height(touch), 0.0);
    QVERIFY(std::abs(result->height.maxCoeff() - 40.0) <= 0.03 * 40.0);
}

void TestInflate::degenerateInputGivesErrors()
{
    auto expectError = [](const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                          GeometryErrorCode code) {
        const auto result = inflateMesh(V, F);
        QVERIFY(!result.hasValue());
        QCOMPARE(int(result.error().code), int(code));
        QVERIFY(!result.error().message.empty());
    };
    Eigen::MatrixX3i one(1, 3);
    one << 0, 1, 2;
    expectError(Eigen::MatrixX2d(0, 2), Eigen::MatrixX3i(0, 3), GeometryErrorCode::EmptyInput);
    expectError(rows({{0, 0}, {1, 0}, {0, 1}}), Eigen::MatrixX3i(0, 3),
                GeometryErrorCode::EmptyInput);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expectError(rows({{0, 0}, {nan, 0}, {0, 1}}), one, GeometryErrorCode::NonFiniteInput);
    const double inf = std::numeric_limits<double>::infinity();
    expectError(rows({{0, 0}, {inf, 0}, {0, 1}}), one, GeometryErrorCode::NonFiniteInput);
    expectError(rows({{0, 0}, {1e9, 0}, {0, 1}}), one, GeometryErrorCode::CoordinateOutOfRange);
    expectError(rows({{0, 0}, {1, 1}, {2, 2}}), one, GeometryErrorCode::DegenerateRegion);
    expectError(rows({{0, 0}, {0, 1}, {1, 0}}), one, GeometryErrorCode::DegenerateRegion);
    expectError(rows({{0, 0}, {1, 0}, {1, 0}}), one, GeometryErrorCode::DegenerateRegion);
    Eigen::MatrixX3i outOfRange(1, 3);
    outOfRange << 0, 1, 3;
    expectError(rows({{0, 0}, {1, 0}, {0, 1}}), outOfRange, GeometryErrorCode::InvalidIndex);
    Eigen::MatrixX3i repeated(1, 3);
    repeated << 0, 1, 1;
    expectError(rows({{0, 0}, {1, 0}, {0, 1}}), repeated, GeometryErrorCode::InvalidIndex);
    const Eigen::MatrixX2d triangle = rows({{0, 0}, {1, 0}, {0, 1}});
    for (const auto &[angle, smoothing] : std::vector<std::pair<double, double>>{
             {0.0, 1.0}, {180.0, 1.0}, {nan, 1.0}, {60.0, -1.0}, {60.0, nan}, {60.0, 1e3}}) {
        InflateOptions options;
        options.contactAngleDegrees = angle;
        options.outlineSmoothing = smoothing;
        const auto result = inflateMesh(triangle, one, options);
        QVERIFY(!result.hasValue());
        QCOMPARE(int(result.error().code), int(GeometryErrorCode::InvalidOptions));
    }
    // Through the region overload: an empty or zero-area region is refused by the mesher.
    QVERIFY(!inflateRegion(Region{}).hasValue());
    QVERIFY(!inflateRegion(Region{Polygon{rows({{0, 0}, {1, 1}, {2, 2}}), {}}}).hasValue());
}

void TestInflate::realShapes_data()
{
    QTest::addColumn<QString>("path");
    const QDir dir(dataDir());
    QStringList files;
    for (const QString &folder : {QStringLiteral("silhouettes"), QStringLiteral("sketches")})
        for (const QString &name :
             QDir(dir.filePath(folder)).entryList({QStringLiteral("*.json")}, QDir::Files))
            files << dir.filePath(folder + QLatin1Char('/') + name);
    if (files.isEmpty())
        QSKIP("shared/data is not available (set FINBOOK_DATA_DIR)");
    for (const QString &path : files)
        QTest::newRow(qPrintable(QFileInfo(path).baseName())) << path;
}

void TestInflate::realShapes()
{
    QFETCH(QString, path);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const auto region = shapeOfFile(QJsonDocument::fromJson(file.readAll()).object());
    QVERIFY2(region.hasValue(), region.hasValue() ? "" : region.error().message.c_str());
    const auto result = inflateRegion(*region);
    QVERIFY2(result.hasValue(), result.hasValue() ? "" : result.error().message.c_str());
    checkInflation(*result);
    const OutlineStats stats = outlineStats(*result);
    QCOMPARE(stats.flat, stats.vertices);
    QCOMPARE(stats.vertical, stats.vertices);
    QVERIFY(inflatedVolume(*result) > 0.0);
}

QTEST_APPLESS_MAIN(TestInflate)
#include "tst_inflate.moc"
