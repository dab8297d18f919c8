// Harmonic cage coordinates: the properties Joshi et al. promise, checked on convex, concave
// and strongly concave cages and on every real drawing and shape in shared/data; mean value
// coordinates on the same cages show that the non-negativity check can fail.
#include "../geometry/cage_test_shapes.h"
#include "../geometry/geometry_test_support.h"

#include <finbook/deform/cage/harmonic_cage.h>
#include <finbook/geometry/cage/cage_polygon.h>
#include <finbook/geometry/cage/fit_cage.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <limits>
#include <random>

using namespace finbook;
using namespace finbook::deform;
using namespace finbook::test;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kTolerance = 1e-9;

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

std::shared_ptr<const CagePrecompute> precompute(const Eigen::MatrixX2d &corners,
                                                 long target = 3000)
{
    CageOptions options;
    options.targetVertices = target;
    auto result = cagePrecompute(corners, options);
    if (!result)
        qWarning("%s", result.error().message.c_str());
    return result ? *result : nullptr;
}

// Points spread over the cage: the centroids of its mesh triangles (all strictly inside).
Eigen::MatrixX2d insidePoints(const CagePrecompute &d)
{
    Eigen::MatrixX2d points(d.mesh.F.rows(), 2);
    for (Eigen::Index t = 0; t < d.mesh.F.rows(); ++t)
        points.row(t) = (d.mesh.V.row(d.mesh.F(t, 0)) + d.mesh.V.row(d.mesh.F(t, 1)) +
                         d.mesh.V.row(d.mesh.F(t, 2))) /
                        3.0;
    return points;
}

// The smallest weight over all rows: what the non-negativity property is about.
double minimumWeight(const Eigen::MatrixXd &weights)
{
    return weights.size() > 0 ? weights.minCoeff() : 0.0;
}

// Mean value coordinates (Floater 2003; Hormann & Floater 2006 for arbitrary polygons) of a
// point strictly inside the cage: w_i = (tan(α_{i−1}/2) + tan(α_i/2)) / r_i, normalised.
Eigen::RowVectorXd meanValueCoordinates(const Eigen::MatrixX2d &cage, const Eigen::Vector2d &x)
{
    const Eigen::Index c = cage.rows();
    Eigen::VectorXd r(c), tanHalf(c);
    for (Eigen::Index i = 0; i < c; ++i)
        r(i) = (cage.row(i).transpose() - x).norm();
    for (Eigen::Index i = 0; i < c; ++i) {
        const Eigen::Vector2d s0 = cage.row(i).transpose() - x;
        const Eigen::Vector2d s1 = cage.row((i + 1) % c).transpose() - x;
        const double area = s0.x() * s1.y() - s0.y() * s1.x(); // 2 × signed area
        tanHalf(i) = (r(i) * r((i + 1) % c) - s0.dot(s1)) / area;
    }
    Eigen::RowVectorXd w(c);
    for (Eigen::Index i = 0; i < c; ++i)
        w(i) = (tanHalf((i + c - 1) % c) + tanHalf(i)) / r(i);
    return w / w.sum();
}

Eigen::MatrixX2d rotated(const Eigen::MatrixX2d &points, double angle, Eigen::RowVector2d shift)
{
    Eigen::Matrix2d R;
    R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    return (points * R.transpose()).rowwise() + shift;
}

