// Cut-out joints (issue 21): where the mesh is cut, the pieces it makes, and that a piece
// cut off at its joint turns rigidly with its bone while the rest stays put.
#include "arm_mesh.h"
#include "grid_mesh.h"

#include <finbook/deform/skeleton/cut_out.h>
#include <finbook/deform/skeleton/rigid_skinning.h>
#include <finbook/deform/skeleton/skeleton.h>
#include <finbook/deform/skeleton/skinning_weights.h>

#include <QTest>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>

using namespace finbook::deform;
using finbook::test::Arm;
using finbook::test::gridMesh;

namespace {

// Keeps the triangles `keep` accepts (by centroid) and drops the vertices left unused.
void keepTriangles(Eigen::MatrixX2d &V, Eigen::MatrixX3i &F,
                   const std::function<bool(const Eigen::Vector2d &)> &keep)
{
    std::vector<int> index(std::size_t(V.rows()), -1);
    std::vector<Eigen::RowVector3i> kept;
    for (Eigen::Index t = 0; t < F.rows(); ++t) {
        const Eigen::Vector2d c =
            (V.row(F(t, 0)) + V.row(F(t, 1)) + V.row(F(t, 2))).transpose() / 3;
        if (keep(c))
            kept.push_back(F.row(t));
    }
    Eigen::MatrixX2d newV(V.rows(), 2);
    int n = 0;
    Eigen::MatrixX3i newF(Eigen::Index(kept.size()), 3);
    for (std::size_t t = 0; t < kept.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            int &i = index[std::size_t(kept[t](k))];
            if (i < 0) {
                i = n++;
                newV.row(i) = V.row(kept[t](k));
            }
            newF(Eigen::Index(t), k) = i;
        }
    }
    V = newV.topRows(n);
    F = newF;
}

Eigen::Vector2d centroid(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, Eigen::Index t)
{
    return (V.row(F(t, 0)) + V.row(F(t, 1)) + V.row(F(t, 2))).transpose() / 3.0;
}

double signedArea(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F, Eigen::Index t)
{
    const Eigen::RowVector2d a = V.row(F(t, 1)) - V.row(F(t, 0)),
                             b = V.row(F(t, 2)) - V.row(F(t, 0));
    return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

// A columns × rows grid over width × height, its inner vertices jittered by `seed` (a fifth
// of a cell at most), keeping the triangles `keep` accepts.
finbook::test::GridMesh jitteredShape(int columns, int rows, double width, double height,
                                      unsigned seed,
                                      const std::function<bool(const Eigen::Vector2d &)> &keep)
{
    finbook::test::GridMesh shape =
        gridMesh(columns, rows, width, height, 0.2, Eigen::Vector2d::Zero(), seed);
    keepTriangles(shape.V, shape.F, keep);
    return shape;
}

// The mesh cut for a root (joint 0) with two limbs of one bone hanging from it, 1–2 and 3–4:
// joints as x, y pairs, and their radii.
auto cutTwoLimbs(const finbook::test::GridMesh &mesh, const std::array<double, 10> &xy,
                 const std::array<double, 5> &radii)
{
    const Skeleton skeleton =
        *makeSkeleton(Eigen::Map<const Eigen::Matrix<double, 5, 2, Eigen::RowMajor>>(xy.data()),
                      (Eigen::VectorXi(5) << -1, 0, 1, 0, 3).finished());
    return cutAtJoints(mesh.V, mesh.F, skeleton,
                       Eigen::Map<const Eigen::VectorXd>(radii.data(), 5));
}

// The cut mesh skinned as the Cut-out mode skins it (weights from the uncut mesh), with the
// bone ending at `joint` turned by `angle` radians: the posed skeleton and the vertices, or
// nothing if a step failed.
struct Turned {
    PosedSkeleton posed;
    Eigen::MatrixX2d U;
};
std::optional<Turned> turnCut(const finbook::test::GridMesh &mesh, const Skeleton &skeleton,
                              const Eigen::VectorXd &radius, const CutMesh &cut, int joint,
                              double angle)
{
    const auto weights = computeSkinningWeights(mesh.V, mesh.F, skeleton);
    if (!weights)
        return std::nullopt;
    const auto rigid = rigidSkinPrecompute(
        cut.V, cut.F,
        withJointZones(cutOutWeights(**weights, skeleton, cut), cut.V, skeleton, radius));
    SkeletonPose pose = restPose(skeleton);
    pose.angles(joint) = angle;
    auto posed = forwardKinematics(skeleton, pose);
    if (!rigid || !posed)
        return std::nullopt;
    Turned out{std::move(*posed), cut.V};
    if (!rigidSkinSolve(**rigid, out.posed, out.U))
        return std::nullopt;
    return out;
}

// A plus sign 40 wide in a `width` × `height` grid, its bars crossing at (150, 150).
finbook::test::GridMesh plusSign(double height)
{
    finbook::test::GridMesh plus = gridMesh(60, int(height / 5.0), 300.0, height, 0.0);
    keepTriangles(plus.V, plus.F, [](const Eigen::Vector2d &c) {
        return std::abs(c.x() - 150.0) < 20.0 || std::abs(c.y() - 150.0) < 20.0;
    });
    return plus;
}

} // namespace

