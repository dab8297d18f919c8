// Object meshes: the ObjectMesh promises, domain (notches and holes stay empty), lobes,
// density, and agreement between V/F and the OpenMesh mesh.
#include "geometry_test_support.h"

#include <finbook/geometry/mesh_quality.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/polyline.h>

#include <QtTest>

#include <cmath>

using namespace finbook::geometry;

namespace {

using namespace finbook::test;

void checkMesh(const ObjectMesh &m)
{
    QVERIFY(m.V.rows() >= 3 && m.F.rows() >= 1);
    QVERIFY(m.V.allFinite());
    QVERIFY(m.F.minCoeff() >= 0 && m.F.maxCoeff() < m.V.rows());
    QVERIFY(triangleSignedAreas(m.V, m.F).minCoeff() > 0.0); // all counter-clockwise
    Eigen::VectorXi uses = Eigen::VectorXi::Zero(m.V.rows());
    for (Eigen::Index i = 0; i < m.F.size(); ++i)
        ++uses(m.F.data()[i]);
    QVERIFY(uses.minCoeff() > 0); // no unreferenced vertex
    QVERIFY(minAngleDegrees(m.V, m.F) >= 20.0);
    const double area = regionArea(m.region);
    QVERIFY(std::abs(triangleSignedAreas(m.V, m.F).sum() - area) <= 1e-9 * area);
    // The OpenMesh mesh is the same mesh, vertex for vertex and face for face.
    QCOMPARE(qsizetype(m.mesh.n_vertices()), qsizetype(m.V.rows()));
    QCOMPARE(qsizetype(m.mesh.n_faces()), qsizetype(m.F.rows()));
    for (const auto v : m.mesh.vertices()) {
        const auto p = m.mesh.point(v);
        QCOMPARE(p[0], m.V(v.idx(), 0));
        QCOMPARE(p[1], m.V(v.idx(), 1));
        QCOMPARE(p[2], 0.0);
    }
    for (const auto f : m.mesh.faces()) {
        std::vector<int> ids;
        for (const auto v : m.mesh.fv_range(f))
            ids.push_back(v.idx());
        QCOMPARE(int(ids.size()), 3);
        const Eigen::RowVector3i row = m.F.row(f.idx());
        // Same cyclic order (OpenMesh may start the cycle at another vertex).
        const int shift = ids[0] == row(0) ? 0 : ids[0] == row(1) ? 1 : 2;
        for (int k = 0; k < 3; ++k)
            QCOMPARE(ids[std::size_t(k)], row((k + shift) % 3));
    }
}

} // namespace

class TestObjectMesh : public QObject {
    Q_OBJECT
private slots:
    void characterSizedShapeHasTargetVertexCount();
    void concaveNotchStaysEmpty();
    void holeStaysEmpty();
    void islandInHoleIsMeshed();
    void lobesAreSeparateComponents();
    void pinchedLobesMesh();
    void densityScalesVertexCount();
    void maxVerticesBoundsAbsurdDensity();
    void strokesMeshCoversEveryPoint();
    void meshRegionRefusesCrossingRings();
    void edgeLengthFollowsArea();
};

void TestObjectMesh::characterSizedShapeHasTargetVertexCount()
{
    // A blob filling most of a 1280×720 canvas.
    const auto mesh = buildObjectMesh(Region{Polygon{ellipse(400, 560, 320, {640, 360}), {}}});
    QVERIFY(mesh.hasValue());
    checkMesh(*mesh);
    QVERIFY(mesh->V.rows() >= 1000 && mesh->V.rows() <= 3000);
    QCOMPARE(connectedComponents(mesh->F, mesh->V.rows()), 1);
}

void TestObjectMesh::concaveNotchStaysEmpty()
{
    // A U: CGAL without domain marks would fill the notch (the convex hull).
    const Eigen::MatrixX2d u = rows(
        {{0, 0}, {300, 0}, {300, 300}, {200, 300}, {200, 100}, {100, 100}, {100, 300}, {0, 300}});
    const auto mesh = buildObjectMesh(Region{Polygon{u, {}}});
    QVERIFY(mesh.hasValue());
    checkMesh(*mesh);
    const double area = triangleSignedAreas(mesh->V, mesh->F).sum();
    QVERIFY(std::abs(area - 70000.0) < 0.01 * 70000.0); // not 90000
    for (Eigen::Index f = 0; f < mesh->F.rows(); ++f) {
        const Eigen::RowVector2d c =
            (mesh->V.row(mesh->F(f, 0)) + mesh->V.row(mesh->F(f, 1)) + mesh->V.row(mesh->F(f, 2))) /
            3.0;
        QVERIFY(!(c.x() > 101 && c.x() < 199 && c.y() > 101));
    }
}

void TestObjectMesh::holeStaysEmpty()
{
    const Eigen::MatrixX2d hole = ellipse(80, 60, 40, {200, 150}).colwise().reverse();
    const auto mesh =
        buildObjectMesh(Region{Polygon{rows({{0, 0}, {400, 0}, {400, 300}, {0, 300}}), {hole}}});
    QVERIFY(mesh.hasValue());
    checkMesh(*mesh);
    QCOMPARE(mesh->region.size(), std::size_t(1));
    QCOMPARE(mesh->region[0].holes.size(), std::size_t(1));
    for (Eigen::Index f = 0; f < mesh->F.rows(); ++f) {
        const Eigen::RowVector2d c =
            (mesh->V.row(mesh->F(f, 0)) + mesh->V.row(mesh->F(f, 1)) + mesh->V.row(mesh->F(f, 2))) /
            3.0;
        QVERIFY(!insideRing(mesh->region[0].holes[0], c));
    }
    const double expected = 120000.0 - M_PI * 60 * 40;
    QVERIFY(std::abs(triangleSignedAreas(mesh->V, mesh->F).sum() - expected) < 0.01 * expected);
}

