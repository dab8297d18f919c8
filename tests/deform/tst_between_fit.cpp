// Between Drawings, numerical core (issue 50): fitting drawing A onto drawing B as rigidly as
// possible, and as-rigid-as-possible interpolation of the fitted pair.
#include "../../deform/src/between/point_grid.h"
#include "between_fixtures.h"
#include "grid_mesh.h"

#include <finbook/deform/between/arap_interpolation.h>
#include <finbook/deform/between/rigid_fit.h>
#include <finbook/geometry/embedding.h>

#include <QtTest>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

using namespace finbook;
using namespace finbook::deform::between;
using finbook::test::StrokePoints;

namespace {

// Drawing A: a meshed rectangle and its stroke points embedded in the mesh.
struct DrawingA {
    test::GridMesh mesh;
    StrokePoints strokes;
    geometry::Embedding samples;
    std::shared_ptr<const RigidFitSource> source;

    DrawingA(int columns, int rows, double width, double height, double spacing,
             bool withMark = false)
        : mesh(test::gridMesh(columns, rows, width, height, 0.1))
    {
        strokes.addRectangle({0.0, 0.0}, {width, height}, spacing);
        // An inner stroke near the left end breaks the outline's half-turn symmetry.
        if (withMark)
            strokes.addSegment({0.15 * width, 0.3 * height}, {0.3 * width, 0.7 * height}, spacing);
        samples = geometry::embed(mesh.V, mesh.F, strokes.P);
        auto made = rigidFitPrecompute(mesh.V, mesh.F, samples, strokes.N);
        if (made)
            source = *made;
    }
    double size() const { return mesh.size(); }
};

double maxRowDistance(const Eigen::MatrixX2d &a, const Eigen::MatrixX2d &b)
{
    return (a - b).rowwise().norm().maxCoeff();
}

// B for the bent-arm tests: A's outline redrawn at another spacing, the forearm (right of the
// elbow at mid-length) turned by 60°, the parts of each half hidden inside the other removed,
// and the outer side of the elbow drawn round (an arc about the elbow, as one draws it).
StrokePoints bentArm(const test::ElbowBend &bend, double width, double height)
{
    StrokePoints redrawn;
    redrawn.addRectangle({0.0, 0.0}, {width, height}, 3.3);
    StrokePoints b;
    const Eigen::Matrix2d back = test::rotationBy(-bend.degrees);
    for (Eigen::Index i = 0; i < redrawn.P.rows(); ++i) {
        const Eigen::Vector2d p = redrawn.P.row(i).transpose();
        const Eigen::Vector2d q = bend.apply(p);
        const bool upper = p.x() <= bend.elbow.x();
        const Eigen::Vector2d inForearm = back * (q - bend.elbow) + bend.elbow;
        const bool hidden = upper ? (inForearm.x() > bend.elbow.x() && inForearm.y() > 0.0 &&
                                     inForearm.y() < height)
                                  : (q.x() < bend.elbow.x() && q.y() > 0.0 && q.y() < height);
        if (!hidden)
            b.add(q, bend.applyNormal(p, redrawn.N.row(i).transpose()));
    }
    const double radius = height / 2.0, sweep = bend.degrees * std::numbers::pi / 180.0;
    const int steps = int(std::round(radius * sweep / 3.3));
    for (int i = 1; i < steps; ++i) {
        const double angle = -0.5 * std::numbers::pi + sweep * i / steps;
        const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
        b.add(bend.elbow + radius * direction, direction);
    }
    return b;
}

// Angle (radians) of the rotation in the polar decomposition of triangle t's map V → U.
double triangleRotation(const Eigen::MatrixX2d &V, const Eigen::MatrixX2d &U,
                        const Eigen::MatrixX3i &F, Eigen::Index t)
{
    Eigen::Matrix2d D0, D1;
    D0 << (V.row(F(t, 1)) - V.row(F(t, 0))).transpose(),
        (V.row(F(t, 2)) - V.row(F(t, 0))).transpose();
    D1 << (U.row(F(t, 1)) - U.row(F(t, 0))).transpose(),
        (U.row(F(t, 2)) - U.row(F(t, 0))).transpose();
    const Eigen::Matrix2d J = D1 * D0.inverse();
    return std::atan2(J(1, 0) - J(0, 1), J(0, 0) + J(1, 1));
}

double wrapAngle(double a)
{
    return std::remainder(a, 2.0 * std::numbers::pi);
}

// A body (100 × 100) and a limb (200 × 40) meshed apart, the limb's left end 10 px over the
// body's right side, stacked (body first) with one hinge: the body's vertex nearest the middle
// of the overlap and the limb's nearest that.
struct HingedPieces {
    Eigen::MatrixX2d V;
    Eigen::MatrixX3i F;
    std::array<int, 2> hinge{};
    Eigen::Index limbFirstVertex = 0, limbFirstTriangle = 0;
    int limbTip = 0; // the limb's vertex at the middle of its far end