class TestCutOut : public QObject {
    Q_OBJECT
private slots:
    void anArmIsCutAtItsElbow()
    {
        const Arm arm;
        const auto cut = cutAtJoints(arm.mesh.V, arm.mesh.F, arm.skeleton, arm.radius);
        QVERIFY(cut.hasValue());
        QCOMPARE(int(cut->cuts.size()), 1);
        QCOMPARE(cut->cuts[0].joint, 1);
        // The cut crosses the bar at the elbow, from one side to the other.
        QVERIFY(std::abs(cut->cuts[0].a.x() - 150.0) < 8.0);
        QVERIFY(std::abs(cut->cuts[0].b.x() - 150.0) < 8.0);
        QVERIFY(std::abs(cut->cuts[0].a.y() - cut->cuts[0].b.y()) > 39.0);
        // Same triangles in the same order, on the same points.
        QCOMPARE(cut->F.rows(), arm.mesh.F.rows());
        QVERIFY(cut->V.rows() > arm.mesh.V.rows());
        QVERIFY(cut->V.topRows(arm.mesh.V.rows()) == arm.mesh.V);
        for (Eigen::Index v = 0; v < cut->V.rows(); ++v)
            QVERIFY(cut->V.row(v) == arm.mesh.V.row(cut->source(v)));
        for (Eigen::Index t = 0; t < cut->F.rows(); ++t) {
            for (int k = 0; k < 3; ++k)
                QCOMPARE(cut->source(cut->F(t, k)), arm.mesh.F(t, k));
            // The forearm is the cut's piece; the upper arm the roots'.
            const double x = centroid(arm.mesh.V, arm.mesh.F, t).x();
            if (x > 156.0)
                QCOMPARE(cut->piece(t), 0);
            if (x < 144.0)
                QCOMPARE(cut->piece(t), -1);
        }
        // No vertex is shared by two pieces: each copy belongs to one.
        std::map<int, int> pieceOf;
        for (Eigen::Index t = 0; t < cut->F.rows(); ++t)
            for (int k = 0; k < 3; ++k) {
                const auto [it, fresh] = pieceOf.emplace(cut->F(t, k), cut->piece(t));
                QVERIFY(fresh || it->second == cut->piece(t));
            }
        // The forearm's outline: one loop of its own vertices, round its triangles.
        QCOMPARE(int(cut->outlines.size()), 1);
        QCOMPARE(int(cut->outlines[0].size()), 1);
        const std::vector<int> &loop = cut->outlines[0][0];
        double area = 0.0, pieceArea = 0.0;
        for (std::size_t i = 0; i < loop.size(); ++i) {
            QCOMPARE(pieceOf.at(loop[i]), 0);
            const Eigen::RowVector2d p = cut->V.row(loop[i]);
            const Eigen::RowVector2d q = cut->V.row(loop[(i + 1) % loop.size()]);
            area += 0.5 * (p.x() * q.y() - q.x() * p.y());
        }
        for (Eigen::Index t = 0; t < cut->F.rows(); ++t)
            if (cut->piece(t) == 0)
                pieceArea += signedArea(cut->V, cut->F, t);
        QVERIFY(std::abs(area - pieceArea) < 1e-6 * std::abs(pieceArea));
        const Eigen::VectorXi bones = bonePieces(arm.skeleton, *cut);
        QCOMPARE(bones(1), -1);
        QCOMPARE(bones(2), 0);
        QCOMPARE(cut->cuts[0].child, 2);
        QCOMPARE(cut->parentPiece, std::vector<int>{-1});
        // The round end: the elbow's distance to the bar's sides (jittered a little).
        QVERIFY2(std::abs(cut->cuts[0].round - 20.0) < 2.0,
                 qPrintable(QString::number(cut->cuts[0].round)));
    }

