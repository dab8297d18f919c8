// Degenerate and hostile input: every case gives a typed error with a message, or the
// documented fallback — never a crash, never NaN.
#include "geometry_test_support.h"

#include <finbook/geometry/embedding.h>
#include <finbook/geometry/mesh_quality.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/polygon_repair.h>

#include <QtTest>

#include <cmath>
#include <limits>
#include <random>

using namespace finbook::geometry;

namespace {

using namespace finbook::test;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
using MeshResult = finbook::Expected<ObjectMesh, GeometryError>;

void expectError(const MeshResult &result, GeometryErrorCode code)
{
    QVERIFY(!result.hasValue());
    QCOMPARE(int(result.error().code), int(code));
    QVERIFY(result.error().message.size() > 10);
}

void expectMesh(const MeshResult &result)
{
    QVERIFY2(result.hasValue(), result.hasValue() ? "" : result.error().message.c_str());
    QVERIFY(result->V.allFinite());
    QVERIFY(result->F.rows() > 0);
    QVERIFY(triangleSignedAreas(result->V, result->F).minCoeff() > 0.0);
    QVERIFY(minAngleDegrees(result->V, result->F) >= 20.0);
}

} // namespace

class TestBadInput : public QObject {
    Q_OBJECT
private slots:
    void emptyGroup();
    void strokesWithoutFinitePoints();
    void nonFinitePointsAreDropped();
    void oneDotBecomesSmallDisk();
    void repeatedPointsOnly();
    void collinearStrokesGiveBand();
    void zeroWidthAndZeroMargin();
    void invalidWidths();
    void hugeCoordinates();
    void invalidOptions();
    void thousandsOfOverlappingStrokes();
    void tinyDrawing();
    void longStroke();
    void badRegions();
};

void TestBadInput::emptyGroup()
{
    expectError(buildObjectMesh(std::vector<StrokeInput>{}), GeometryErrorCode::EmptyInput);
    expectError(buildObjectMesh(Region{}), GeometryErrorCode::EmptyInput);
}

void TestBadInput::strokesWithoutFinitePoints()
{
    const std::vector<StrokeInput> strokes{{Eigen::MatrixX2d(0, 2), 3.0},
                                           {rows({{kNaN, 1}, {2, kInf}}), 3.0}};
    expectError(buildObjectMesh(strokes), GeometryErrorCode::EmptyInput);
}

void TestBadInput::nonFinitePointsAreDropped()
{
    const std::vector<StrokeInput> strokes{
        {rows({{0, 0}, {kNaN, 5}, {50, 0}, {kInf, kInf}, {50, 50}, {0, 50}}), 3.0},
        {rows({{-kInf, 0}}), 3.0}};
    const auto mesh = buildObjectMesh(strokes);
    expectMesh(mesh);
    const Embedding e = embed(*mesh, strokes[0].points);
    QCOMPARE(e.unlocated, 2);
    QCOMPARE(e.snapped, 0);
    QVERIFY(applyEmbedding(e, mesh->V, mesh->F).allFinite());
}

void TestBadInput::oneDotBecomesSmallDisk()
{
    const auto mesh = buildObjectMesh({{rows({{100, 200}}), 4.0}});
    expectMesh(mesh);
    const double r = 2.0 + SilhouetteOptions{}.margin;
    const double area = triangleSignedAreas(mesh->V, mesh->F).sum();
    QVERIFY(area > 0.85 * M_PI * r * r && area <= M_PI * r * r);
    QVERIFY(mesh->V.rows() < 200); // a dot does not get a character's vertex budget
    QCOMPARE(embed(*mesh, rows({{100, 200}})).snapped, 0);
}

void TestBadInput::repeatedPointsOnly()
{
    expectMesh(buildObjectMesh({{rows({{7, 7}, {7, 7}, {7, 7}, {7, 7}}), 3.0}}));
}

void TestBadInput::collinearStrokesGiveBand()
{
    std::vector<StrokeInput> strokes;
    for (int i = 0; i < 5; ++i)
        strokes.push_back({rows({{10.0 * i, 0}, {10.0 * i + 30, 0}, {10.0 * i + 15, 0}}), 2.0});
    const auto mesh = buildObjectMesh(strokes);
    expectMesh(mesh);
    QCOMPARE(connectedComponents(mesh->F, mesh->V.rows()), 1);
}

void TestBadInput::zeroWidthAndZeroMargin()
{
    MeshOptions options;
    options.silhouette.margin = 0.0;
    expectError(buildObjectMesh({{rows({{0, 0}, {100, 0}}), 0.0}}, options),
                GeometryErrorCode::DegenerateRegion);
    // Zero width with the default margin is fine: the margin alone gives a band.
    expectMesh(buildObjectMesh({{rows({{0, 0}, {100, 0}}), 0.0}}));
}

void TestBadInput::invalidWidths()
{
    for (double width : {kNaN, -1.0, kInf, 1e9})
        expectError(buildObjectMesh({{rows({{0, 0}, {10, 10}}), width}}),
                    GeometryErrorCode::InvalidWidth);
}