    HingedPieces()
    {
        const test::GridMesh body = test::gridMesh(10, 10, 100.0, 100.0);
        const test::GridMesh limb =
            test::gridMesh(20, 4, 200.0, 40.0, 0.0, Eigen::Vector2d(90.0, 30.0));
        V.resize(body.V.rows() + limb.V.rows(), 2);
        V << body.V, limb.V;
        F.resize(body.F.rows() + limb.F.rows(), 3);
        F << body.F, (limb.F.array() + int(body.V.rows())).matrix();
        limbFirstVertex = body.V.rows();
        limbFirstTriangle = body.F.rows();
        limbTip = int(limbFirstVertex) + limb.vertex(20, 2);
        Eigen::Index b = 0, l = 0;
        (body.V.rowwise() - Eigen::RowVector2d(95.0, 50.0)).rowwise().squaredNorm().minCoeff(&b);
        (limb.V.rowwise() - body.V.row(b)).rowwise().squaredNorm().minCoeff(&l);
        hinge = {int(b), int(limbFirstVertex + l)};
    }
    // The limb turned by `degrees` about its hinge vertex, the body unmoved.
    Eigen::MatrixX2d limbTurned(double degrees) const
    {
        Eigen::MatrixX2d U = V;
        const Eigen::Vector2d c = V.row(hinge[1]).transpose();
        const Eigen::Matrix2d R = test::rotationBy(degrees);
        for (Eigen::Index v = limbFirstVertex; v < V.rows(); ++v)
            U.row(v) = (R * (V.row(v).transpose() - c) + c).transpose();
        return U;
    }
};

} // namespace

class TestBetweenFit : public QObject {
    Q_OBJECT

private slots:
    void rigidMotionIsRecovered_data();
    void rigidMotionIsRecovered();
    void bentArmKeepsItsElbow();
    void farTurnedArmIsFoundWithTheSkeleton();
    void reversedShuffledStrokesGiveTheSameFit();
    void pinDisambiguatesAMirror();
    void movedPinRefits();
    void unfittableDrawingsFail();
    void degenerateTargetsStayFinite();
    void interpolationEndsAreExact();
    void turnedLimbKeepsItsLength();
    void curledLimbTurnsOneWay();
    void hingedPieceTurnsAboutItsHinge();
    void hingeHoldsAFittedPiece();
    void limbBeyondAFoldTurnsAsItTurned();
    void pointGridAnswersAsASearchOfEveryPoint();
};

void TestBetweenFit::rigidMotionIsRecovered_data()
{
    QTest::addColumn<double>("degrees");
    QTest::addColumn<double>("scale");
    QTest::newRow("rigid 35°") << 35.0 << 1.0;
    QTest::newRow("rigid 160°") << 160.0 << 1.0; // beyond what ICP alone turns back
    QTest::newRow("scaled 1.3, 35°") << 35.0 << 1.3;
}

void TestBetweenFit::rigidMotionIsRecovered()
{
    QFETCH(double, degrees);
    QFETCH(double, scale);
    const DrawingA a(40, 8, 300.0, 60.0, 5.0, true);
    QVERIFY(a.source);
    const Eigen::Matrix2d linear = scale * test::rotationBy(degrees);
    const Eigen::Vector2d shift(420.0, -130.0);
    const StrokePoints b = a.strokes.transformed(linear, shift);
    RigidFitOptions options;
    options.allowScale = scale != 1.0;
    const RigidFitResult fit = rigidFit(*a.source, *rigidFitTarget(b.P, b.N), {}, options);
    QCOMPARE(int(fit.status), int(FitStatus::Fitted));
    QVERIFY(fit.U.allFinite());
    const double error = maxRowDistance(fit.samples, b.P);
    QVERIFY2(error < 1e-3, qPrintable(QString::number(error)));
    QVERIFY(fit.converged);
    QVERIFY(fit.medianResidual < 1e-3);
    QVERIFY(std::abs(fit.scale - scale) < 1e-6);
    if (scale != 1.0) {
        // The ARAP stage fits the scale too: started from a fit made at A's own size, a refit
        // that allows scale finds it.
        RigidFitOptions rigid;
        rigid.allowScale = false;
        const RigidFitResult unscaled = rigidFit(*a.source, *rigidFitTarget(b.P, b.N), {}, rigid);
        options.refitIterations = 40;
        const RigidFitResult refit =
            rigidRefit(*a.source, *rigidFitTarget(b.P, b.N), {}, unscaled, options);
        QVERIFY2(std::abs(refit.scale - scale) < 0.02 * scale,
                 qPrintable(QString("%1 → %2").arg(unscaled.scale).arg(refit.scale)));
    }
}

