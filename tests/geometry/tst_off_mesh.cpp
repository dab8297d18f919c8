// The OFF reader for 2D meshes (z ignored): the benchmark's and File → Import's way to bring in
// meshes such as the harmonic-coordinates notebook's "woody" figure.
#include "geometry_test_support.h"

#include <finbook/geometry/cage/cage_polygon.h>
#include <finbook/geometry/cage/fit_cage.h>
#include <finbook/geometry/import/off_mesh.h>
#include <finbook/geometry/mesh_quality.h>
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/simplicity.h>

#include <QtTest>

using namespace finbook::geometry;

class TestOffMesh : public QObject {
    Q_OBJECT
private slots:
    void readsOff();
    void readsWoodyOff();
    void refusesMalformedOff_data();
    void refusesMalformedOff();
};

void TestOffMesh::readsOff()
{
    // A unit square as a quad and a triangle beside it, clockwise, with comments.
    const std::string text = "OFF # a comment\n"
                             "# whole-line comment\n"
                             "5 2 0\n"
                             "0 0 0\n0 1 0\n1 1 0\n1 0 0\n"
                             "2 0.5 7 255 0 0\n"
                             "4 0 1 2 3\n"
                             "3 3 2 4 0 0 0\n";
    const auto mesh = parseOff(text);
    QVERIFY2(mesh, mesh ? "" : mesh.error().message.c_str());
    QCOMPARE(mesh->V.rows(), Eigen::Index(5));
    QCOMPARE(mesh->F.rows(), Eigen::Index(3));
    QVERIFY(mesh->V.row(4) == Eigen::RowVector2d(2, 0.5));
    QVERIFY(triangleSignedAreas(mesh->V, mesh->F).minCoeff() > 0.0); // flipped to positive
    QCOMPARE(int(mesh->boundaryLoops.size()), 1);
    QCOMPARE(mesh->boundaryLoops.front().size(), Eigen::Index(5));
    const auto rings = boundaryRings(*mesh);
    QCOMPARE(signedArea(rings.front()), 1.5);
    // Counts on the OFF line, COFF.
    const auto inline_ =
        parseOff("COFF 3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n");
    QVERIFY(inline_);
    QCOMPARE(inline_->F.rows(), Eigen::Index(1));
}

void TestOffMesh::readsWoodyOff()
{
    const auto mesh = readOff(FINBOOK_SOURCE_DIR "/tests/data/woody-synthetic.off");
    QVERIFY2(mesh, mesh ? "" : mesh.error().message.c_str());
    QVERIFY(mesh->V.rows() >= 150 && mesh->V.rows() <= 260);
    QCOMPARE(int(mesh->boundaryLoops.size()), 1);
    const auto rings = boundaryRings(*mesh);
    QVERIFY(signedArea(rings.front()) > 0.0);
    QVERIFY(isSimple(rings.front()));
    QVERIFY(std::abs(signedArea(rings.front()) - triangleSignedAreas(mesh->V, mesh->F).sum()) <
            1e-6 * signedArea(rings.front()));
    // The notebook's case: a cage around the figure containing all its vertices.
    FitCageOptions options;
    Polygon outline;
    outline.outer = rings.front();
    const auto cage = fitCage(Region{outline}, mesh->V, options);
    QVERIFY(cage);
    QVERIFY(!checkCage(*cage));
    QCOMPARE(cageOutsidePoints(*cage, mesh->V, 0.5 * options.margin).size(), Eigen::Index(0));
    QVERIFY(!readOff("/nonexistent/woody.off"));
}

void TestOffMesh::refusesMalformedOff_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("code");
    const auto code = [](GeometryErrorCode c) { return int(c); };
    const int malformed = code(GeometryErrorCode::MalformedFile);
    QTest::newRow("empty") << QString() << malformed;
    QTest::newRow("not off") << "PLY\n3 1 0\n" << malformed;
    QTest::newRow("no counts") << "OFF\n" << malformed;
    QTest::newRow("negative") << "OFF\n-3 1 0\n" << malformed;
    QTest::newRow("too many") << "OFF\n900000000 1 0\n" << code(GeometryErrorCode::TooManyPoints);
    QTest::newRow("missing vertex") << "OFF\n3 1 0\n0 0 0\n1 0 0\n" << malformed;
    QTest::newRow("text vertex") << "OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n" << malformed;
    QTest::newRow("nan") << "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n" << malformed;
    QTest::newRow("overflow") << "OFF\n3 1 0\n0 0 0\n1e999 0 0\n0 1 0\n3 0 1 2\n" << malformed;
    QTest::newRow("huge") << "OFF\n3 1 0\n0 0 0\n1e9 0 0\n0 1 0\n3 0 1 2\n"
                          << code(GeometryErrorCode::CoordinateOutOfRange);
    QTest::newRow("missing face") << "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n" << malformed;
    QTest::newRow("two corners") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n" << malformed;
    QTest::newRow("bad index") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n" << malformed;
    QTest::newRow("repeated index") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n" << malformed;
    QTest::newRow("short face") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n" << malformed;
}

void TestOffMesh::refusesMalformedOff()
{
    QFETCH(QString, text);
    QFETCH(int, code);
    const auto mesh = parseOff(text.toStdString());
    QVERIFY(!mesh);
    QCOMPARE(int(mesh.error().code), code);
    QVERIFY(!mesh.error().message.empty());
}

QTEST_APPLESS_MAIN(TestOffMesh)
#include "tst_off_mesh.moc"
