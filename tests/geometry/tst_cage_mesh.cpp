// Cages in the geometry layer: validation, the interior mesh harmonic coordinates are solved on,
// and Fit Cage (also on every real drawing and shape in shared/data).
#include "cage_test_shapes.h"
#include "geometry_test_support.h"

#include <finbook/geometry/cage/cage_mesh.h>
#include <finbook/geometry/cage/cage_polygon.h>
#include <finbook/geometry/cage/fit_cage.h>
#include <finbook/geometry/mesh_quality.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/simplicity.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <limits>
#include <map>

Q_DECLARE_METATYPE(Eigen::MatrixX2d)

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

QString dataDir()
{
    const QByteArray env = qgetenv("FINBOOK_DATA_DIR");
    return env.isEmpty() ? QStringLiteral(FINBOOK_DATA_DIR) : QString::fromLocal8Bit(env);
}

QStringList dataFiles(const QString &folder)
{
    const QDir dir(dataDir() + QLatin1Char('/') + folder);
    QStringList files;
    for (const QString &name : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        files << dir.filePath(name);
    return files;
}

QJsonObject readJson(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(file.readAll()).object()
                                          : QJsonObject();
}

// The smallest interior angle at a convex corner of the cage, degrees.
double sharpestCorner(const Eigen::MatrixX2d &corners)
{
    const Eigen::Index c = corners.rows();
    const double orientation = signedArea(corners) > 0.0 ? 1.0 : -1.0;
    double sharpest = 180.0;
    for (Eigen::Index i = 0; i < c; ++i) {
        const Eigen::Vector2d u = corners.row((i + c - 1) % c) - corners.row(i);
        const Eigen::Vector2d w = corners.row((i + 1) % c) - corners.row(i);
        if (orientation * (w.x() * u.y() - w.y() * u.x()) > 0.0) // convex
            sharpest =
                std::min(sharpest, std::acos(u.normalized().dot(w.normalized())) * 180 / M_PI);
    }
    return sharpest;
}

double extentOf(const Eigen::MatrixX2d &points)
{
    return (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
}

// Every promise of CageMesh on one cage.
void checkCageMesh(const Eigen::MatrixX2d &corners, const CageMesh &m, double maxEdge)
{
    const Eigen::Index c = corners.rows(), n = m.V.rows();
    const double tolerance = 1e-9 * extentOf(corners);
    QCOMPARE(m.cornerCount, c);
    QVERIFY(m.boundaryCount >= c && m.boundaryCount <= n);
    QVERIFY(m.V.topRows(c) == corners); // exactly, not just close
    QVERIFY(m.F.minCoeff() >= 0 && m.F.maxCoeff() < n);
    QVERIFY(triangleSignedAreas(m.V, m.F).minCoeff() > 0.0);
    // The mesh covers the cage, concave notches excluded: areas agree.
    const double area = std::abs(signedArea(corners));
    QVERIFY2(std::abs(triangleSignedAreas(m.V, m.F).sum() - area) <= 1e-9 * area,
             qPrintable(QString::number(triangleSignedAreas(m.V, m.F).sum() - area)));
    std::vector<int> uses(std::size_t(n), 0);
    for (Eigen::Index i = 0; i < m.F.size(); ++i)
        ++uses[std::size_t(m.F.data()[i])];
    QVERIFY(std::all_of(uses.begin(), uses.end(), [](int u) { return u > 0; }));
    // Boundary vertices lie on their edge at their parameter, sorted along each edge.
    for (Eigen::Index v = 0; v < m.boundaryCount; ++v) {
        const int e = m.boundaryEdge(v);
        const double t = m.boundaryParameter(v);
        QVERIFY(e >= 0 && e < c && t >= 0.0 && t < 1.0);
        const Eigen::Vector2d a = corners.row(e), b = corners.row((e + 1) % c);
        QVERIFY((m.V.row(v).transpose() - ((1 - t) * a + t * b)).norm() <= tolerance);
        if (v >= c && v > c && m.boundaryEdge(v - 1) == e)
            QVERIFY(m.boundaryParameter(v - 1) < t);
    }
    for (Eigen::Index v = 0; v < c; ++v)
        QVERIFY(m.boundaryEdge(v) == v && m.boundaryParameter(v) == 0.0);
    // Interior vertices are strictly inside; the mesh's boundary edges join consecutive
    // boundary vertices of one cage edge (nothing outside the cage, nothing missing).
    for (Eigen::Index v = m.boundaryCount; v < n; ++v)
        QVERIFY(distanceToCage(corners, m.V.row(v).transpose()) > tolerance);
    std::map<std::pair<int, int>, int> edges;
    double longest = 0.0;
    for (Eigen::Index t = 0; t < m.F.rows(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = m.F(t, k), b = m.F(t, (k + 1) % 3);
            ++edges[{std::min(a, b), std::max(a, b)}];
            longest = std::max(longest, (m.V.row(a) - m.V.row(b)).norm());
        }
    int boundaryEdges = 0;
    for (const auto &[edge, count] : edges) {
        QVERIFY(count == 1 || count == 2);
        if (count == 1) {
            ++boundaryEdges;
            QVERIFY(edge.first < m.boundaryCount && edge.second < m.boundaryCount);
        }
    }
    QCOMPARE(Eigen::Index(boundaryEdges), m.boundaryCount);
    QVERIFY2(longest <= maxEdge * (1.0 + 1e-9), qPrintable(QString::number(longest / maxEdge)));
    // 20° (CGAL's bound, 20.7°) wherever the cage allows it; sharper cage corners keep their angle.
    const double bound = std::min(20.0, sharpestCorner(corners) - 1e-6);
    QVERIFY2(minAngleDegrees(m.V, m.F) >= bound,
             qPrintable(QString::number(minAngleDegrees(m.V, m.F))));
    QCOMPARE(connectedComponents(m.F, n), 1);
}

} // namespace

class TestCageMesh : public QObject {
    Q_OBJECT
private slots:
    void refusesBadCages_data();
    void refusesBadCages();
    void normalizesOrientation();
    void meshesConcaveCages_data();
    void meshesConcaveCages();
    void hitsTheVertexTarget();
    void meshRefusesBadOptions();
    void reportsPointsOutside();
    void fitsSyntheticDrawings();
    void fitHandlesDegenerateInput();
    void fitCornerCountIsAdjustable();
    void fitsRealSketches_data();
    void fitsRealSketches();
    void fitsRealSilhouettes_data();
    void fitsRealSilhouettes();
};

void TestCageMesh::refusesBadCages_data()
{
    QTest::addColumn<Eigen::MatrixX2d>("corners");
    QTest::addColumn<int>("code");
    const auto code = [](GeometryErrorCode c) { return int(c); };
    QTest::newRow("none") << Eigen::MatrixX2d(0, 2) << code(GeometryErrorCode::TooFewCorners);
    QTest::newRow("one") << rows({{1, 1}}) << code(GeometryErrorCode::TooFewCorners);
    QTest::newRow("two") << rows({{0, 0}, {5, 5}}) << code(GeometryErrorCode::TooFewCorners);
    QTest::newRow("nan") << rows({{0, 0}, {kNaN, 0}, {0, 5}})
                         << code(GeometryErrorCode::NonFiniteInput);
    QTest::newRow("huge") << rows({{0, 0}, {2e6, 0}, {0, 5}})
                          << code(GeometryErrorCode::CoordinateOutOfRange);
    QTest::newRow("collinear") << rows({{0, 0}, {1, 1}, {2, 2}, {3, 3}})
                               << code(GeometryErrorCode::DegenerateRegion);
    QTest::newRow("all on one spot")
        << rows({{4, 4}, {4, 4}, {4, 4}}) << code(GeometryErrorCode::DegenerateRegion);
    QTest::newRow("bow tie") << rows({{0, 0}, {10, 10}, {10, 0}, {0, 5}})
                             << code(GeometryErrorCode::NotSimple);
    QTest::newRow("repeated corner")
        << rows({{0, 0}, {10, 0}, {10, 0}, {10, 10}}) << code(GeometryErrorCode::NotSimple);
    QTest::newRow("corner on an edge")
        << rows({{0, 0}, {10, 0}, {10, 10}, {5, 0}, {0, 10}}) << code(GeometryErrorCode::NotSimple);
}

void TestCageMesh::refusesBadCages()
{
    QFETCH(Eigen::MatrixX2d, corners);
    QFETCH(int, code);
    const auto error = checkCage(corners);
    QVERIFY(error.has_value());
    QCOMPARE(int(error->code), code);
    QVERIFY(!error->message.empty());
    const auto mesh = meshCage(corners, 1.0);
    QVERIFY(!mesh);
    QCOMPARE(int(mesh.error().code), code);
    QVERIFY(!normalizedCage(corners));
}

void TestCageMesh::normalizesOrientation()
{
    for (const NamedCage &cage : allCages()) {
        QVERIFY2(!checkCage(cage.corners), cage.name.c_str());
        const auto normal = normalizedCage(cage.corners);
        QVERIFY(normal);
        QVERIFY(signedArea(*normal) > 0.0);
        QVERIFY(normal->row(0) == cage.corners.row(0));
        QCOMPARE(std::abs(signedArea(*normal)), std::abs(signedArea(cage.corners)));
        if (signedArea(cage.corners) > 0.0)
            QVERIFY(*normal == cage.corners);
        else
            QVERIFY(normal->row(1) == cage.corners.row(cage.corners.rows() - 1));
    }
}

void TestCageMesh::meshesConcaveCages_data()
{
    QTest::addColumn<Eigen::MatrixX2d>("corners");
    QTest::addColumn<long>("target");
    for (const NamedCage &cage : allCages())
        for (long target : {300L, 3000L})
            QTest::newRow((cage.name + " " + std::to_string(target)).c_str())
                << cage.corners << target;
}

void TestCageMesh::meshesConcaveCages()
{
    QFETCH(Eigen::MatrixX2d, corners);
    QFETCH(long, target);
    const double maxEdge = cageEdgeLength(corners, target);
    QVERIFY(maxEdge > 0.0);
    const auto mesh = meshCage(corners, maxEdge);
    QVERIFY2(mesh, mesh ? "" : mesh.error().message.c_str());
    checkCageMesh(corners, *mesh, maxEdge);
}

void TestCageMesh::hitsTheVertexTarget()
{
    for (const NamedCage &cage : allCages()) {
        for (long target : {1400L, 5400L}) {
            const auto mesh = meshCage(cage.corners, cageEdgeLength(cage.corners, target));
            QVERIFY(mesh);
            const double ratio = double(mesh->V.rows()) / double(target);
            QVERIFY2(ratio > 0.75 && ratio < 1.3,
                     qPrintable(QString::fromStdString(cage.name) + QStringLiteral(" ") +
                                QString::number(mesh->V.rows())));
            // Most of the interior comes from the lattice, not from CGAL's refinement.
            if (target >= 5400 && cage.name != "spiral" && cage.name != "sharp star")
                QVERIFY(mesh->latticeVertices > mesh->V.rows() / 2);
        }
    }
}

void TestCageMesh::meshRefusesBadOptions()
{
    const Eigen::MatrixX2d cage = squareCage();
    for (const double maxEdge : {0.0, -1.0, kNaN, std::numeric_limits<double>::infinity(), 1e-6}) {
        const auto mesh = meshCage(cage, maxEdge);
        QVERIFY(!mesh);
        QCOMPARE(mesh.error().code, GeometryErrorCode::InvalidOptions);
    }
    QCOMPARE(cageEdgeLength(rows({{0, 0}, {1, 1}}), 100), 0.0);
    // An edge longer than the cage still gives a valid (coarse) mesh.
    const auto coarse = meshCage(cage, 1e4);
    QVERIFY(coarse);
    checkCageMesh(cage, *coarse, 1e4);
}

void TestCageMesh::reportsPointsOutside()
{
    const Eigen::MatrixX2d cage = horseshoeCage();
    const double chord = cage(24, 0);                 // the inner arc's vertical chord across y = 0
    const Eigen::MatrixX2d points = rows({{150, 0},   // in the band
                                          {0, 0},     // in the notch the convex hull would fill
                                          {0, 150},   // in the band, on the other side
                                          {chord, 0}, // on an edge: contained
                                          {300, 300}, // far outside
                                          {kNaN, 1},  // not a point
                                          {-150, 0}}); // in the gap between the band's ends
    const Eigen::VectorXi outside = cageOutsidePoints(cage, points);
    QCOMPARE(outside, (Eigen::VectorXi(4) << 1, 4, 5, 6).finished());
    QCOMPARE(cageOutsidePoints(cage, points.topRows(1), 40.0).size(), Eigen::Index(0));
    QCOMPARE(cageOutsidePoints(cage, points.topRows(1), 60.0).size(), Eigen::Index(1));
    const auto error = checkCageContains(cage, points);
    QVERIFY(error);
    QCOMPARE(error->code, GeometryErrorCode::PointsOutsideCage);
    QVERIFY(error->message.find("4 points") != std::string::npos);
    QVERIFY(!checkCageContains(cage, points.topRows(1)));
}

namespace {

// The Fit Cage promises for one input.
void checkFit(const Eigen::MatrixX2d &cage, const Eigen::MatrixX2d &points,
              const FitCageOptions &options)
{
    QVERIFY(!checkCage(cage));
    QVERIFY(signedArea(cage) > 0.0);
    QVERIFY2(cage.rows() <= options.corners + 2, qPrintable(QString::number(cage.rows())));
    const Eigen::VectorXi outside = cageOutsidePoints(cage, points, 0.5 * options.margin);
    Eigen::Index finiteOutside = 0;
    for (const int k : outside)
        finiteOutside += points.row(k).allFinite() ? 1 : 0;
    QCOMPARE(finiteOutside, Eigen::Index(0));
}

Eigen::MatrixX2d allPoints(const std::vector<StrokeInput> &strokes)
{
    Eigen::Index total = 0;
    for (const StrokeInput &s : strokes)
        total += s.points.rows();
    Eigen::MatrixX2d points(total, 2);
    total = 0;
    for (const StrokeInput &s : strokes) {
        points.middleRows(total, s.points.rows()) = s.points;
        total += s.points.rows();
    }
    return points;
}

} // namespace

void TestCageMesh::fitsSyntheticDrawings()
{
    // A horseshoe drawn as one stroke, two blobs far apart, a spiral stroke.
    std::vector<std::vector<StrokeInput>> drawings;
    Eigen::MatrixX2d arc(60, 2);
    for (int i = 0; i < 60; ++i)
        arc.row(i) << 300 + 150 * std::cos(-2.3 + 4.6 * i / 59),
            300 + 150 * std::sin(-2.3 + 4.6 * i / 59);
    drawings.push_back({{arc, 4.0}});
    drawings.push_back({{circle(20, 30, {100, 100}), 3.0}, {circle(20, 30, {600, 400}), 3.0}});
    Eigen::MatrixX2d spiral(200, 2);
    for (int i = 0; i < 200; ++i) {
        const double t = 3.0 * 2 * M_PI * i / 199;
        spiral.row(i) << 400 + (20 + 15 * t) * std::cos(t), 400 + (20 + 15 * t) * std::sin(t);
    }
    drawings.push_back({{spiral, 2.0}});
    for (const auto &strokes : drawings) {
        FitCageOptions options;
        const auto cage = fitCage(strokes, options);
        QVERIFY2(cage, cage ? "" : cage.error().message.c_str());
        checkFit(*cage, allPoints(strokes), options);
        QVERIFY(cage->rows() >= 6); // coarse, but not a triangle
    }
}

void TestCageMesh::fitHandlesDegenerateInput()
{
    FitCageOptions options;
    // One point: a small cage around it.
    const auto dot = fitCage({{rows({{10, 20}}), 3.0}}, options);
    QVERIFY(dot);
    checkFit(*dot, rows({{10, 20}}), options);
    // Collinear points: a thin cage around the segment.
    const auto line = fitCage({{rows({{0, 0}, {50, 50}, {100, 100}}), 0.0}}, options);
    QVERIFY(line);
    checkFit(*line, rows({{0, 0}, {50, 50}, {100, 100}}), options);
    // Points alone (no shape), NaN rows skipped.
    const Eigen::MatrixX2d loose = rows({{0, 0}, {kNaN, 3}, {400, 10}, {200, 300}});
    const auto cage = fitCage(Region{}, loose, options);
    QVERIFY(cage);
    checkFit(*cage, loose, options);
    // Nothing finite, bad options: errors, not crashes.
    const auto none = fitCage(Region{}, rows({{kNaN, kNaN}}), options);
    QVERIFY(!none);
    QCOMPARE(none.error().code, GeometryErrorCode::EmptyInput);
    QCOMPARE(fitCage({{rows({{kNaN, 1}}), 3.0}}, options).error().code,
             GeometryErrorCode::EmptyInput);
    QVERIFY(!fitCage(std::vector<StrokeInput>{}, options));
    for (const auto &[corners, margin] :
         std::vector<std::pair<int, double>>{{2, 8.0}, {5000, 8.0}, {16, -1.0}, {16, kNaN}}) {
        FitCageOptions bad;
        bad.corners = corners;
        bad.margin = margin;
        const auto refused = fitCage(Region{}, rows({{0, 0}}), bad);
        QVERIFY(!refused);
        QCOMPARE(refused.error().code, GeometryErrorCode::InvalidOptions);
    }
    QCOMPARE(fitCage(Region{}, rows({{3e6, 0}}), options).error().code,
             GeometryErrorCode::CoordinateOutOfRange);
}

void TestCageMesh::fitCornerCountIsAdjustable()
{
    Eigen::MatrixX2d arc(80, 2);
    for (int i = 0; i < 80; ++i)
        arc.row(i) << 150 * std::cos(-2.5 + 5.0 * i / 79), 150 * std::sin(-2.5 + 5.0 * i / 79);
    const std::vector<StrokeInput> strokes{{arc, 4.0}};
    Eigen::Index previous = 0;
    for (const int corners : {8, 12, 16, 24}) {
        FitCageOptions options;
        options.corners = corners;
        const auto cage = fitCage(strokes, options);
        QVERIFY(cage);
        checkFit(*cage, arc, options);
        QVERIFY(cage->rows() >= previous); // more corners allowed → never fewer used
        previous = cage->rows();
    }
    QVERIFY(previous >= 14);
}

void TestCageMesh::fitsRealSketches_data()
{
    QTest::addColumn<QString>("path");
    const QStringList files = dataFiles(QStringLiteral("sketches"));
    if (files.isEmpty())
        QSKIP("no real data (set FINBOOK_DATA_DIR to ../shared/data)");
    for (const QString &path : files)
        QTest::newRow(qPrintable(QFileInfo(path).baseName())) << path;
}

void TestCageMesh::fitsRealSketches()
{
    QFETCH(QString, path);
    std::vector<StrokeInput> strokes;
    for (const QJsonValue &stroke : readJson(path).value(QStringLiteral("strokes")).toArray())
        strokes.push_back({toMatrix(stroke.toArray()), 3.0});
    for (const int corners : {8, 16, 24}) {
        FitCageOptions options;
        options.corners = corners;
        const auto cage = fitCage(strokes, options);
        QVERIFY2(cage, cage ? "" : cage.error().message.c_str());
        checkFit(*cage, allPoints(strokes), options);
        if (corners == 16) {
            const auto mesh = meshCage(*cage, cageEdgeLength(*cage, 1500));
            QVERIFY2(mesh, mesh ? "" : mesh.error().message.c_str());
            checkCageMesh(*cage, *mesh, cageEdgeLength(*cage, 1500));
            QVERIFY(mesh->latticeVertices > 0); // the fast path, not the all-CGAL fallback
        }
    }
}

void TestCageMesh::fitsRealSilhouettes_data()
{
    QTest::addColumn<QString>("path");
    const QStringList files = dataFiles(QStringLiteral("silhouettes"));
    if (files.isEmpty())
        QSKIP("no real data (set FINBOOK_DATA_DIR to ../shared/data)");
    for (const QString &path : files)
        QTest::newRow(qPrintable(QFileInfo(path).baseName())) << path;
}

void TestCageMesh::fitsRealSilhouettes()
{
    QFETCH(QString, path);
    const QJsonArray contours = readJson(path).value(QStringLiteral("contours")).toArray();
    QVERIFY(!contours.isEmpty());
    Polygon polygon;
    std::vector<Eigen::MatrixX2d> rings;
    for (qsizetype i = 0; i < contours.size(); ++i) {
        rings.push_back(toMatrix(contours[i].toArray()));
        (i == 0 ? polygon.outer : polygon.holes.emplace_back()) = rings.back();
    }
    Eigen::Index total = 0;
    for (const auto &ring : rings)
        total += ring.rows();
    Eigen::MatrixX2d points(total, 2);
    total = 0;
    for (const auto &ring : rings) {
        points.middleRows(total, ring.rows()) = ring;
        total += ring.rows();
    }
    FitCageOptions options;
    const auto cage = fitCage(Region{polygon}, points, options);
    QVERIFY2(cage, cage ? "" : cage.error().message.c_str());
    checkFit(*cage, points, options);
    const auto mesh = meshCage(*cage, cageEdgeLength(*cage, 1500));
    QVERIFY2(mesh, mesh ? "" : mesh.error().message.c_str());
    checkCageMesh(*cage, *mesh, cageEdgeLength(*cage, 1500));
    QVERIFY(mesh->latticeVertices > 0);
}

QTEST_APPLESS_MAIN(TestCageMesh)
#include "tst_cage_mesh.moc"
