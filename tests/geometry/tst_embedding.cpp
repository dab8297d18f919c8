// Embedding points in a mesh: exact round trip at rest, affine maps carried over, snapping of
// outside points to the true nearest point, and no NaN for any input.
#include <finbook/geometry/embedding.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/triangle_locator.h>

#include <QtTest>

#include <cmath>
#include <limits>
#include <random>

using namespace finbook::geometry;

namespace {

ObjectMesh blobMesh()
{
    std::vector<StrokeInput> strokes;
    for (int k = 0; k < 3; ++k) {
        Eigen::MatrixX2d ring(90, 2);
        for (int i = 0; i < 90; ++i) {
            const double t = 2 * M_PI * i / 89.0;
            ring.row(i) << 300 * k + 120 * std::cos(t), 80 * std::sin(t) + 20 * std::sin(5 * t);
        }
        strokes.push_back({ring, 3.0});
    }
    auto mesh = buildObjectMesh(strokes);
    return std::move(*mesh);
}

// Random points inside random triangles (and the vertices themselves).
Eigen::MatrixX2d pointsOnMesh(const ObjectMesh &m, int count)
{
    std::mt19937 random(42);
    std::uniform_int_distribution<int> face(0, int(m.F.rows()) - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Eigen::MatrixX2d points(count + m.V.rows(), 2);
    for (int i = 0; i < count; ++i) {
        double a = unit(random), b = unit(random);
        if (a + b > 1) {
            a = 1 - a;
            b = 1 - b;
        }
        const int f = face(random);
        points.row(i) =
            (1 - a - b) * m.V.row(m.F(f, 0)) + a * m.V.row(m.F(f, 1)) + b * m.V.row(m.F(f, 2));
    }
    points.bottomRows(m.V.rows()) = m.V;
    return points;
}

double meshSize(const ObjectMesh &m)
{
    return (m.V.colwise().maxCoeff() - m.V.colwise().minCoeff()).maxCoeff();
}

double distanceToTriangle(const Eigen::RowVector2d &p, const ObjectMesh &m, int f)
{
    // Brute force: inside → 0, else the nearest of the three edges.
    const Eigen::RowVector2d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const auto cross = [](Eigen::RowVector2d u, Eigen::RowVector2d v) {
        return u.x() * v.y() - u.y() * v.x();
    };
    if (cross(b - a, p - a) >= 0 && cross(c - b, p - b) >= 0 && cross(a - c, p - c) >= 0)
        return 0.0;
    double best = std::numeric_limits<double>::max();
    for (auto [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
        const double t = std::clamp((p - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
        best = std::min(best, (p - (u + t * (v - u))).norm());
    }
    return best;
}

} // namespace

class TestEmbedding : public QObject {
    Q_OBJECT
private slots:
    void restPoseReproducesPoints();
    void weightsAreConvex();
    void affineMotionCarriesOver();
    void outsidePointsSnapToNearest();
    void nonFiniteAndEmptyNeverGiveNaN();
};

void TestEmbedding::restPoseReproducesPoints()
{
    const ObjectMesh mesh = blobMesh();
    const Eigen::MatrixX2d points = pointsOnMesh(mesh, 20000);
    const Embedding e = embed(mesh, points);
    QCOMPARE(e.snapped, 0);
    QCOMPARE(e.unlocated, 0);
    const Eigen::MatrixX2d back = applyEmbedding(e, mesh.V, mesh.F);
    QVERIFY((back - points).cwiseAbs().maxCoeff() <= 1e-9 * meshSize(mesh));
}

void TestEmbedding::weightsAreConvex()
{
    const ObjectMesh mesh = blobMesh();
    const Embedding e = embed(mesh, pointsOnMesh(mesh, 5000));
    QVERIFY(e.I.minCoeff() >= 0 && e.I.maxCoeff() < mesh.F.rows());
    QVERIFY(e.B.minCoeff() >= -1e-12);
    QVERIFY((e.B.rowwise().sum().array() - 1.0).abs().maxCoeff() < 1e-12);
}

void TestEmbedding::affineMotionCarriesOver()
{
    // Barycentric coordinates are affine-invariant: moving the mesh by an affine map moves the
    // embedded points by the same map.
    const ObjectMesh mesh = blobMesh();
    const Eigen::MatrixX2d points = pointsOnMesh(mesh, 3000);
    const Embedding e = embed(mesh, points);
    Eigen::Matrix2d A;
    A << 0.8, -0.9, 0.4, 1.3;
    const Eigen::RowVector2d t(250.0, -40.0);
    const Eigen::MatrixX2d Vmoved = (mesh.V * A.transpose()).rowwise() + t;
    const Eigen::MatrixX2d expected = (points * A.transpose()).rowwise() + t;
    const Eigen::MatrixX2d moved = applyEmbedding(e, Vmoved, mesh.F);
    QVERIFY((moved - expected).cwiseAbs().maxCoeff() <= 1e-9 * meshSize(mesh));
}

void TestEmbedding::outsidePointsSnapToNearest()
{
    const ObjectMesh mesh = blobMesh();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> x(-600, 1300), y(-400, 400);
    Eigen::MatrixX2d points(300, 2);
    for (int i = 0; i < points.rows(); ++i)
        points.row(i) << x(random), y(random);
    points.row(0) << 1e7, -1e7; // far away
    const Embedding e = embed(mesh, points);
    QVERIFY(e.snapped > 0);
    const Eigen::MatrixX2d placed = applyEmbedding(e, mesh.V, mesh.F);
    QVERIFY(placed.allFinite());
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        double nearest = std::numeric_limits<double>::max();
        for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
            nearest = std::min(nearest, distanceToTriangle(points.row(i), mesh, int(f)));
        QVERIFY(e.B.row(i).minCoeff() >= -1e-12);
        // The embedded position is (one of) the nearest point(s) of the mesh.
        QVERIFY(std::abs((placed.row(i) - points.row(i)).norm() - nearest) <=
                1e-9 * std::max(1.0, nearest));
    }
}

void TestEmbedding::nonFiniteAndEmptyNeverGiveNaN()
{
    const ObjectMesh mesh = blobMesh();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    Eigen::MatrixX2d points(3, 2);
    points << nan, 0, inf, -inf, 10, 10;
    const Embedding e = embed(mesh, points);
    QCOMPARE(e.unlocated, 2);
    QVERIFY(applyEmbedding(e, mesh.V, mesh.F).allFinite());

    const Embedding none = embed(mesh.V, Eigen::MatrixX3i(0, 3), points);
    QVERIFY((none.I.array() == -1).all());
    QVERIFY(applyEmbedding(none, mesh.V, mesh.F).allFinite());

    // A mesh with NaN positions locates nothing instead of indexing garbage.
    Eigen::MatrixX2d broken = mesh.V;
    broken(0, 0) = nan;
    const Location nowhere = TriangleLocator(broken, mesh.F).locate({0, 0});
    QCOMPARE(nowhere.triangle, -1);
}

QTEST_APPLESS_MAIN(TestEmbedding)
#include "tst_embedding.moc"