void TestBetweenFit::bentArmKeepsItsElbow()
{
    const DrawingA a(60, 8, 300.0, 40.0, 4.0);
    QVERIFY(a.source);
    const test::ElbowBend bend{{150.0, 20.0}, 60.0};
    const StrokePoints b = bentArm(bend, 300.0, 40.0);
    const RigidFitResult fit = rigidFit(*a.source, *rigidFitTarget(b.P, b.N));
    QCOMPARE(int(fit.status), int(FitStatus::Fitted));
    QVERIFY(fit.U.allFinite());
    // The elbow (centre of the arm at mid-length) lands where it is in B.
    const geometry::Embedding elbow = geometry::embed(a.mesh.V, a.mesh.F, bend.elbow.transpose());
    const Eigen::Vector2d fittedElbow = geometry::applyEmbedding(elbow, fit.U, a.mesh.F).row(0);
    const double elbowError = (fittedElbow - bend.elbow).norm();
    QVERIFY2(elbowError < 0.02 * 300.0, qPrintable(QString::number(elbowError)));
    // Every sample away from the joint lands near where the bend took it. (Near it, the
    // inner side of A, longer than B's, where the two halves overlap, is squeezed into B's
    // crease over about an arm's width either side, as ARAP spreads a compression.)
    double worst = 0.0;
    for (Eigen::Index s = 0; s < a.strokes.P.rows(); ++s) {
        const Eigen::Vector2d p = a.strokes.P.row(s).transpose();
        if (std::abs(p.x() - bend.elbow.x()) > 60.0)
            worst = std::max(worst, (fit.samples.row(s).transpose() - bend.apply(p)).norm());
    }
    QVERIFY2(worst < 0.02 * 300.0, qPrintable(QString::number(worst)));
    // The upper arm is rigid, and in place: its vertices are a rigid motion of their rest
    // positions to within 1 % of the arm's length, and that motion is nearly the identity.
    std::vector<Eigen::Index> upper;
    for (Eigen::Index v = 0; v < a.mesh.V.rows(); ++v)
        if (a.mesh.V(v, 0) < 120.0)
            upper.push_back(v);
    Eigen::MatrixX2d rest(Eigen::Index(upper.size()), 2), moved(Eigen::Index(upper.size()), 2);
    for (std::size_t i = 0; i < upper.size(); ++i) {
        rest.row(Eigen::Index(i)) = a.mesh.V.row(upper[i]);
        moved.row(Eigen::Index(i)) = fit.U.row(upper[i]);
    }
    const Eigen::Matrix3d T = Eigen::umeyama(rest.transpose(), moved.transpose(), false);
    const Eigen::MatrixX2d rigid = (rest * T.topLeftCorner<2, 2>().transpose()).rowwise() +
                                   T.topRightCorner<2, 1>().transpose();
    const double nonRigid = maxRowDistance(rigid, moved);
    QVERIFY2(nonRigid < 0.01 * 300.0, qPrintable(QString::number(nonRigid)));
    QVERIFY(maxRowDistance(moved, rest) < 0.02 * 300.0);
}

// A forearm a third of the arm long, turned by 120°: from the whole-arm alignment (a
// compromise between the two halves) the ICP settles with the forearm on the upper arm's
// lines; with A's skeleton (shoulder, elbow, hand) the upper arm, the longest part, is placed
// first and the forearm turned about the elbow, and the fit lands.
void TestBetweenFit::farTurnedArmIsFoundWithTheSkeleton()
{
    const DrawingA a(60, 8, 300.0, 40.0, 4.0);
    QVERIFY(a.source);
    const test::ElbowBend bend{{200.0, 20.0}, 120.0};
    const StrokePoints b = bentArm(bend, 300.0, 40.0);
    const auto target = rigidFitTarget(b.P, b.N);
    const auto farError = [&](const RigidFitResult &fit) {
        double worst = 0.0;
        for (Eigen::Index s = 0; s < a.strokes.P.rows(); ++s) {
            const Eigen::Vector2d p = a.strokes.P.row(s).transpose();
            if (std::abs(p.x() - bend.elbow.x()) > 60.0)
                worst = std::max(worst, (fit.samples.row(s).transpose() - bend.apply(p)).norm());
        }
        return worst;
    };
    const RigidFitResult plain = rigidFit(*a.source, *target);
    FitSkeleton skeleton;
    skeleton.joints = {{0.0, 20.0}, {200.0, 20.0}, {300.0, 20.0}};
    skeleton.parent = {-1, 0, 1};
    const RigidFitResult jointed = rigidFit(*a.source, *target, {}, skeleton);
    qInfo("far samples: %.1f px off without the skeleton, %.1f px with it", farError(plain),
          farError(jointed));
    QCOMPARE(int(jointed.status), int(FitStatus::Fitted));
    QVERIFY2(farError(jointed) < 0.05 * 300.0, qPrintable(QString::number(farError(jointed))));
    QVERIFY(farError(jointed) < farError(plain));
    // A skeleton that is not one (a parent after its child, a NaN joint) is ignored.
    FitSkeleton bad = skeleton;
    bad.parent = {-1, 2, 1};
    QVERIFY(rigidFit(*a.source, *target, {}, bad).U.allFinite());
    bad = skeleton;
    bad.joints[1].x() = std::numeric_limits<double>::quiet_NaN();
    const RigidFitResult ignored = rigidFit(*a.source, *target, {}, bad);
    QVERIFY(ignored.U.allFinite());
}