    void aJointInTheMiddleOfAWideShapeIsNotCut()
    {
        // The same bones in a 300 × 200 slab: the outline lies five radii from the elbow.
        Arm arm;
        arm.mesh = gridMesh(30, 20, 300.0, 200.0, 0.1, Eigen::Vector2d(0.0, -80.0));
        const auto cut = cutAtJoints(arm.mesh.V, arm.mesh.F, arm.skeleton, arm.radius);
        QVERIFY(cut.hasValue());
        QVERIFY(cut->cuts.empty());
        QVERIFY(cut->V == arm.mesh.V);
        QVERIFY(cut->F == arm.mesh.F);
        QVERIFY((cut->piece.array() == -1).all());
    }

    void aCutThatDoesNotSeparateIsNotMade()
    {
        // A square ring 40 wide: a cut across its left side leaves the piece below joined to
        // the one above round the other three sides.
        finbook::test::GridMesh ring = gridMesh(60, 60, 300.0, 300.0, 0.0);
        keepTriangles(ring.V, ring.F, [](const Eigen::Vector2d &c) {
            return !(c.x() > 40 && c.x() < 260 && c.y() > 40 && c.y() < 260);
        });
        Eigen::MatrixX2d joints(3, 2);
        joints << 20.0, 280.0, 20.0, 150.0, 20.0, 20.0;
        const Skeleton skeleton = *makeSkeleton(joints, Eigen::Vector3i(-1, 0, 1));
        const auto cut = cutAtJoints(ring.V, ring.F, skeleton, Eigen::Vector3d(20, 20, 20));
        QVERIFY(cut.hasValue());
        QVERIFY(cut->cuts.empty());
    }

    void aCutPieceTurnsRigidlyAndTheRestStays()
    {
        const Arm arm;
        const auto cut = cutAtJoints(arm.mesh.V, arm.mesh.F, arm.skeleton, arm.radius);
        QVERIFY(cut.hasValue());
        const auto weights = computeSkinningWeights(arm.mesh.V, arm.mesh.F, arm.skeleton);
        QVERIFY(weights.hasValue());
        const SkinningWeights pieces = cutOutWeights(**weights, arm.skeleton, *cut);
        QCOMPARE(pieces.W.rows(), cut->V.rows());
        for (Eigen::Index v = 0; v < pieces.W.rows(); ++v)
            QVERIFY(std::abs(pieces.W.row(v).sum() - 1.0) < 1e-9);
        const auto rigid = rigidSkinPrecompute(
            cut->V, cut->F, withJointZones(pieces, cut->V, arm.skeleton, arm.radius));
        QVERIFY(rigid.hasValue());
        for (const double degrees : {60.0, -100.0}) {
            SkeletonPose pose = restPose(arm.skeleton);
            pose.angles(2) = degrees * M_PI / 180.0;
            const auto posed = forwardKinematics(arm.skeleton, pose);
            QVERIFY(posed.hasValue());
            Eigen::MatrixX2d U = cut->V;
            QVERIFY(rigidSkinSolve(**rigid, *posed, U).hasValue());
            // Vertex pieces from their triangles.
            Eigen::VectorXi piece = Eigen::VectorXi::Constant(U.rows(), -1);
            for (Eigen::Index t = 0; t < cut->F.rows(); ++t)
                for (int k = 0; k < 3; ++k)
                    piece(cut->F(t, k)) = cut->piece(t);
            double worst = 0.0;
            for (Eigen::Index v = 0; v < U.rows(); ++v) {
                const Eigen::Vector2d rest = cut->V.row(v).transpose();
                const Eigen::Vector2d expected =
                    piece(v) == 0 ? transformPoint(posed->transforms[2], rest) : rest;
                worst = std::max(worst, (U.row(v).transpose() - expected).norm());
            }
            QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
            for (Eigen::Index t = 0; t < cut->F.rows(); ++t)
                QVERIFY(signedArea(U, cut->F, t) * signedArea(cut->V, cut->F, t) > 0.0);
        }
    }