// All the properties on one cage and one set of points inside it.
void checkProperties(const Eigen::MatrixX2d &corners, const CagePrecompute &d,
                     const Eigen::MatrixX2d &points)
{
    const double scale = std::max(1.0, d.extent);
    QVERIFY(d.W.allFinite());
    QCOMPARE(d.negativeEdgeWeights, 0);
    // Partition of unity and linear reproduction at every mesh vertex.
    QVERIFY((d.W.rowwise().sum().array() - 1.0).abs().maxCoeff() <= kTolerance);
    QVERIFY((d.W * corners - d.mesh.V).cwiseAbs().maxCoeff() <= kTolerance * scale);
    QVERIFY2(d.minCoordinate >= -kTolerance, qPrintable(QString::number(d.minCoordinate)));
    // Interpolation on the cage: boundary rows are the hat values of their edge.
    const Eigen::Index c = corners.rows();
    for (Eigen::Index v = 0; v < d.mesh.boundaryCount; ++v) {
        Eigen::RowVectorXd hat = Eigen::RowVectorXd::Zero(c);
        hat(d.mesh.boundaryEdge(v)) += 1.0 - d.mesh.boundaryParameter(v);
        hat((d.mesh.boundaryEdge(v) + 1) % c) += d.mesh.boundaryParameter(v);
        QVERIFY((d.W.row(v) - hat).cwiseAbs().maxCoeff() <= kTolerance);
    }
    // Bound points: the same properties per point, and the identity pose changes nothing.
    const auto binding = cageBind(d, points);
    QVERIFY2(binding, binding ? "" : binding.error().message.c_str());
    QVERIFY((binding->weights.rowwise().sum().array() - 1.0).abs().maxCoeff() <= kTolerance);
    QVERIFY2(minimumWeight(binding->weights) >= -kTolerance,
             qPrintable(QString::number(minimumWeight(binding->weights))));
    Eigen::MatrixX2d out;
    QVERIFY(!cageDeform(*binding, corners, out));
    QVERIFY2((out - points).cwiseAbs().maxCoeff() <= kTolerance * scale,
             qPrintable(QString::number((out - points).cwiseAbs().maxCoeff())));
    // A rigid motion of the cage moves the points rigidly (linear reproduction).
    QVERIFY(!cageDeform(*binding, rotated(corners, 0.7, {30, -12}), out));
    QVERIFY((out - rotated(points, 0.7, {30, -12})).cwiseAbs().maxCoeff() <= kTolerance * scale);
    const auto posedMesh = cageDeformMesh(d, rotated(corners, 0.7, {30, -12}));
    QVERIFY(posedMesh);
    QVERIFY((*posedMesh - rotated(d.mesh.V, 0.7, {30, -12})).cwiseAbs().maxCoeff() <=
            kTolerance * scale);
}

} // namespace

class TestHarmonicCage : public QObject {
    Q_OBJECT
private slots:
    void propertiesHold_data();
    void propertiesHold();
    void interpolatesOnTheCage();
    void meanValueCoordinatesGoNegative();
    void dragIsLinearInEachCorner();
    void bindsManyPointsOnTwoThreads();
    void selfCrossingPoseStillDeforms();
    void refusesBadCages();
    void reportsPointsOutside();
    void refusesBadPoses();
    void cancels();
    void realSketches_data();
    void realSketches();
    void realSilhouettes_data();
    void realSilhouettes();
};

void TestHarmonicCage::propertiesHold_data()
{
    QTest::addColumn<int>("cage");
    QTest::addColumn<int>("target");
    const std::vector<NamedCage> cages = allCages();
    // 8000 vertices: the factorization and the solve split over two threads.
    for (std::size_t k = 0; k < cages.size(); ++k)
        for (const int target : {200, 3000, 8000})
            QTest::newRow((cages[k].name + " " + std::to_string(target)).c_str())
                << int(k) << target;
}

void TestHarmonicCage::propertiesHold()
{
    QFETCH(int, cage);
    QFETCH(int, target);
    const Eigen::MatrixX2d corners = allCages()[std::size_t(cage)].corners;
    const auto d = precompute(corners, target);
    QVERIFY(d);
    QVERIFY(d->restCorners == corners);
    QCOMPARE(d->W.rows(), d->mesh.V.rows());
    QCOMPARE(d->W.cols(), corners.rows());
    QVERIFY(d->relativeResidual <= 1e-12);
    checkProperties(corners, *d, insidePoints(*d));
}

void TestHarmonicCage::interpolatesOnTheCage()
{
    const Eigen::MatrixX2d corners = horseshoeCage();
    const auto d = precompute(corners);
    QVERIFY(d);
    // Points on every edge (and the corners themselves) get the hat values of their edge, and
    // follow the posed edge linearly.
    const Eigen::Index c = corners.rows();
    Eigen::MatrixX2d points(4 * c, 2), expected(4 * c, 2);
    Eigen::MatrixX2d posed = corners;
    std::mt19937 random(3);
    std::normal_distribution<double> jitter(0.0, 15.0);
    for (Eigen::Index i = 0; i < c; ++i)
        posed.row(i) += Eigen::RowVector2d(jitter(random), jitter(random));
    std::vector<Eigen::RowVectorXd> hats;
    for (Eigen::Index e = 0; e < c; ++e) {
        for (int k = 0; k < 4; ++k) {
            const double t = k / 4.0 + 0.05 * (k > 0);
            const Eigen::Index row = 4 * e + k;
            points.row(row) = (1 - t) * corners.row(e) + t * corners.row((e + 1) % c);
            expected.row(row) = (1 - t) * posed.row(e) + t * posed.row((e + 1) % c);
            Eigen::RowVectorXd hat = Eigen::RowVectorXd::Zero(c);
            hat(e) += 1 - t;
            hat((e + 1) % c) += t;
            hats.push_back(hat);
        }
    }
    const auto binding = cageBind(*d, points);
    QVERIFY2(binding, binding ? "" : binding.error().message.c_str());
    for (Eigen::Index row = 0; row < points.rows(); ++row)
        QVERIFY((binding->weights.row(row) - hats[std::size_t(row)]).cwiseAbs().maxCoeff() <=
                kTolerance);
    Eigen::MatrixX2d out;
    QVERIFY(!cageDeform(*binding, posed, out));
    QVERIFY((out - expected).cwiseAbs().maxCoeff() <= kTolerance * d->extent);
}