void TestBetweenFit::reversedShuffledStrokesGiveTheSameFit()
{
    const DrawingA a(60, 8, 300.0, 40.0, 4.0);
    const test::ElbowBend bend{{150.0, 20.0}, 60.0};
    const StrokePoints b = bentArm(bend, 300.0, 40.0);
    // Reversed order, then shuffled, and every normal negated (strokes drawn the other way).
    std::vector<Eigen::Index> order(std::size_t(b.P.rows()));
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = Eigen::Index(order.size() - 1 - i);
    std::mt19937 random(7);
    std::shuffle(order.begin(), order.end(), random);
    StrokePoints c;
    for (const Eigen::Index i : order)
        c.add(b.P.row(i).transpose(), -b.N.row(i).transpose());
    const RigidFitResult first = rigidFit(*a.source, *rigidFitTarget(b.P, b.N));
    const RigidFitResult second = rigidFit(*a.source, *rigidFitTarget(c.P, c.N));
    QCOMPARE(int(second.status), int(first.status));
    const double difference = maxRowDistance(first.U, second.U);
    QVERIFY2(difference < 1e-6, qPrintable(QString::number(difference)));
}

void TestBetweenFit::pinDisambiguatesAMirror()
{
    // A rectangle's outline looks the same turned by half a turn: the coarse alignment cannot
    // tell 10° from 190° and takes the smaller turn. The truth is 190°; one pin says so.
    const DrawingA a(40, 12, 200.0, 60.0, 5.0);
    const Eigen::Vector2d centre(100.0, 30.0), shift(50.0, 80.0);
    const Eigen::Matrix2d R = test::rotationBy(190.0);
    const StrokePoints b = a.strokes.transformed(R, shift + centre - R * centre);
    const auto target = rigidFitTarget(b.P, b.N);
    const RigidFitResult unpinned = rigidFit(*a.source, *target);
    QCOMPARE(int(unpinned.status), int(FitStatus::Fitted)); // it fits B's outline, wrongly
    QVERIFY(maxRowDistance(unpinned.samples, b.P) > 100.0);

    const Eigen::VectorXi pinned = (Eigen::VectorXi(1) << 0).finished();
    const FitPins pins = pinsAtSamples(a.samples, pinned, b.P.row(0));
    const RigidFitResult fit = rigidFit(*a.source, *target, pins);
    QCOMPARE(int(fit.status), int(FitStatus::Fitted));
    const double error = maxRowDistance(fit.samples, b.P);
    QVERIFY2(error < 1e-3 * a.size(), qPrintable(QString::number(error)));
    QVERIFY((fit.samples.row(0) - b.P.row(0)).norm() < 1e-3 * a.size());
}

void TestBetweenFit::movedPinRefits()
{
    const DrawingA a(60, 8, 300.0, 40.0, 4.0);
    const test::ElbowBend bend{{150.0, 20.0}, 60.0};
    const StrokePoints b = bentArm(bend, 300.0, 40.0);
    const auto target = rigidFitTarget(b.P, b.N);
    const RigidFitResult fit = rigidFit(*a.source, *target);
    // Pin the forearm's far top corner 25 px further round than the fit put it.
    Eigen::Index corner = 0;
    for (Eigen::Index s = 0; s < a.strokes.P.rows(); ++s)
        if ((a.strokes.P.row(s) - Eigen::RowVector2d(300.0, 40.0)).norm() <
            (a.strokes.P.row(corner) - Eigen::RowVector2d(300.0, 40.0)).norm())
            corner = s;
    const Eigen::RowVector2d goal = fit.samples.row(corner) + Eigen::RowVector2d(-25.0, 0.0);
    const FitPins pins =
        pinsAtSamples(a.samples, (Eigen::VectorXi(1) << int(corner)).finished(), goal);
    const RigidFitResult refit = rigidRefit(*a.source, *target, pins, fit);
    QVERIFY(refit.U.allFinite());
    const double before = (fit.samples.row(corner) - goal).norm();
    const double after = (refit.samples.row(corner) - goal).norm();
    QVERIFY2(after < 0.2 * before, qPrintable(QString("%1 → %2").arg(before).arg(after)));
    // The upper arm, far from the pin, stays where it was.
    for (Eigen::Index v = 0; v < a.mesh.V.rows(); ++v)
        if (a.mesh.V(v, 0) < 60.0)
            QVERIFY((refit.U.row(v) - fit.U.row(v)).norm() < 0.01 * 300.0);
}