    void aPlusSignsLimbsAreCutAtItsJunction()
    {
        // Hung from the bottom bar's end: the junction's three limbs are cut there, each
        // between its bar and the neighbouring ones (at the plus's inner corners).
        const finbook::test::GridMesh plus = plusSign(300.0);
        Eigen::MatrixX2d joints(5, 2);
        joints << 150.0, 300.0, 150.0, 150.0, 0.0, 150.0, 300.0, 150.0, 150.0, 0.0;
        const Skeleton skeleton =
            *makeSkeleton(joints, (Eigen::VectorXi(5) << -1, 0, 1, 1, 1).finished());
        const double r = 20.0 * std::sqrt(2.0);
        const Eigen::VectorXd radius = (Eigen::VectorXd(5) << 20.0, r, 20.0, 20.0, 20.0).finished();
        const auto cut = cutAtJoints(plus.V, plus.F, skeleton, radius);
        QVERIFY(cut.hasValue());
        QCOMPARE(int(cut->cuts.size()), 3);
        std::map<int, int> pieceOfChild;
        for (std::size_t c = 0; c < cut->cuts.size(); ++c) {
            QCOMPARE(cut->cuts[c].joint, 1);
            pieceOfChild[cut->cuts[c].child] = int(c);
            // Both ends at inner corners of the plus.
            for (const Eigen::Vector2d &end : {cut->cuts[c].a, cut->cuts[c].b}) {
                QVERIFY(std::abs(std::abs(end.x() - 150.0) - 20.0) < 1e-3);
                QVERIFY(std::abs(std::abs(end.y() - 150.0) - 20.0) < 1e-3);
            }
        }
        QCOMPARE(int(pieceOfChild.size()), 3);
        const Eigen::VectorXi bones = bonePieces(skeleton, *cut);
        QCOMPARE(bones(1), -1);
        for (int child : {2, 3, 4})
            QCOMPARE(bones(child), pieceOfChild.at(child));
        for (Eigen::Index t = 0; t < cut->F.rows(); ++t) {
            const Eigen::Vector2d c = centroid(plus.V, plus.F, t);
            const int expected = c.x() < 130.0   ? pieceOfChild.at(2)
                                 : c.x() > 170.0 ? pieceOfChild.at(3)
                                 : c.y() < 130.0 ? pieceOfChild.at(4)
                                 : c.y() > 170.0 ? -1
                                                 : -2;
            if (expected != -2)
                QCOMPARE(cut->piece(t), expected);
        }
        // Each cut's round end touches the outline at the inner corners; the piece above
        // every cut is the bottom bar's.
        std::map<int, int> vertexPiece;
        for (Eigen::Index t = 0; t < cut->F.rows(); ++t)
            for (int k = 0; k < 3; ++k)
                vertexPiece[cut->F(t, k)] = cut->piece(t);
        QCOMPARE(int(cut->parentPiece.size()), 3);
        for (std::size_t c = 0; c < 3; ++c) {
            QCOMPARE(cut->parentPiece[c], -1);
            QVERIFY2(std::abs(cut->cuts[c].round - r) < 1e-9,
                     qPrintable(QString::number(cut->cuts[c].round)));
        }
        // The right bar turns rigidly about the junction; the rest stays.
        const auto turned = turnCut(plus, skeleton, radius, *cut, 3, 60.0 * M_PI / 180.0);
        QVERIFY(turned.has_value());
        const PosedSkeleton *posed = &turned->posed;
        const Eigen::MatrixX2d &U = turned->U;
        double worst = 0.0;
        for (Eigen::Index v = 0; v < U.rows(); ++v) {
            const Eigen::Vector2d rest = cut->V.row(v).transpose();
            const Eigen::Vector2d expected = vertexPiece.at(int(v)) == pieceOfChild.at(3)
                                                 ? transformPoint(posed->transforms[3], rest)
                                                 : rest;
            worst = std::max(worst, (U.row(v).transpose() - expected).norm());
        }
        QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
    }