void TestBadInput::hugeCoordinates()
{
    expectError(buildObjectMesh({{rows({{0, 0}, {1e12, 5}}), 3.0}}),
                GeometryErrorCode::CoordinateOutOfRange);
    expectError(buildObjectMesh(Region{Polygon{rows({{0, 0}, {-1e12, 0}, {0, 1}}), {}}}),
                GeometryErrorCode::CoordinateOutOfRange);
    // Large but supported: a drawing far from the origin meshes like one near it.
    const auto far = buildObjectMesh({{rows({{9e5, 9e5}, {9e5 + 300, 9e5 + 100}}), 3.0}});
    const auto near = buildObjectMesh({{rows({{0, 0}, {300, 100}}), 3.0}});
    expectMesh(far);
    expectMesh(near);
    const double a = triangleSignedAreas(far->V, far->F).sum();
    const double b = triangleSignedAreas(near->V, near->F).sum();
    QVERIFY(std::abs(a - b) < 1e-3 * b);
}

void TestBadInput::invalidOptions()
{
    const std::vector<StrokeInput> strokes{{rows({{0, 0}, {50, 50}}), 3.0}};
    MeshOptions options;
    options.density = 0.0;
    expectError(buildObjectMesh(strokes, options), GeometryErrorCode::InvalidOptions);
    options.density = kNaN;
    expectError(buildObjectMesh(strokes, options), GeometryErrorCode::InvalidOptions);
    options = {};
    options.silhouette.gap = -1.0;
    expectError(buildObjectMesh(strokes, options), GeometryErrorCode::InvalidOptions);
    options = {};
    options.silhouette.margin = kInf;
    expectError(buildObjectMesh(strokes, options), GeometryErrorCode::InvalidOptions);
    options = {};
    options.maxVertices = 10; // below the target
    expectError(buildObjectMesh(strokes, options), GeometryErrorCode::InvalidOptions);
    options = {};
    options.repair.cornerRadius = kNaN;
    expectError(buildObjectMesh(Region{Polygon{rows({{0, 0}, {9, 0}, {0, 9}}), {}}}, options),
                GeometryErrorCode::InvalidOptions);
}

void TestBadInput::thousandsOfOverlappingStrokes()
{
    std::mt19937 random(3);
    std::uniform_real_distribution<double> coord(0.0, 600.0);
    std::vector<StrokeInput> strokes;
    for (int s = 0; s < 3000; ++s) {
        Eigen::MatrixX2d points(12, 2);
        for (int i = 0; i < points.rows(); ++i)
            points.row(i) << coord(random), coord(random);
        strokes.push_back({points, 1.0 + (s % 5)});
    }
    const auto mesh = buildObjectMesh(strokes);
    expectMesh(mesh);
    QVERIFY(mesh->V.rows() <= 2 * MeshOptions{}.maxVertices);
}

void TestBadInput::tinyDrawing()
{
    // A scribble a thousandth of a pixel across: the pen width dominates, a small disk.
    const auto mesh = buildObjectMesh({{rows({{0, 0}, {1e-3, 1e-3}, {0, 1e-3}}), 2.0}});
    expectMesh(mesh);
}

void TestBadInput::longStroke()
{
    Eigen::MatrixX2d spiral(100000, 2);
    for (int i = 0; i < spiral.rows(); ++i) {
        const double t = i * 0.002;
        spiral.row(i) << (50 + 2 * t) * std::cos(t), (50 + 2 * t) * std::sin(t);
    }
    expectMesh(buildObjectMesh({{spiral, 2.0}}));
}

void TestBadInput::badRegions()
{
    // Collinear outline, a ring of two points, NaN rows: errors or dropped, never a crash.
    expectError(buildObjectMesh(Region{Polygon{rows({{0, 0}, {5, 5}, {10, 10}}), {}}}),
                GeometryErrorCode::DegenerateRegion);
    expectError(buildObjectMesh(Region{Polygon{rows({{0, 0}, {5, 5}}), {}}}),
                GeometryErrorCode::DegenerateRegion);
    expectMesh(buildObjectMesh(
        Region{Polygon{rows({{0, 0}, {kNaN, 3}, {100, 0}, {100, 100}, {0, 100}}), {}}}));
    // A hole larger than its outer ring swallows it under even-odd: what is left is meshed.
    expectMesh(buildObjectMesh(Region{Polygon{rows({{0, 0}, {10, 0}, {10, 10}, {0, 10}}),
                                              {rows({{-5, -5}, {15, -5}, {15, 15}, {-5, 15}})}}}));
    // Thinner than the corner radius: nothing survives the opening.
    expectError(
        buildObjectMesh(Region{Polygon{rows({{0, 0}, {100, 0}, {100, 0.5}, {0, 0.5}}), {}}}),
        GeometryErrorCode::DegenerateRegion);
    expectError(meshRegion(Region{Polygon{Eigen::MatrixX2d(0, 2), {}}}),
                GeometryErrorCode::NotSimple);
}

QTEST_APPLESS_MAIN(TestBadInput)
#include "tst_bad_input.moc"