void TestBetweenFit::unfittableDrawingsFail()
{
    const DrawingA a(60, 8, 300.0, 40.0, 4.0);
    // B: a large ring far away, nothing like an arm.
    StrokePoints ring;
    for (int i = 0; i < 400; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / 400.0;
        const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
        ring.add(Eigen::Vector2d(3000.0, 2000.0) + 500.0 * direction, direction);
    }
    const RigidFitResult fit = rigidFit(*a.source, *rigidFitTarget(ring.P, ring.N));
    QCOMPARE(int(fit.status), int(FitStatus::ResidualTooLarge));
    QVERIFY(fit.U.allFinite() && fit.samples.allFinite());
    QVERIFY(!fit.worstSamples.empty());
    QVERIFY(!fit.worstRegion.isEmpty());
    QVERIFY(!fit.message.empty());
    QVERIFY(fit.distortion > 0.25 || fit.relativeMedian > 0.05 ||
            fit.coverageMedian > 0.05 * fit.targetDiagonal);

    // B: A as it is, and beside it more again of something A has no part for. The fit
    // stretches A towards both (distortion). Pinned in place and without B→A pairs, A fits
    // its part exactly, and the uncovered part of B is what fails it.
    StrokePoints more = a.strokes;
    const int extra = int(a.strokes.P.rows()) * 3 / 2;
    for (int i = 0; i < extra; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / double(extra);
        const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
        more.add(Eigen::Vector2d(150.0, 300.0) + 120.0 * direction, direction);
    }
    const auto moreTarget = rigidFitTarget(more.P, more.N);
    const RigidFitResult partial = rigidFit(*a.source, *moreTarget);
    QCOMPARE(int(partial.status), int(FitStatus::ResidualTooLarge));
    QVERIFY(partial.U.allFinite());
    RigidFitOptions oneWay;
    oneWay.symmetric = false;
    const Eigen::VectorXi onA = (Eigen::VectorXi(2) << 0, int(a.strokes.P.rows()) / 2).finished();
    const FitPins inPlace = pinsAtSamples(
        a.samples, onA,
        (Eigen::MatrixX2d(2, 2) << a.strokes.P.row(onA(0)), a.strokes.P.row(onA(1))).finished());
    const RigidFitResult uncovered = rigidFit(*a.source, *moreTarget, inPlace, oneWay);
    QCOMPARE(int(uncovered.status), int(FitStatus::ResidualTooLarge));
    QVERIFY(uncovered.relativeMedian < 0.01 && uncovered.distortion < 0.01); // A itself fits
    QVERIFY(uncovered.U.allFinite());

    const RigidFitResult empty =
        rigidFit(*a.source, *rigidFitTarget(Eigen::MatrixX2d(0, 2), Eigen::MatrixX2d(0, 2)));
    QCOMPARE(int(empty.status), int(FitStatus::EmptyTarget));
    QVERIFY(empty.U.allFinite());
    QCOMPARE(empty.U, a.mesh.V);
}

void TestBetweenFit::degenerateTargetsStayFinite()
{
    const DrawingA a(30, 6, 300.0, 60.0, 6.0);
    StrokePoints point, line, repeated;
    point.add({10.0, 20.0}, {0.0, 1.0});
    for (int i = 0; i < 50; ++i)
        line.add({5.0 * i, 2.0 * i}, {-2.0, 5.0});
    for (int i = 0; i < 20; ++i)
        repeated.add({7.0, 7.0}, {1.0, 0.0});
    Eigen::MatrixX2d withNaN = line.P;
    withNaN(3, 0) = std::numeric_limits<double>::quiet_NaN();
    for (const auto &[P, N] : {std::pair(point.P, point.N), std::pair(line.P, line.N),
                               std::pair(repeated.P, repeated.N), std::pair(withNaN, line.N)}) {
        const RigidFitResult fit = rigidFit(*a.source, *rigidFitTarget(P, N));
        QVERIFY(fit.U.allFinite() && fit.samples.allFinite() && fit.residual.allFinite());
        QVERIFY(std::isfinite(fit.medianResidual) && std::isfinite(fit.p95Residual));
    }
}

void TestBetweenFit::interpolationEndsAreExact()
{
    const test::GridMesh mesh = test::gridMesh(30, 6, 300.0, 40.0, 0.15);
    const test::ElbowBend bend{{150.0, 20.0}, 75.0};
    Eigen::MatrixX2d V1(mesh.V.rows(), 2);
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) // a bend blended over the joint, + a shift
        V1.row(v) = bend.apply(mesh.V.row(v).transpose()).transpose() * 1.1 +
                    Eigen::RowVector2d(30.0, -12.0);
    const auto data = arapInterpolationPrecompute(mesh.V, V1, mesh.F);
    QVERIFY(data);
    const auto start = arapInterpolate(**data, 0.0), end = arapInterpolate(**data, 1.0);
    QVERIFY(start && end);
    QVERIFY2(maxRowDistance(*start, mesh.V) < 1e-9 * mesh.size(),
             qPrintable(QString::number(maxRowDistance(*start, mesh.V))));
    QVERIFY2(maxRowDistance(*end, V1) < 1e-9 * mesh.size(),
             qPrintable(QString::number(maxRowDistance(*end, V1))));
    const auto middle = arapInterpolate(**data, 0.5);
    QVERIFY(middle && middle->allFinite());
    QVERIFY(maxRowDistance(*middle, mesh.V) > 1.0 && maxRowDistance(*middle, V1) > 1.0);
}