    void aRootJunctionKeepsItsHeaviestLimb()
    {
        // The root at the crossing of a plus whose bottom bar is the longest: the three other
        // bars are cut off; the bottom one stays the body.
        const finbook::test::GridMesh plus = plusSign(450.0);
        Eigen::MatrixX2d joints(5, 2);
        joints << 150.0, 150.0, 0.0, 150.0, 300.0, 150.0, 150.0, 0.0, 150.0, 450.0;
        const Skeleton skeleton =
            *makeSkeleton(joints, (Eigen::VectorXi(5) << -1, 0, 0, 0, 0).finished());
        const Eigen::VectorXd radius =
            (Eigen::VectorXd(5) << 20.0 * std::sqrt(2.0), 20.0, 20.0, 20.0, 20.0).finished();
        const auto cut = cutAtJoints(plus.V, plus.F, skeleton, radius);
        QVERIFY(cut.hasValue());
        QCOMPARE(int(cut->cuts.size()), 3);
        for (const JointCut &c : cut->cuts) {
            QCOMPARE(c.joint, 0);
            QVERIFY(c.child != 4);
        }
        for (Eigen::Index t = 0; t < cut->F.rows(); ++t)
            if (centroid(plus.V, plus.F, t).y() > 170.0)
                QCOMPARE(cut->piece(t), -1);
        QCOMPARE(bonePieces(skeleton, *cut)(4), -1);
    }

    void legsSplitByASlitAreCutApart()
    {
        // Two legs under a body, split by a slit two cells wide: each leg's cut runs from its
        // outer side to the corner where the slit ends. A flood that went on through that
        // corner vertex (the cut passes through it, to round-off) reached the other leg, and
        // the leg was left uncut (an octopus's arms). Jittered grids put the corner anywhere.
        int cutCorners = 0;
        for (unsigned seed = 1; seed <= 40; ++seed) {
            const finbook::test::GridMesh legs =
                jitteredShape(40, 40, 200.0, 200.0, seed, [](const Eigen::Vector2d &c) {
                    const bool slit = c.y() > 120.0 && std::abs(c.x() - 100.0) < 5.0;
                    return c.y() < 100.0 || (c.x() > 60.0 && c.x() < 140.0 && !slit);
                });
            const auto cut = cutTwoLimbs(legs, {100, 50, 80, 122, 80, 195, 120, 122, 120, 195},
                                         {50, 18, 18, 18, 18});
            QVERIFY(cut.hasValue());
            std::map<int, int> pieceOfJoint;
            for (std::size_t c = 0; c < cut->cuts.size(); ++c)
                pieceOfJoint[cut->cuts[c].joint] = int(c);
            QVERIFY2(
                int(cut->cuts.size()) == 2 && pieceOfJoint.count(1) && pieceOfJoint.count(3),
                qPrintable(QStringLiteral("seed %1: %2 cuts").arg(seed).arg(cut->cuts.size())));
            for (Eigen::Index t = 0; t < cut->F.rows(); ++t) {
                const Eigen::Vector2d c = centroid(legs.V, legs.F, t);
                if (c.y() > 140.0)
                    QCOMPARE(cut->piece(t), pieceOfJoint.at(c.x() < 100.0 ? 1 : 3));
                if (c.y() < 100.0)
                    QCOMPARE(cut->piece(t), -1);
            }
            // How often the cut ended on a mesh vertex (the case this is about).
            for (const JointCut &c : cut->cuts)
                for (const Eigen::Vector2d &end : {c.a, c.b})
                    for (Eigen::Index v = 0; v < legs.V.rows(); ++v)
                        cutCorners += (legs.V.row(v).transpose() - end).norm() < 1e-3 ? 1 : 0;
        }
        QVERIFY(cutCorners > 0);
    }