void TestHarmonicCage::meanValueCoordinatesGoNegative()
{
    for (const NamedCage &cage : concaveCages()) {
        const auto d = precompute(cage.corners);
        QVERIFY(d);
        const Eigen::MatrixX2d points = insidePoints(*d);
        Eigen::MatrixXd mvc(points.rows(), cage.corners.rows());
        for (Eigen::Index k = 0; k < points.rows(); ++k)
            mvc.row(k) = meanValueCoordinates(cage.corners, points.row(k).transpose());
        // They are genuine generalized barycentric coordinates ...
        QVERIFY((mvc.rowwise().sum().array() - 1.0).abs().maxCoeff() <= kTolerance);
        QVERIFY((mvc * cage.corners - points).cwiseAbs().maxCoeff() <= kTolerance * d->extent);
        // ... that the non-negativity check rejects, while harmonic coordinates pass it.
        qInfo("%s: min mean value coordinate %.4f, min harmonic coordinate %.2e", cage.name.c_str(),
              minimumWeight(mvc), minimumWeight(cageBind(*d, points)->weights));
        QVERIFY(minimumWeight(mvc) < -1e-3);
        QVERIFY(minimumWeight(cageBind(*d, points)->weights) >= -kTolerance);
    }
}

void TestHarmonicCage::dragIsLinearInEachCorner()
{
    const Eigen::MatrixX2d corners = handCage();
    const auto d = precompute(corners);
    QVERIFY(d);
    const auto binding = cageBind(*d, insidePoints(*d));
    QVERIFY(binding);
    Eigen::MatrixX2d base, moved;
    QVERIFY(!cageDeform(*binding, corners, base));
    const double *storage = base.data();
    for (const Eigen::Index corner : {Eigen::Index(0), Eigen::Index(12)}) {
        Eigen::MatrixX2d posed = corners;
        posed.row(corner) += Eigen::RowVector2d(40, -25);
        QVERIFY(!cageDeform(*binding, posed, moved));
        const Eigen::MatrixX2d expected =
            base + binding->weights.col(corner) * Eigen::RowVector2d(40, -25);
        QVERIFY((moved - expected).cwiseAbs().maxCoeff() <= kTolerance * d->extent);
        // Locality inside the cage: the fingertip corner barely moves the far side of the palm.
        if (corner == 12)
            QVERIFY(binding->weights.col(corner).minCoeff() < 1e-3);
    }
    QVERIFY(!cageDeform(*binding, corners, base));
    QCOMPARE(base.data(), storage); // reused, not reallocated
    const auto fresh = cageDeform(*binding, corners);
    QVERIFY(fresh && *fresh == base);
    QCOMPARE(cageDeform(*binding, corners.topRows(3)).error().code, DeformErrorCode::SizeMismatch);
}