void TestBetweenFit::turnedLimbKeepsItsLength()
{
    // A body (x < 60) and a limb (x > 140) turned by 170°, the turn bent over the joint between.
    const test::GridMesh mesh = test::gridMesh(60, 8, 300.0, 40.0);
    const test::StripCurl joint{60.0, 80.0, 170.0};
    Eigen::MatrixX2d V1(mesh.V.rows(), 2);
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
        V1.row(v) = joint.apply(mesh.V.row(v).transpose()).transpose();
    const auto data = arapInterpolationPrecompute(mesh.V, V1, mesh.F);
    QVERIFY(data);
    const auto middle = arapInterpolate(**data, 0.5);
    QVERIFY(middle);
    const int from = mesh.vertex(28, 4), tip = mesh.vertex(60, 4); // x = 140 and x = 300
    const double rest = (mesh.V.row(tip) - mesh.V.row(from)).norm();
    const double arap = ((*middle).row(tip) - (*middle).row(from)).norm();
    const Eigen::MatrixX2d blend = 0.5 * (mesh.V + V1);
    const double linear = (blend.row(tip) - blend.row(from)).norm();
    QVERIFY2(std::abs(arap / rest - 1.0) < 0.01, qPrintable(QString::number(arap / rest)));
    QVERIFY(linear < 0.5 * rest); // what the naive blend does to it
    // Every triangle turns the same way: the body not at all, the limb by half of 170°.
    for (Eigen::Index t = 0; t < mesh.F.rows(); ++t) {
        const double angle =
            triangleRotation(mesh.V, *middle, mesh.F, t) * 180.0 / std::numbers::pi;
        QVERIFY2(angle > -3.0 && angle < 88.0, qPrintable(QString::number(angle)));
        if (mesh.V(mesh.F(t, 0), 0) > 150.0)
            QVERIFY2(std::abs(angle - 85.0) < 1.0, qPrintable(QString::number(angle)));
    }
}

void TestBetweenFit::curledLimbTurnsOneWay()
{
    // A tail curled by 240° from x = 100 to its tip: its triangles turn by up to 240°, past the
    // half turn where an angle taken in (−180°, 180°] would flip to the other way round.
    const test::GridMesh mesh = test::gridMesh(60, 8, 300.0, 40.0);
    const test::StripCurl curl{100.0, 200.0, 240.0};
    Eigen::MatrixX2d V1(mesh.V.rows(), 2);
    for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
        V1.row(v) = curl.apply(mesh.V.row(v).transpose()).transpose();
    const auto data = arapInterpolationPrecompute(mesh.V, V1, mesh.F);
    QVERIFY(data);
    const auto middle = arapInterpolate(**data, 0.5);
    QVERIFY(middle);
    for (Eigen::Index t = 0; t < mesh.F.rows(); ++t) {
        const double x =
            (mesh.V(mesh.F(t, 0), 0) + mesh.V(mesh.F(t, 1), 0) + mesh.V(mesh.F(t, 2), 0)) / 3.0;
        const double expected = 0.5 * curl.angleAt(x);
        QVERIFY2(std::abs((*data)->angle(t) - curl.angleAt(x)) < 0.1,
                 qPrintable(QString("%1 %2").arg((*data)->angle(t)).arg(curl.angleAt(x))));
        const double got = triangleRotation(mesh.V, *middle, mesh.F, t);
        QVERIFY2(std::abs(wrapAngle(got - expected)) < 15.0 * std::numbers::pi / 180.0,
                 qPrintable(QString("triangle %1: %2° for %3°")
                                .arg(t)
                                .arg(got * 180.0 / std::numbers::pi)
                                .arg(expected * 180.0 / std::numbers::pi)));
    }
}

void TestBetweenFit::limbBeyondAFoldTurnsAsItTurned()
{
    // A limb (x ≥ 110) turned by 40° about the joint at x = 105, where the fitted pose folded:
    // the joint's column of vertices lies scattered behind the body's edge, so the triangles
    // on either side of it are turned over or torn, with angles that are noise. Whatever the
    // noise, the limb turns by 40°, and halfway by 20° with its length kept.
    const Eigen::Vector2d pivot(105.0, 20.0);
    const Eigen::Matrix2d turn = Eigen::Rotation2Dd(40.0 * std::numbers::pi / 180.0).matrix();
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const test::GridMesh mesh = test::gridMesh(60, 8, 300.0, 40.0);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> scatter(-6.0, 6.0);
        Eigen::MatrixX2d V1 = mesh.V;
        for (int r = 0; r <= mesh.rows; ++r) {
            for (int c = 22; c <= mesh.columns; ++c) {
                const int v = mesh.vertex(c, r);
                V1.row(v) = (pivot + turn * (mesh.V.row(v).transpose() - pivot)).transpose();
            }
            const int fold = mesh.vertex(21, r);
            V1.row(fold) << 92.0 + scatter(rng), mesh.V(fold, 1) + scatter(rng);
        }
        const auto data = arapInterpolationPrecompute(mesh.V, V1, mesh.F);
        QVERIFY(data);
        QVERIFY((*data)->flippedTriangles > 0);
        const auto middle = arapInterpolate(**data, 0.5);
        QVERIFY(middle);
        for (Eigen::Index t = 0; t < mesh.F.rows(); ++t) {
            if (mesh.V(mesh.F(t, 0), 0) < 115.0 || mesh.V(mesh.F(t, 1), 0) < 115.0 ||
                mesh.V(mesh.F(t, 2), 0) < 115.0)
                continue;
            QVERIFY2(std::abs((*data)->angle(t) - 40.0 * std::numbers::pi / 180.0) < 1e-6,
                     qPrintable(QString("seed %1, triangle %2: %3°")
                                    .arg(seed)
                                    .arg(t)
                                    .arg((*data)->angle(t) * 180.0 / std::numbers::pi)));
        }
        const int from = mesh.vertex(24, 4), tip = mesh.vertex(60, 4); // x = 120 and x = 300
        const double rest = (mesh.V.row(tip) - mesh.V.row(from)).norm();
        const double half = ((*middle).row(tip) - (*middle).row(from)).norm();
        QVERIFY2(std::abs(half / rest - 1.0) < 0.02,
                 qPrintable(QString("seed %1: %2").arg(seed).arg(half / rest)));
        const Eigen::Vector2d along = ((*middle).row(tip) - (*middle).row(from)).transpose();
        const double degrees = std::atan2(along.y(), along.x()) * 180.0 / std::numbers::pi;
        QVERIFY2(std::abs(degrees - 20.0) < 5.0,
                 qPrintable(QString("seed %1: %2°").arg(seed).arg(degrees)));
    }
}