    void aRingIsCutOpenWhereItsSkeletonBreaks()
    {
        // A handle under a body: two bars 20 wide joined by a bar at the bottom, round a hole.
        // The skeleton, a tree, breaks the loop in the bottom bar: each side is a chain from
        // the body to a tip at the break, 10 apart. Each chain is cut where it leaves the
        // body, and the two pieces part at the break: without that, each side's flood ran on
        // round the ring to the other side's joints and neither was cut, so turning one side
        // dragged the whole handle (a deer's antlers, a guitar's neck).
        finbook::test::GridMesh handle = gridMesh(40, 44, 200.0, 220.0);
        keepTriangles(handle.V, handle.F, [](const Eigen::Vector2d &c) {
            const bool bars = (c.x() > 40.0 && c.x() < 60.0) || (c.x() > 140.0 && c.x() < 160.0);
            const bool bottom = c.y() > 200.0 && c.x() > 40.0 && c.x() < 160.0;
            return c.y() < 100.0 || bars || bottom;
        });
        Eigen::MatrixX2d joints(7, 2);
        joints << 100.0, 50.0,                        // the body
            50.0, 110.0, 50.0, 210.0, 95.0, 210.0,    // down the left bar to the break
            150.0, 110.0, 150.0, 210.0, 105.0, 210.0; // and the right
        const Skeleton skeleton =
            *makeSkeleton(joints, (Eigen::VectorXi(7) << -1, 0, 1, 2, 0, 4, 5).finished());
        // The corners' radii unknown (0) leaves them uncut: each side is one piece.
        const Eigen::VectorXd radius =
            (Eigen::VectorXd(7) << 50.0, 10.0, 0.0, 10.0, 10.0, 0.0, 10.0).finished();
        const auto cut = cutAtJoints(handle.V, handle.F, skeleton, radius);
        QVERIFY(cut.hasValue());
        std::map<int, int> pieceOfJoint;
        for (std::size_t c = 0; c < cut->cuts.size(); ++c)
            pieceOfJoint[cut->cuts[c].joint] = int(c);
        QCOMPARE(int(cut->cuts.size()), 2);
        QVERIFY(pieceOfJoint.count(1) && pieceOfJoint.count(4));
        for (Eigen::Index t = 0; t < cut->F.rows(); ++t) {
            const Eigen::Vector2d c = centroid(handle.V, handle.F, t);
            if (c.y() > 115.0 && c.x() < 94.0)
                QCOMPARE(cut->piece(t), pieceOfJoint.at(1));
            if (c.y() > 115.0 && c.x() > 106.0)
                QCOMPARE(cut->piece(t), pieceOfJoint.at(4));
            if (c.y() < 100.0)
                QCOMPARE(cut->piece(t), -1);
        }
        // The break's vertices are copied, one for each side.
        int copied = 0;
        for (Eigen::Index v = handle.V.rows(); v < cut->V.rows(); ++v)
            copied += std::abs(cut->V(v, 0) - 95.0) < 6.0 && cut->V(v, 1) > 199.0 ? 1 : 0;
        QVERIFY(copied >= 5);
        // Turned at its cut, the left side moves as a piece and the right stays.
        const auto turned = turnCut(handle, skeleton, radius, *cut, 2, 0.5);
        QVERIFY(turned.has_value());
        const Eigen::MatrixX2d &U = turned->U;
        double leftMoved = 0.0, rightMoved = 0.0;
        for (Eigen::Index t = 0; t < cut->F.rows(); ++t)
            for (int k = 0; k < 3; ++k) {
                const double moved = (U.row(cut->F(t, k)) - cut->V.row(cut->F(t, k))).norm();
                if (cut->piece(t) == pieceOfJoint.at(1))
                    leftMoved = std::max(leftMoved, moved);
                if (cut->piece(t) == pieceOfJoint.at(4) || cut->piece(t) < 0)
                    rightMoved = std::max(rightMoved, moved);
            }
        QVERIFY(leftMoved > 20.0);
        QVERIFY(rightMoved < 1e-9);
    }