void TestObjectMesh::islandInHoleIsMeshed()
{
    Region region{Polygon{ellipse(120, 200, 200), {ellipse(90, 120, 120).colwise().reverse()}},
                  Polygon{ellipse(60, 50, 50), {}}};
    const auto mesh = meshRegion(region);
    QVERIFY(mesh.hasValue());
    checkMesh(*mesh);
    QCOMPARE(connectedComponents(mesh->F, mesh->V.rows()), 2);
}

void TestObjectMesh::lobesAreSeparateComponents()
{
    const std::vector<StrokeInput> strokes{{ellipse(50, 40, 40, {0, 0}), 3.0},
                                           {ellipse(50, 40, 40, {300, 0}), 3.0}};
    const auto mesh = buildObjectMesh(strokes);
    QVERIFY(mesh.hasValue());
    checkMesh(*mesh);
    QCOMPARE(connectedComponents(mesh->F, mesh->V.rows()), 2);
}

void TestObjectMesh::pinchedLobesMesh()
{
    // Two squares meeting at one corner: a non-manifold point OpenMesh cannot store as one
    // vertex, so it is split into two.
    const Region region{Polygon{rows({{0, 0}, {100, 0}, {100, 100}, {0, 100}}), {}},
                        Polygon{rows({{100, 100}, {200, 100}, {200, 200}, {100, 200}}), {}}};
    const auto mesh = meshRegion(region);
    QVERIFY2(mesh.hasValue(), mesh.hasValue() ? "" : mesh.error().message.c_str());
    checkMesh(*mesh);
    QCOMPARE(connectedComponents(mesh->F, mesh->V.rows()), 2);
}

void TestObjectMesh::densityScalesVertexCount()
{
    const Region region{Polygon{ellipse(200, 300, 200), {}}};
    MeshOptions coarse, fine;
    coarse.density = 0.5;
    fine.density = 2.0;
    const auto a = meshRegion(region, coarse), b = meshRegion(region, MeshOptions{}),
               c = meshRegion(region, fine);
    QVERIFY(a.hasValue() && b.hasValue() && c.hasValue());
    checkMesh(*a);
    checkMesh(*c);
    // Edge length ∝ 1/density, so about 4× the vertices per doubling.
    QVERIFY(b->V.rows() > 2.5 * a->V.rows() && b->V.rows() < 6 * a->V.rows());
    QVERIFY(c->V.rows() > 2.5 * b->V.rows() && c->V.rows() < 6 * b->V.rows());
}

void TestObjectMesh::maxVerticesBoundsAbsurdDensity()
{
    MeshOptions options;
    options.density = 100.0;
    options.maxVertices = 5000;
    const auto mesh = meshRegion(Region{Polygon{ellipse(200, 300, 200), {}}}, options);
    QVERIFY(mesh.hasValue());
    checkMesh(*mesh);
    QVERIFY(mesh->V.rows() <= 2 * options.maxVertices);
}

void TestObjectMesh::strokesMeshCoversEveryPoint()
{
    std::vector<StrokeInput> strokes;
    for (int i = 0; i < 6; ++i)
        strokes.push_back({ellipse(40, 60 + 10 * i, 30, {100.0 * i, 50.0 * (i % 2)}), 2.0 + i});
    const auto mesh = buildObjectMesh(strokes);
    QVERIFY(mesh.hasValue());
    checkMesh(*mesh);
    for (const StrokeInput &s : strokes)
        for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
            bool covered = false;
            for (const Polygon &p : mesh->region)
                covered = covered || insideRing(p.outer, s.points.row(i));
            QVERIFY(covered);
        }
}

void TestObjectMesh::meshRegionRefusesCrossingRings()
{
    const auto mesh = meshRegion(Region{Polygon{rows({{0, 0}, {40, 40}, {40, 0}, {0, 40}}), {}}});
    QVERIFY(!mesh.hasValue());
    QCOMPARE(mesh.error().code, GeometryErrorCode::NotSimple);
    QVERIFY(!mesh.error().message.empty());
    // The repairing overload takes the same bowtie.
    QVERIFY(buildObjectMesh(Region{Polygon{rows({{0, 0}, {40, 40}, {40, 0}, {0, 40}}), {}}})
                .hasValue());
}

void TestObjectMesh::edgeLengthFollowsArea()
{
    const MeshOptions options;
    const double small = meshEdgeLength(1e4, 400, options);
    const double large = meshEdgeLength(1e6, 4000, options);
    QVERIFY(large > 5 * small && large < 15 * small); // ≈ 10× for 100× the area
    QCOMPARE(meshEdgeLength(0.0, 0.0, options), options.minEdge);
}

QTEST_APPLESS_MAIN(TestObjectMesh)
#include "tst_object_mesh.moc"