// The fit's nearest-point grid answers exactly as looking at every point would (the same row,
// ties to the lower, the same distance), for points along curves as drawings have them (sparse
// ones on the coarse cells, dense ones on the fine cells too), with and without the normal
// filter, from inside and far outside the grid, with no normals, and bounded by a reach.
void TestBetweenFit::pointGridAnswersAsASearchOfEveryPoint()
{
    std::mt19937 rng(20261207u);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int round = 0; round < 6; ++round) {
        // Points along a few wavy lines, some repeated (ties), as a drawing's samples lie.
        const int k = 200 + 300 * round;
        Eigen::MatrixX2d P(k, 2), N(k, 2);
        for (int i = 0; i < k; ++i) {
            const double t = unit(rng) * 6.0, line = double(i % 5);
            P.row(i) << 40.0 * t + 3.0 * line, 60.0 * line + 20.0 * std::sin(t * (1.0 + line));
            if (i % 17 == 3 && i > 0)
                P.row(i) = P.row(i - 1); // a point drawn twice
            const double a = unit(rng) * 2.0 * std::numbers::pi;
            N.row(i) << std::cos(a), std::sin(a);
        }
        const detail::PointGrid grid(P, N), plain(P, Eigen::MatrixX2d());
        const Eigen::Vector2d lo = P.colwise().minCoeff(), hi = P.colwise().maxCoeff();
        for (int query = 0; query < 400; ++query) {
            // Inside the box, then up to twice its size away from it.
            const double reach = query < 300 ? 1.0 : 5.0;
            const Eigen::Vector2d q(
                lo.x() + (unit(rng) * reach - (reach - 1.0) / 2.0) * (hi.x() - lo.x()),
                lo.y() + (unit(rng) * reach - (reach - 1.0) / 2.0) * (hi.y() - lo.y()));
            const double a = unit(rng) * 2.0 * std::numbers::pi;
            const Eigen::Vector2d normal(std::cos(a), std::sin(a));
            for (const double agreement : {0.0, 0.5, 0.95}) {
                int expected = -1;
                double expectedSquared = std::numeric_limits<double>::infinity();
                for (int i = 0; i < k; ++i) {
                    if (agreement > 0.0 && std::abs(N.row(i).dot(normal)) < agreement)
                        continue;
                    const double d = (P.row(i).transpose() - q).squaredNorm();
                    if (d < expectedSquared) { // the lower row on a tie
                        expectedSquared = d;
                        expected = i;
                    }
                }
                double distance = -1.0;
                QCOMPARE(grid.nearest(q, normal, agreement, distance), expected);
                QCOMPARE(distance, std::sqrt(expectedSquared));
                if (agreement == 0.0) {
                    QCOMPARE(plain.nearest(q, normal, 0.9, distance), expected);
                    QCOMPARE(distance, std::sqrt(expectedSquared));
                }
                // A bounded search: the same point when it lies within reach, none beyond.
                const double within = unit(rng) * 2.0 * std::sqrt(expectedSquared);
                const bool reached = expected >= 0 && std::sqrt(expectedSquared) <= within;
                QCOMPARE(grid.nearest(q, normal, agreement, distance, within),
                         reached ? expected : -1);
                QCOMPARE(distance, reached ? std::sqrt(expectedSquared)
                                           : std::numeric_limits<double>::infinity());
            }
        }
    }
}

