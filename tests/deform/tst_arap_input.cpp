// Degenerate input to the ARAP precompute gives a typed error, never NaN or a crash.
#include "grid_mesh.h"

#include <finbook/deform/arap.h>

#include <QTest>

#include <cmath>
#include <limits>

using namespace finbook::deform;

Q_DECLARE_METATYPE(Eigen::MatrixX2d)
Q_DECLARE_METATYPE(Eigen::MatrixX3i)
Q_DECLARE_METATYPE(Eigen::VectorXi)
Q_DECLARE_METATYPE(finbook::deform::DeformErrorCode)

class TestArapInput : public QObject {
    Q_OBJECT

private slots:
    void rejectsDegenerateInput_data();
    void rejectsDegenerateInput();
    void acceptsAnyTriangleOrientation();
    void acceptsFullyPinnedComponent();
    void acceptsFarAwayMeshes();
};

void TestArapInput::rejectsDegenerateInput_data()
{
    QTest::addColumn<Eigen::MatrixX2d>("V");
    QTest::addColumn<Eigen::MatrixX3i>("F");
    QTest::addColumn<Eigen::VectorXi>("b");
    QTest::addColumn<DeformErrorCode>("expected");

    const auto g = finbook::test::gridMesh(3, 3, 1.0, 1.0);
    Eigen::VectorXi pins(2);
    pins << 0, 15;
    using Code = DeformErrorCode;
    QTest::newRow("no vertices") << Eigen::MatrixX2d(0, 2) << Eigen::MatrixX3i(0, 3)
                                 << Eigen::VectorXi() << Code::EmptyMesh;
    QTest::newRow("no triangles") << g.V << Eigen::MatrixX3i(0, 3) << pins << Code::EmptyMesh;

    Eigen::MatrixX3i tooLarge = g.F, negative = g.F;
    tooLarge(4, 1) = int(g.V.rows());
    negative(0, 2) = -1;
    QTest::newRow("index past the end") << g.V << tooLarge << pins << Code::InvalidIndex;
    QTest::newRow("negative index") << g.V << negative << pins << Code::InvalidIndex;
    Eigen::VectorXi badPin = pins;
    badPin(1) = 99;
    QTest::newRow("pin past the end") << g.V << g.F << badPin << Code::InvalidIndex;

    Eigen::MatrixX2d nan = g.V, inf = g.V;
    nan(5, 0) = std::numeric_limits<double>::quiet_NaN();
    inf(7, 1) = std::numeric_limits<double>::infinity();
    QTest::newRow("NaN position") << nan << g.F << pins << Code::NonFiniteInput;
    QTest::newRow("infinite position") << inf << g.F << pins << Code::NonFiniteInput;
    QTest::newRow("huge coordinates")
        << Eigen::MatrixX2d(g.V * 1e200) << g.F << pins << Code::CoordinateOutOfRange;

    Eigen::MatrixX2d collinear = g.V;
    collinear.row(g.F(3, 2)) = 0.5 * (collinear.row(g.F(3, 0)) + collinear.row(g.F(3, 1)));
    QTest::newRow("collinear corners") << collinear << g.F << pins << Code::DegenerateTriangle;
    Eigen::MatrixX2d coincident = g.V;
    coincident.row(5) = coincident.row(6);
    QTest::newRow("coincident vertices") << coincident << g.F << pins << Code::DegenerateTriangle;
    Eigen::MatrixX3i repeated = g.F;
    repeated(2, 1) = repeated(2, 0);
    QTest::newRow("repeated corner") << g.V << repeated << pins << Code::DegenerateTriangle;

    // Two squares touching at one corner: the second could spin about it at no step-1 cost.
    const auto other = finbook::test::gridMesh(3, 3, 1.0, 1.0, 0.0, {1.0, 1.0});
    Eigen::MatrixX2d pinchedV = g.V;
    Eigen::MatrixX3i pinchedF = g.F;
    finbook::test::appendMesh(pinchedV, pinchedF, other.V, other.F);
    const int corner = g.vertex(3, 3), duplicate = int(g.V.rows()) + other.vertex(0, 0);
    pinchedF = pinchedF.unaryExpr([&](int v) { return v == duplicate ? corner : v; });
    QTest::newRow("pinched vertex") << pinchedV << pinchedF << pins << Code::NonManifoldVertex;
}

void TestArapInput::rejectsDegenerateInput()
{
    QFETCH(Eigen::MatrixX2d, V);
    QFETCH(Eigen::MatrixX3i, F);
    QFETCH(Eigen::VectorXi, b);
    QFETCH(DeformErrorCode, expected);
    const auto result = arapPrecompute(V, F, b);
    QVERIFY(!result);
    QCOMPARE(result.error().code, expected);
    QVERIFY(!result.error().message.empty());
}

// Mixed orientation does not change the rest shape of a triangle, so it is no error.
void TestArapInput::acceptsAnyTriangleOrientation()
{
    auto g = finbook::test::gridMesh(6, 6, 1.0, 1.0, 0.2);
    for (Eigen::Index t = 0; t < g.F.rows(); t += 3)
        std::swap(g.F(t, 1), g.F(t, 2));
    Eigen::VectorXi b(2);
    b << 0, int(g.V.rows()) - 1;
    const auto data = arapPrecompute(g.V, g.F, b);
    QVERIFY(data);
    const Eigen::MatrixX2d moved = finbook::test::rigidlyMoved(g.V, 1.0, {2.0, 3.0});
    Eigen::MatrixX2d U;
    QVERIFY(arapSolve(**data, finbook::test::rowsOf(moved, b), U));
    QVERIFY((U - moved).rowwise().norm().maxCoeff() <= 1e-9 * g.size());
}

// A single triangle with all corners pinned leaves nothing to solve for.
void TestArapInput::acceptsFullyPinnedComponent()
{
    Eigen::MatrixX2d V(3, 2);
    V << 0.0, 0.0, 1.0, 0.0, 0.0, 1.0;
    const Eigen::MatrixX3i F = Eigen::RowVector3i(0, 1, 2);
    const Eigen::VectorXi b = Eigen::Vector3i(0, 1, 2);
    const auto data = arapPrecompute(V, F, b);
    QVERIFY(data);
    Eigen::MatrixX2d bc(3, 2), U;
    bc << 1.0, 1.0, 3.0, 1.0, 1.0, 2.0;
    QVERIFY(arapSolve(**data, bc, U));
    QCOMPARE(U, bc);
}

// Far from the origin (a huge canvas), rigid motions still come out rigid at mesh scale.
void TestArapInput::acceptsFarAwayMeshes()
{
    const auto g = finbook::test::gridMesh(8, 8, 100.0, 100.0, 0.2, {1e6, -1e6});
    Eigen::VectorXi b(2);
    b << 0, int(g.V.rows()) - 1;
    const auto data = arapPrecompute(g.V, g.F, b);
    QVERIFY(data);
    const Eigen::MatrixX2d moved = finbook::test::rigidlyMoved(g.V, 0.5, {3.0, 4.0});
    Eigen::MatrixX2d U;
    QVERIFY(arapSolve(**data, finbook::test::rowsOf(moved, b), U));
    QVERIFY((U - moved).rowwise().norm().maxCoeff() <= 1e-9 * g.size());
}

QTEST_APPLESS_MAIN(TestArapInput)
#include "tst_arap_input.moc"