    void cutsMeetingAtANotchLeaveNoIsland()
    {
        // Two ears side by side on a head, parted only by a V notch at the top: each ear's cut
        // runs from its outer side through its joint to the bottom of the notch. The triangles
        // between the two cuts there could end up in neither ear and cut off from the head, an
        // island that followed the nearest bone (an ear) when it turned. Jittered grids put
        // the notch's vertices anywhere.
        int islands = 0;
        for (unsigned seed = 1; seed <= 40; ++seed) {
            const finbook::test::GridMesh head =
                jitteredShape(40, 32, 200.0, 160.0, seed, [](const Eigen::Vector2d &c) {
                    const bool notch =
                        c.y() > 128.0 && std::abs(c.x() - 100.0) < 0.3 * (c.y() - 128.0);
                    return c.y() < 100.0 || (c.x() > 80.0 && c.x() < 120.0 && !notch);
                });
            const auto cut = cutTwoLimbs(head, {100, 50, 91, 112, 91, 158, 109, 112, 109, 158},
                                         {50, 10, 4, 10, 4});
            QVERIFY(cut.hasValue());
            // Each piece is one part, joined across its triangles' edges.
            std::map<std::pair<int, int>, std::vector<int>> edges;
            for (Eigen::Index t = 0; t < cut->F.rows(); ++t)
                for (int k = 0; k < 3; ++k) {
                    const int a = cut->F(t, k), b = cut->F(t, (k + 1) % 3);
                    edges[{std::min(a, b), std::max(a, b)}].push_back(int(t));
                }
            std::vector<int> part(std::size_t(cut->F.rows()), -1);
            std::map<int, int> partsOfPiece;
            for (Eigen::Index start = 0; start < cut->F.rows(); ++start) {
                if (part[std::size_t(start)] >= 0)
                    continue;
                ++partsOfPiece[cut->piece(start)];
                std::vector<int> stack{int(start)};
                part[std::size_t(start)] = int(start);
                while (!stack.empty()) {
                    const int t = stack.back();
                    stack.pop_back();
                    for (int k = 0; k < 3; ++k) {
                        const int a = cut->F(t, k), b = cut->F(t, (k + 1) % 3);
                        for (const int u : edges[{std::min(a, b), std::max(a, b)}])
                            if (part[std::size_t(u)] < 0 && cut->piece(u) == cut->piece(t)) {
                                part[std::size_t(u)] = int(start);
                                stack.push_back(u);
                            }
                    }
                }
            }
            for (const auto &[piece, parts] : partsOfPiece)
                islands += parts - 1;
        }
        QCOMPARE(islands, 0);
    }

    void badRadiiAreRefused()
    {
        const Arm arm;
        const auto cut = cutAtJoints(arm.mesh.V, arm.mesh.F, arm.skeleton, Eigen::Vector2d(1, 1));
        QVERIFY(!cut.hasValue());
        QCOMPARE(cut.error().code, DeformErrorCode::SizeMismatch);
        // A zero radius (unknown) leaves that joint uncut.
        const auto uncut =
            cutAtJoints(arm.mesh.V, arm.mesh.F, arm.skeleton, Eigen::Vector3d(20.0, 0.0, 20.0));
        QVERIFY(uncut.hasValue());
        QVERIFY(uncut->cuts.empty());
    }
};

QTEST_APPLESS_MAIN(TestCutOut)
#include "tst_cut_out.moc"