void TestBetweenFit::hingedPieceTurnsAboutItsHinge()
{
    // A limb meshed apart from the body (drawn over it) and turned 120° about its hinge: with
    // the hinge linked, the in-between turns it about the hinge, which stays where it is; each
    // part's centroid moved on its own straight line instead swings the limb's root off the
    // body (what the interpolation did with no link).
    const HingedPieces pieces;
    const Eigen::MatrixX2d V1 = pieces.limbTurned(120.0);
    const auto linked = arapInterpolationPrecompute(pieces.V, V1, pieces.F, {pieces.hinge});
    const auto apart = arapInterpolationPrecompute(pieces.V, V1, pieces.F);
    QVERIFY(linked && apart);
    const double size = (pieces.V.colwise().maxCoeff() - pieces.V.colwise().minCoeff()).norm();
    const auto start = arapInterpolate(**linked, 0.0), end = arapInterpolate(**linked, 1.0);
    QVERIFY(start && end);
    QVERIFY(maxRowDistance(*start, pieces.V) < 1e-9 * size);
    QVERIFY(maxRowDistance(*end, V1) < 1e-9 * size);
    const auto middle = arapInterpolate(**linked, 0.5), loose = arapInterpolate(**apart, 0.5);
    QVERIFY(middle && loose);
    const auto [b, l] = pieces.hinge;
    const Eigen::RowVector2d rest = pieces.V.row(l);
    QVERIFY2(((*middle).row(l) - rest).norm() < 0.5,
             qPrintable(QString::number(((*middle).row(l) - rest).norm())));
    QVERIFY(((*middle).row(b) - pieces.V.row(b)).norm() < 0.5);
    const double length = (pieces.V.row(pieces.limbTip) - rest).norm();
    const Eigen::RowVector2d reach = (*middle).row(pieces.limbTip) - (*middle).row(l);
    QVERIFY2(std::abs(reach.norm() / length - 1.0) < 0.01,
             qPrintable(QString::number(reach.norm() / length)));
    const Eigen::RowVector2d restReach = pieces.V.row(pieces.limbTip) - rest;
    const double turned =
        std::atan2(restReach.x() * reach.y() - restReach.y() * reach.x(), restReach.dot(reach));
    QVERIFY2(std::abs(turned * 180.0 / std::numbers::pi - 60.0) < 1.0,
             qPrintable(QString::number(turned * 180.0 / std::numbers::pi)));
    // Without the link the limb's root leaves the body (its centroid takes the chord).
    QVERIFY2(((*loose).row(l) - rest).norm() > 20.0,
             qPrintable(QString::number(((*loose).row(l) - rest).norm())));
    // A link to a vertex that does not exist is refused, not read out of range.
    QVERIFY(!arapInterpolationPrecompute(pieces.V, V1, pieces.F, {{0, int(pieces.V.rows())}}));
}

void TestBetweenFit::hingeHoldsAFittedPiece()
{
    // B: the body's outline, and the limb turned 25° about the hinge, drawn as its two long
    // sides only (no end drawn): nothing in B says how far along itself the limb lies, so a
    // limb meshed apart slides along its sides unless the hinge holds it on the body.
    const HingedPieces pieces;
    StrokePoints a;
    a.addRectangle({0.0, 0.0}, {100.0, 100.0}, 2.0);
    a.addRectangle({90.0, 30.0}, {290.0, 70.0}, 2.0);
    const geometry::Embedding samples = geometry::embed(pieces.V, pieces.F, a.P);
    // Each point of the limb's outline in the limb's mesh (the body's takes the overlap).
    geometry::Embedding own = samples;
    const Eigen::MatrixX3i limbF = pieces.F.bottomRows(pieces.F.rows() - pieces.limbFirstTriangle);
    const geometry::Embedding inLimb =
        geometry::embed(pieces.V, limbF, a.P.bottomRows(a.P.rows() / 2));
    for (Eigen::Index i = 0; i < inLimb.I.size(); ++i) {
        own.I(a.P.rows() / 2 + i) = inLimb.I(i) + int(pieces.limbFirstTriangle);
        own.B.row(a.P.rows() / 2 + i) = inLimb.B.row(i);
    }
    const auto source = rigidFitPrecompute(pieces.V, pieces.F, own, a.N, {pieces.hinge});
    QVERIFY(source);
    QVERIFY(!rigidFitPrecompute(pieces.V, pieces.F, own, a.N, {{-1, 0}}));
    const Eigen::MatrixX2d U1 = pieces.limbTurned(25.0);
    const Eigen::MatrixX2d onB = geometry::applyEmbedding(own, U1, pieces.F);
    StrokePoints b;
    for (Eigen::Index i = 0; i < onB.rows(); ++i) {
        const Eigen::Vector2d p = a.P.row(i).transpose();
        const bool limbEnd = i >= a.P.rows() / 2 && (p.x() < 140.0 || p.x() > 250.0);
        if (!limbEnd)
            b.add(onB.row(i).transpose(), a.N.row(i).transpose());
    }
    const RigidFitResult fit = rigidFit(**source, *rigidFitTarget(b.P, b.N));
    QCOMPARE(fit.status, FitStatus::Fitted);
    const auto [body, limb] = pieces.hinge;
    QVERIFY2((fit.U.row(body) - fit.U.row(limb)).norm() < 1.0,
             qPrintable(QString::number((fit.U.row(body) - fit.U.row(limb)).norm())));
    // The limb lies on B's sides, turned as B's: a vertex of its side half way along lies on
    // B's side line (along it, the missing ends leave the limb a little short).
    const Eigen::Index side = pieces.limbFirstVertex + 11; // limb grid vertex (11, 0): x = 200
    const Eigen::Vector2d along = test::rotationBy(25.0) * Eigen::Vector2d(1.0, 0.0);
    const Eigen::Vector2d off = (fit.U.row(side) - U1.row(side)).transpose();
    const double across = std::abs(off.x() * along.y() - off.y() * along.x());
    QVERIFY2(across < 1.5, qPrintable(QString::number(across)));
}

QTEST_APPLESS_MAIN(TestBetweenFit)
#include "tst_between_fit.moc"