void TestHarmonicCage::bindsManyPointsOnTwoThreads()
{
    const auto d = precompute(handCage(), 2000);
    QVERIFY(d);
    std::mt19937 random(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Eigen::MatrixX2d points(60000, 2);
    for (Eigen::Index k = 0; k < points.rows();) { // inside the palm and the thumb's base
        const Eigen::RowVector2d p(1.0 + 118.0 * unit(random), 1.0 + 118.0 * unit(random));
        points.row(k++) = p;
    }
    const auto all = cageBind(*d, points); // above the threshold: two threads
    QVERIFY(all);
    const auto first = cageBind(*d, points.topRows(30000)),
               second = cageBind(*d, points.bottomRows(30000));
    QVERIFY(first && second);
    QVERIFY(all->weights.topRows(30000) == first->weights);
    QVERIFY(all->weights.bottomRows(30000) == second->weights);
    QVERIFY((all->weights.rowwise().sum().array() - 1.0).abs().maxCoeff() <= kTolerance);
    // An outside point in the second half is reported with its row.
    points(45000, 0) = -50.0;
    const auto outside = cageBind(*d, points);
    QVERIFY(!outside);
    QCOMPARE(outside.error().items, std::vector<int>{45000});
}

void TestHarmonicCage::selfCrossingPoseStillDeforms()
{
    const Eigen::MatrixX2d corners = horseshoeCage();
    const auto d = precompute(corners, 1000);
    QVERIFY(d);
    const auto binding = cageBind(*d, insidePoints(*d));
    QVERIFY(binding);
    Eigen::MatrixX2d posed = corners;
    posed.row(0) = corners.row(20); // far across the band: the posed cage crosses itself
    QVERIFY(geometry::checkCage(posed).has_value());
    Eigen::MatrixX2d out;
    QVERIFY(!cageDeform(*binding, posed, out));
    QVERIFY(out.allFinite());
    const auto mesh = cageDeformMesh(*d, posed);
    QVERIFY(mesh && mesh->allFinite());
}

void TestHarmonicCage::refusesBadCages()
{
    const std::vector<Eigen::MatrixX2d> bad = {
        Eigen::MatrixX2d(0, 2),
        rows({{0, 0}}),
        rows({{0, 0}, {1, 0}}),
        rows({{0, 0}, {10, 10}, {10, 0}, {0, 5}}),  // crosses itself
        rows({{0, 0}, {5, 5}, {10, 10}}),           // zero area
        rows({{0, 0}, {kNaN, 0}, {0, 10}}),         // not a number
        rows({{0, 0}, {10, 0}, {10, 0}, {0, 10}})}; // repeated corner
    for (const Eigen::MatrixX2d &corners : bad) {
        const auto result = cagePrecompute(corners);
        QVERIFY(!result);
        QCOMPARE(result.error().code, DeformErrorCode::InvalidCage);
        QVERIFY(!result.error().message.empty());
    }
    // Meshes too fine for memory are refused before anything is built.
    CageOptions fine;
    fine.maxEdge = 0.01;
    QCOMPARE(cagePrecompute(squareCage(), fine).error().code, DeformErrorCode::TooLarge);
    CageOptions many;
    many.targetVertices = 400'000;
    QCOMPARE(cagePrecompute(horseshoeCage(100), many).error().code, DeformErrorCode::TooLarge);
}

void TestHarmonicCage::reportsPointsOutside()
{
    const Eigen::MatrixX2d corners = horseshoeCage();
    const auto d = precompute(corners, 1000);
    QVERIFY(d);
    const Eigen::MatrixX2d points = rows({{150, 0}, {0, 0}, {0, 150}, {-150, 0}, {0, -150}});
    const auto outside = cageBind(*d, points);
    QVERIFY(!outside);
    QCOMPARE(outside.error().code, DeformErrorCode::PointsOutsideCage);
    QCOMPARE(outside.error().items, (std::vector<int>{1, 3}));
    // Rounding-level excursions past an edge are on the cage, not outside it.
    const Eigen::RowVector2d a = corners.row(0), b = corners.row(1);
    const Eigen::RowVector2d outward =
        Eigen::RowVector2d(b.y() - a.y(), a.x() - b.x()).normalized();
    QVERIFY(cageBind(*d, 0.5 * (a + b) + 1e-11 * outward));
    QVERIFY(!cageBind(*d, 0.5 * (a + b) + 1e-3 * outward));
    const auto nan = cageBind(*d, rows({{150, 0}, {kNaN, 0}}));
    QVERIFY(!nan);
    QCOMPARE(nan.error().code, DeformErrorCode::NonFiniteInput);
    QCOMPARE(nan.error().items, std::vector<int>{1});
    const auto none = cageBind(*d, Eigen::MatrixX2d(0, 2));
    QVERIFY(none && none->weights.rows() == 0);
}

void TestHarmonicCage::refusesBadPoses()
{
    const auto d = precompute(squareCage(), 500);
    QVERIFY(d);
    const auto binding = cageBind(*d, rows({{50, 50}, {100, 20}}));
    QVERIFY(binding);
    Eigen::MatrixX2d out;
    QCOMPARE(cageDeform(*binding, squareCage().topRows(3), out)->code,
             DeformErrorCode::SizeMismatch);
    Eigen::MatrixX2d posed = squareCage();
    posed(2, 1) = kNaN;
    QCOMPARE(cageDeform(*binding, posed, out)->code, DeformErrorCode::NonFiniteInput);
    posed(2, 1) = 1e200;
    QCOMPARE(cageDeform(*binding, posed, out)->code, DeformErrorCode::CoordinateOutOfRange);
    QCOMPARE(cageDeformMesh(*d, squareCage().topRows(2)).error().code,
             DeformErrorCode::SizeMismatch);
}

void TestHarmonicCage::cancels()
{
    for (int allowed = 0; allowed < 3; ++allowed) {
        int polls = 0;
        const auto result = cagePrecompute(horseshoeCage(), {}, [&] { return polls++ >= allowed; });
        QVERIFY(!result);
        QCOMPARE(result.error().code, DeformErrorCode::Cancelled);
    }
    int polls = 0;
    QVERIFY(cagePrecompute(horseshoeCage(), {}, [&] { return ++polls < 0; }));
    QVERIFY(polls >= 3); // polled between the stages
}

namespace {

// Fit a cage to the points, precompute, bind them and check every property.
void checkRealShape(const geometry::Region &shape, const Eigen::MatrixX2d &points)
{
    geometry::FitCageOptions fit;
    const auto cage = geometry::fitCage(shape, points, fit);
    QVERIFY2(cage, cage ? "" : cage.error().message.c_str());
    const auto d = precompute(*cage, 2000);
    QVERIFY(d);
    checkProperties(*cage, *d, points);
    // A random pose: finite, and each point stays a convex combination of the posed corners.
    std::mt19937 random(11);
    std::normal_distribution<double> jitter(0.0, 0.1 * d->extent);
    Eigen::MatrixX2d posed = *cage;
    for (Eigen::Index i = 0; i < posed.rows(); ++i)
        posed.row(i) += Eigen::RowVector2d(jitter(random), jitter(random));
    const auto binding = cageBind(*d, points);
    Eigen::MatrixX2d out;
    QVERIFY(!cageDeform(*binding, posed, out));
    QVERIFY(out.allFinite());
    QVERIFY((out.colwise().minCoeff().array() >= posed.colwise().minCoeff().array() - 1e-9).all());
    QVERIFY((out.colwise().maxCoeff().array() <= posed.colwise().maxCoeff().array() + 1e-9).all());
}

} // namespace

void TestHarmonicCage::realSketches_data()
{
    QTest::addColumn<QString>("path");
    const QStringList files = dataFiles(QStringLiteral("sketches"));
    if (files.isEmpty())
        QSKIP("no real data (set FINBOOK_DATA_DIR to ../shared/data)");
    for (const QString &path : files)
        QTest::newRow(qPrintable(QFileInfo(path).baseName())) << path;
}

void TestHarmonicCage::realSketches()
{
    QFETCH(QString, path);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    std::vector<geometry::StrokeInput> strokes;
    Eigen::Index total = 0;
    for (const QJsonValue &stroke : QJsonDocument::fromJson(file.readAll())
                                        .object()
                                        .value(QStringLiteral("strokes"))
                                        .toArray()) {
        strokes.push_back({toMatrix(stroke.toArray()), 3.0});
        total += strokes.back().points.rows();
    }
    Eigen::MatrixX2d points(total, 2);
    total = 0;
    for (const auto &stroke : strokes) {
        points.middleRows(total, stroke.points.rows()) = stroke.points;
        total += stroke.points.rows();
    }
    const auto region = geometry::silhouette(strokes);
    QVERIFY(region);
    checkRealShape(*region, points);
}

void TestHarmonicCage::realSilhouettes_data()
{
    QTest::addColumn<QString>("path");
    const QStringList files = dataFiles(QStringLiteral("silhouettes"));
    if (files.isEmpty())
        QSKIP("no real data (set FINBOOK_DATA_DIR to ../shared/data)");
    for (const QString &path : files)
        QTest::newRow(qPrintable(QFileInfo(path).baseName())) << path;
}

void TestHarmonicCage::realSilhouettes()
{
    QFETCH(QString, path);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonArray contours = QJsonDocument::fromJson(file.readAll())
                                    .object()
                                    .value(QStringLiteral("contours"))
                                    .toArray();
    geometry::Polygon polygon;
    std::vector<Eigen::MatrixX2d> rings;
    Eigen::Index total = 0;
    for (qsizetype i = 0; i < contours.size(); ++i) {
        rings.push_back(toMatrix(contours[i].toArray()));
        (i == 0 ? polygon.outer : polygon.holes.emplace_back()) = rings.back();
        total += rings.back().rows();
    }
    Eigen::MatrixX2d points(total, 2);
    total = 0;
    for (const auto &ring : rings) {
        points.middleRows(total, ring.rows()) = ring;
        total += ring.rows();
    }
    checkRealShape(geometry::Region{polygon}, points);
}

QTEST_APPLESS_MAIN(TestHarmonicCage)
#include "tst_harmonic_cage.moc"
