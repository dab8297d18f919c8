// Automatic skeletons of single parts: the shapes of issue 9 (rectangle, plus sign, hand),
// holes, the refinement controls at their extremes, purity, budgets, cancellation and
// degenerate input.
#include "skeleton_test_support.h"

#include <finbook/geometry/polyline.h>
#include <finbook/geometry/silhouette.h>
#include <finbook/geometry/skeleton/raw_skeleton.h>
#include <finbook/geometry/skeleton/skeleton.h>
#include <finbook/geometry/skeleton/skeleton_refine.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

Skeleton skeletonOf(const Region &region, const RefineOptions &options = {})
{
    const auto s = skeletonize(region, {}, options);
    if (!s)
        qFatal("skeletonize failed: %s", s.error().message.c_str());
    return *s;
}

RawSkeleton rawOf(const Region &region)
{
    const auto raw = rawSkeleton(region);
    if (!raw)
        qFatal("rawSkeleton failed: %s", raw.error().message.c_str());
    return *raw;
}

// RealSkel's refinement alone: the four controls without the animator rig's clean-up.
RefineOptions realSkel()
{
    RefineOptions options;
    options.animatorRig = false;
    return options;
}

Skeleton refined(const RawSkeleton &raw, const RefineOptions &options)
{
    const auto s = refineSkeleton(raw, options);
    if (!s)
        qFatal("refineSkeleton failed: %s", s.error().message.c_str());
    return *s;
}

// A stick figure drawn with a thick pen: head, body, two arms, two legs.
Region stickFigure()
{
    std::vector<StrokeInput> strokes{
        {rows({{0, 0}, {2, 60}, {0, 120}}), 16.0},
        {rows({{-70, 30}, {0, 36}, {72, 44}}), 14.0},
        {rows({{0, 120}, {-25, 170}, {-52, 222}}), 14.0},
        {rows({{0, 120}, {22, 175}, {44, 226}}), 14.0},
        {rows({{1, -28}}), 44.0},
    };
    const auto region = silhouette(strokes);
    if (!region)
        qFatal("stick figure: %s", region.error().message.c_str());
    return *region;
}

QString dataFile(const char *relative)
{
    const QByteArray env = qgetenv("FINBOOK_DATA_DIR");
    const QString dir =
        env.isEmpty() ? QStringLiteral(FINBOOK_DATA_DIR) : QString::fromLocal8Bit(env);
    return dir + QLatin1Char('/') + QLatin1String(relative);
}

void checkSkeleton(const Skeleton &s, const Region &shape)
{
    QVERIFY(isValidSkeleton(s));
    QVERIFY(s.jointCount() >= 1);
    QVERIFY(bonesInside(s, shape) >= 0.99);
}

} // namespace

class TestSkeleton : public QObject {
    Q_OBJECT
private slots:
    void rectangleIsOneBoneAlongItsLongAxis_data();
    void rectangleIsOneBoneAlongItsLongAxis();
    void plusSignHasOneJunctionAndFourTerminals();
    void handHasFiveFingers();
    void stickFigureHasLimbs();
    void holeLoopIsCutWhereThinnest();
    void rootIsNearestCentreOfMassOrChosen();
    void radiusIsInscribedDistance();
    void boneComplexityExtremes();
    void mergeExtremes();
    void pruneExtremes();
    void collapseExtremes();
    void refinementIsPure();
    void rawSkeletonIsDeterministic();
    void vertexBudgetHolds();
    void cancelStopsOrCompletes();
    void degenerateInputs();
    void badInputIsTypedError();
    void randomOutlinesNeverBreak();
};

void TestSkeleton::rectangleIsOneBoneAlongItsLongAxis_data()
{
    QTest::addColumn<double>("angle");
    QTest::addColumn<double>("width");
    QTest::addColumn<double>("height");
    QTest::newRow("axis-aligned") << 0.0 << 200.0 << 40.0;
    QTest::newRow("upright") << 0.0 << 30.0 << 150.0;
    QTest::newRow("turned 30 degrees") << M_PI / 6 << 240.0 << 50.0;
    QTest::newRow("turned 135 degrees") << 0.75 * M_PI << 120.0 << 60.0;
}

void TestSkeleton::rectangleIsOneBoneAlongItsLongAxis()
{
    QFETCH(double, angle);
    QFETCH(double, width);
    QFETCH(double, height);
    const Region shape = regionOf(bar(width, height, angle, {300, 200}));
    const Skeleton s = skeletonOf(shape);
    checkSkeleton(s, shape);
    QCOMPARE(boneCount(s), 1);
    QCOMPARE(s.jointCount(), 2);
    const Eigen::RowVector2d bone = s.joints.row(1) - s.joints.row(0);
    const Eigen::RowVector2d longAxis = width >= height
                                            ? Eigen::RowVector2d(std::cos(angle), std::sin(angle))
                                            : Eigen::RowVector2d(-std::sin(angle), std::cos(angle));
    QVERIFY(std::abs(bone.normalized().dot(longAxis)) > 0.999);
    // The straight skeleton's axis ends half a width from each end.
    const double expected = std::abs(width - height);
    QVERIFY2(std::abs(bone.norm() - expected) < 0.05 * expected,
             qPrintable(QString::number(bone.norm())));
    QVERIFY(std::abs(s.radius(0) - std::min(width, height) / 2) < 1.0);
}

void TestSkeleton::plusSignHasOneJunctionAndFourTerminals()
{
    const Region shape = regionOf(plusSign(40, 120));
    const Skeleton s = skeletonOf(shape);
    checkSkeleton(s, shape);
    QCOMPARE(countKind(s, JointKind::Junction), 1);
    QCOMPARE(countKind(s, JointKind::Terminal), 4);
    QCOMPARE(boneCount(s), 4);
    const Eigen::VectorXi degree = jointDegrees(s);
    for (int j = 0; j < s.jointCount(); ++j) {
        if (degree(j) == 4)
            QVERIFY(s.joints.row(j).norm() < 2.0);
        else
            QVERIFY(std::abs(s.joints.row(j).norm() - 100.0) < 2.0);
    }
}

void TestSkeleton::handHasFiveFingers()
{
    QFile file(dataFile("silhouettes/kimia99_hand_7_1.json"));
    if (!file.open(QIODevice::ReadOnly))
        QSKIP("shared/data/silhouettes is not available (set FINBOOK_DATA_DIR)");
    const QJsonArray contours = QJsonDocument::fromJson(file.readAll())
                                    .object()
                                    .value(QStringLiteral("contours"))
                                    .toArray();
    const Region shape = regionOf(toMatrix(contours[0].toArray()));
    // The animator rig drops the wrist's stub (it stays within the palm's disk).
    QCOMPARE(countKind(skeletonOf(shape), JointKind::Terminal), 5);
    const Skeleton s = skeletonOf(shape, realSkel());
    checkSkeleton(s, shape);
    const Eigen::VectorXi degree = jointDegrees(s);
    const double top = shape[0].outer.col(1).minCoeff(), bottom = shape[0].outer.col(1).maxCoeff();
    // Five fingers and maybe the wrist (its stub reaches just out of the palm's inscribed disk
    // or not, with how finely the outline's bottom is kept): five or six tips; the fingers' in
    // the upper three quarters, each at the end of a branch at least three finger widths long.
    const int tips = countKind(s, JointKind::Terminal);
    QVERIFY2(tips == 5 || tips == 6, qPrintable(QString::number(tips)));
    const std::vector<std::vector<int>> children = jointChildren(s);
    int fingers = 0;
    for (int j = 0; j < s.jointCount(); ++j) {
        if (degree(j) != 1 || s.joints(j, 1) > top + 0.75 * (bottom - top))
            continue;
        // Walk from the tip to the first junction.
        double length = 0.0;
        int at = j, previous = -1;
        while (degree(at) <= 2) {
            int next = s.parent(at) >= 0 && s.parent(at) != previous ? s.parent(at) : -1;
            for (int c : children[std::size_t(at)])
                next = c != previous && next < 0 ? c : next;
            if (next < 0)
                break;
            length += (s.joints.row(next) - s.joints.row(at)).norm();
            previous = at;
            at = next;
        }
        QVERIFY2(length >= 6.0 * s.radius(j), qPrintable(QString::number(length)));
        ++fingers;
    }
    QCOMPARE(fingers, 5);
}

void TestSkeleton::stickFigureHasLimbs()
{
    const Region shape = stickFigure();
    const Skeleton s = skeletonOf(shape);
    checkSkeleton(s, shape);
    // Head, two hands, two feet.
    QCOMPARE(countKind(s, JointKind::Terminal), 5);
    QVERIFY(countKind(s, JointKind::Junction) >= 2);
}

void TestSkeleton::holeLoopIsCutWhereThinnest()
{
    // A ring whose hole sits right of centre: thinnest on the right.
    Polygon ring{circle(96, 100), {oriented(circle(80, 60, {25, 3}), false)}};
    const Region shape{ring};
    const Skeleton s = skeletonOf(shape);
    checkSkeleton(s, shape);
    QCOMPARE(boneCount(s), s.jointCount() - 1); // a tree: the loop is cut
    QCOMPARE(countKind(s, JointKind::Terminal), 2);
    for (int j = 0; j < s.jointCount(); ++j) {
        if (jointDegrees(s)(j) == 1)
            QVERIFY2(s.joints(j, 0) > 50.0, qPrintable(QString::number(s.joints(j, 0))));
    }
}

void TestSkeleton::rootIsNearestCentreOfMassOrChosen()
{
    const Region shape = stickFigure();
    const RawSkeleton raw = rawOf(shape);
    const Skeleton s = refined(raw, realSkel());
    QCOMPARE(s.root, 0);
    QCOMPARE(s.parent(s.root), -1);
    for (int j = 0; j < s.jointCount(); ++j)
        QVERIFY((s.joints.row(j) - raw.centroid).norm() >=
                (s.joints.row(s.root) - raw.centroid).norm());
    RefineOptions options = realSkel();
    options.rootNear = Eigen::Vector2d(-70, 30); // the left hand
    const Skeleton handRoot = refined(raw, options);
    QVERIFY((handRoot.joints.row(handRoot.root) - Eigen::RowVector2d(-70, 30)).norm() < 20.0);
    QVERIFY(boneSet(handRoot) == boneSet(s)); // same bones, other root
}

void TestSkeleton::radiusIsInscribedDistance()
{
    const Region shape = stickFigure();
    const RawSkeleton raw = rawOf(shape);
    QVERIFY(raw.radius.allFinite() && raw.radius.minCoeff() >= 0.0);
    // No joint's circle reaches far outside the shape: radius ≤ distance to the outline.
    const Skeleton s = refined(raw, {});
    for (int j = 0; j < s.jointCount(); ++j) {
        double distance = std::numeric_limits<double>::infinity();
        for (const Eigen::MatrixX2d &r : regionRings(shape)) {
            for (Eigen::Index i = 0; i < r.rows(); ++i) {
                const Eigen::RowVector2d a = r.row(i), ab = r.row((i + 1) % r.rows()) - a;
                const double t =
                    std::clamp((s.joints.row(j) - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
                distance = std::min(distance, (s.joints.row(j) - (a + t * ab)).norm());
            }
        }
        QVERIFY2(s.radius(j) <= distance + 1.0,
                 qPrintable(QStringLiteral("%1 vs %2").arg(s.radius(j)).arg(distance)));
        QVERIFY(s.radius(j) >= 0.5 * distance);
    }
}

void TestSkeleton::boneComplexityExtremes()
{
    const RawSkeleton raw = rawOf(stickFigure());
    RefineOptions fine = realSkel(), coarse = realSkel();
    fine.boneTolerance = 0.0;
    coarse.boneTolerance = std::numeric_limits<double>::infinity();
    const Skeleton many = refined(raw, fine), few = refined(raw, coarse);
    QVERIFY2(boneCount(many) > boneCount(few),
             qPrintable(QStringLiteral("%1 vs %2").arg(boneCount(many)).arg(boneCount(few))));
    // Tolerance 0 keeps every raw edge as a bone.
    QCOMPARE(boneCount(many), int(raw.edges.rows()));
    RefineOptions middle = realSkel();
    middle.boneTolerance = 2.0;
    const int between = boneCount(refined(raw, middle));
    QVERIFY(between >= boneCount(few) && between <= boneCount(many));
}

void TestSkeleton::mergeExtremes()
{
    const RawSkeleton raw = rawOf(stickFigure());
    const Skeleton none = refined(raw, realSkel());
    RefineOptions all = realSkel();
    all.mergeDistance = refineRanges(raw).mergeDistance + 1.0;
    const Skeleton merged = refined(raw, all);
    QVERIFY(countKind(merged, JointKind::Junction) < countKind(none, JointKind::Junction));
    QVERIFY(boneCount(merged) < boneCount(none));
    QCOMPARE(countKind(merged, JointKind::Terminal), countKind(none, JointKind::Terminal));
    QVERIFY(bonesInside(merged, stickFigure()) >= 0.99);
}

void TestSkeleton::pruneExtremes()
{
    const RawSkeleton raw = rawOf(stickFigure());
    const Skeleton none = refined(raw, {});
    RefineOptions all;
    all.pruneLength = refineRanges(raw).pruneLength + 1.0;
    const Skeleton pruned = refined(raw, all);
    QVERIFY(boneCount(pruned) < boneCount(none));
    // Pruning stops at one branch: two tips, no junction.
    QCOMPARE(countKind(pruned, JointKind::Terminal), 2);
    QCOMPARE(countKind(pruned, JointKind::Junction), 0);
}

void TestSkeleton::collapseExtremes()
{
    const RawSkeleton raw = rawOf(stickFigure());
    RefineOptions detailed;
    detailed.boneTolerance = 1.0;
    const Skeleton none = refined(raw, detailed);
    RefineOptions all = detailed;
    all.collapseLength = refineRanges(raw).collapseLength + 1.0;
    const Skeleton collapsed = refined(raw, all);
    QVERIFY2(boneCount(collapsed) < boneCount(none),
             qPrintable(QStringLiteral("%1 vs %2").arg(boneCount(collapsed)).arg(boneCount(none))));
    // Tips are never collapsed away, and bones stay inside.
    QCOMPARE(countKind(collapsed, JointKind::Terminal), countKind(none, JointKind::Terminal));
    QVERIFY(bonesInside(collapsed, stickFigure()) >= 0.99);
}

void TestSkeleton::refinementIsPure()
{
    const RawSkeleton raw = rawOf(stickFigure());
    RefineOptions a, b;
    a.boneTolerance = 3.0;
    a.pruneLength = 10.0;
    b.mergeDistance = 200.0;
    b.collapseLength = 40.0;
    const Skeleton first = refined(raw, a);
    refined(raw, b);
    const Skeleton again = refined(raw, a);
    QVERIFY(identical(first, again));
    const RawSkeleton copy = raw;
    QVERIFY(identical(refined(copy, a), first));
}

void TestSkeleton::rawSkeletonIsDeterministic()
{
    const Region shape = stickFigure();
    const RawSkeleton x = rawOf(shape), y = rawOf(shape);
    QVERIFY(x.nodes == y.nodes && x.radius == y.radius && x.edges == y.edges);
    QCOMPARE(x.edges.rows(), x.nodes.rows() - 1); // one tree: a connected figure
}

void TestSkeleton::vertexBudgetHolds()
{
    // A noisy 4,000-point blob and a perfectly regular 300-spike star (the slow case of CGAL).
    Eigen::MatrixX2d blob(4000, 2), star(600, 2);
    for (int i = 0; i < 4000; ++i) {
        const double t = 2 * M_PI * i / 4000;
        const double r = 200 + 30 * std::sin(3 * t) + 2 * std::sin(977.0 * i);
        blob.row(i) << r * std::cos(t), r * std::sin(t);
    }
    for (int i = 0; i < 600; ++i) {
        const double t = 2 * M_PI * i / 600, r = i % 2 ? 60 : 100;
        star.row(i) << r * std::cos(t), r * std::sin(t);
    }
    for (const Eigen::MatrixX2d &ring : {blob, star}) {
        SkeletonOptions options;
        const auto raw = rawSkeleton(regionOf(ring), options);
        QVERIFY(raw.hasValue());
        QVERIFY(raw->polygonVertices <= options.maxVertices);
        QVERIFY(raw->nodes.allFinite());
        const auto s = refineSkeleton(*raw);
        QVERIFY(s.hasValue());
        checkSkeleton(*s, regionOf(ring));
    }
}

void TestSkeleton::cancelStopsOrCompletes()
{
    const Region shape = stickFigure();
    SkeletonOptions stop;
    stop.cancelled = [] { return true; };
    const auto cancelled = rawSkeleton(shape, stop);
    QVERIFY(!cancelled.hasValue());
    QCOMPARE(cancelled.error().code, GeometryErrorCode::Cancelled);
    // Cancelling after k polls either stops or gives exactly the uncancelled result.
    const RawSkeleton full = rawOf(shape);
    int completed = 0;
    for (int k = 0; k < 200; k += 7) {
        int polls = 0;
        SkeletonOptions later;
        later.cancelled = [&polls, k] { return ++polls > k; };
        const auto raw = rawSkeleton(shape, later);
        if (raw.hasValue()) {
            QVERIFY(raw->nodes == full.nodes && raw->edges == full.edges);
            ++completed;
        } else {
            QCOMPARE(raw.error().code, GeometryErrorCode::Cancelled);
        }
    }
    QVERIFY(completed > 0);
    int polls = 0;
    SkeletonOptions counting;
    counting.cancelled = [&polls] { return ++polls < 0; };
    QVERIFY(rawSkeleton(shape, counting).hasValue());
    QVERIFY(polls > 10); // polled inside CGAL's event loop, not just between stages
}

void TestSkeleton::degenerateInputs()
{
    // One dot (a disk, through the silhouette), a point, a straight line, a zero-area
    // scribble, a figure eight that touches itself at a point.
    const auto dot = silhouette({{rows({{10, 10}}), 3.0}});
    QVERIFY(dot.hasValue());
    const Region point = regionOf(rows({{5, 5}}));
    const Region line = regionOf(rows({{0, 0}, {10, 0}, {20, 0}, {30, 0}}));
    const Region scribble = regionOf(rows({{0, 0}, {10, 5}, {20, 0}, {10, 5}}));
    const Region eight = regionOf(
        rows({{0, 0}, {40, 0}, {40, 40}, {80, 40}, {80, 80}, {40, 80}, {40, 40}, {0, 40}}));
    for (const Region &shape : {*dot, point, line, scribble}) {
        const auto raw = rawSkeleton(shape);
        QVERIFY(raw.hasValue());
        const auto s = refineSkeleton(*raw);
        QVERIFY(s.hasValue());
        QVERIFY(isValidSkeleton(*s));
        QVERIFY(s->jointCount() >= 1 && boneCount(*s) <= 1);
    }
    QCOMPARE(skeletonOf(point).jointCount(), 1);
    const Skeleton alongLine = skeletonOf(line);
    QCOMPARE(boneCount(alongLine), 1);
    QVERIFY(std::abs((alongLine.joints.row(1) - alongLine.joints.row(0)).norm() - 30.0) < 1e-9);
    QVERIFY(rawOf(line).degenerate);
    const Skeleton eightSkeleton = skeletonOf(eight);
    checkSkeleton(eightSkeleton, eight);
    // The pinch splits the figure into two squares: one joint each, two trees that the
    // animator rig joins (one piece hangs from the other) and RealSkel leaves apart.
    QCOMPARE(eightSkeleton.jointCount(), 2);
    QCOMPARE(boneCount(eightSkeleton), 1);
    const Skeleton apart = skeletonOf(eight, realSkel());
    QCOMPARE(apart.jointCount(), 2);
    QCOMPARE(boneCount(apart), 0);
}

void TestSkeleton::badInputIsTypedError()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QCOMPARE(rawSkeleton(Region{}).error().code, GeometryErrorCode::EmptyInput);
    QCOMPARE(rawSkeleton(regionOf(rows({{nan, 1}, {nan, nan}}))).error().code,
             GeometryErrorCode::EmptyInput);
    QCOMPARE(rawSkeleton(regionOf(rows({{0, 0}, {1e9, 0}, {0, 1}}))).error().code,
             GeometryErrorCode::CoordinateOutOfRange);
    SkeletonOptions tiny;
    tiny.targetVertices = 2;
    QCOMPARE(rawSkeleton(regionOf(bar(10, 5)), tiny).error().code,
             GeometryErrorCode::InvalidOptions);
    // NaN rows among good ones are dropped.
    Eigen::MatrixX2d withNan = bar(100, 20);
    withNan.conservativeResize(5, 2);
    withNan.row(4) << nan, nan;
    QCOMPARE(boneCount(skeletonOf(regionOf(withNan))), 1);
    const RawSkeleton raw = rawOf(regionOf(bar(100, 20)));
    RefineOptions negative;
    negative.pruneLength = -1.0;
    QCOMPARE(refineSkeleton(raw, negative).error().code, GeometryErrorCode::InvalidOptions);
    RefineOptions notANumber;
    notANumber.boneTolerance = nan;
    QCOMPARE(refineSkeleton(raw, notANumber).error().code, GeometryErrorCode::InvalidOptions);
    RawSkeleton broken = raw;
    broken.edges(0, 0) = 99;
    QCOMPARE(refineSkeleton(broken, {}).error().code, GeometryErrorCode::InvalidIndex);
    QCOMPARE(refineSkeleton(RawSkeleton{}, {})->jointCount(), 0);
}

namespace {
// Seeded random outlines of three kinds: a self-crossing ring of random points, the
// silhouette of random pen strokes, and a star (exactly symmetric for even seeds).
Region randomOutline(std::mt19937 &rng, int kind)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    if (kind == 0) {
        Eigen::MatrixX2d ring(3 + int(u(rng) * 40), 2);
        for (Eigen::Index i = 0; i < ring.rows(); ++i)
            ring.row(i) << 300 * u(rng), 300 * u(rng);
        return regionOf(ring);
    }
    if (kind == 1) {
        std::vector<StrokeInput> strokes;
        for (int s = 0, n = 1 + int(u(rng) * 6); s < n; ++s) {
            Eigen::MatrixX2d points(1 + int(u(rng) * 25), 2);
            Eigen::RowVector2d at(400 * u(rng), 400 * u(rng));
            for (Eigen::Index i = 0; i < points.rows(); ++i) {
                at += Eigen::RowVector2d(60 * (u(rng) - 0.5), 60 * (u(rng) - 0.5));
                points.row(i) = at;
            }
            strokes.push_back({points, 1.0 + 20.0 * u(rng)});
        }
        const auto region = silhouette(strokes);
        return region ? *region : Region{};
    }
    const int n = 2 * (4 + int(u(rng) * 100));
    const double noise = kind == 2 ? 0.0 : 5.0;
    Eigen::MatrixX2d star(n, 2);
    for (int i = 0; i < n; ++i) {
        const double t = 2 * M_PI * i / n, r = (i % 2 ? 60 : 100) + noise * u(rng);
        star.row(i) << r * std::cos(t), r * std::sin(t);
    }
    return regionOf(star);
}
} // namespace

void TestSkeleton::randomOutlinesNeverBreak()
{
    for (int seed = 0; seed < 80; ++seed) {
        std::mt19937 rng{std::uint32_t(seed)};
        const Region shape = randomOutline(rng, seed % 4);
        if (shape.empty())
            continue;
        const auto raw = rawSkeleton(shape);
        QVERIFY2(raw.hasValue(), qPrintable(QStringLiteral("seed %1").arg(seed)));
        QVERIFY(raw->nodes.allFinite() && raw->radius.allFinite());
        std::uniform_real_distribution<double> u(0.0, 1.0);
        const RefineRanges ranges = refineRanges(*raw);
        RefineOptions options;
        options.boneTolerance = 5.0 * u(rng);
        options.mergeDistance = ranges.mergeDistance * u(rng);
        options.pruneLength = ranges.pruneLength * u(rng);
        options.collapseLength = ranges.collapseLength * u(rng);
        for (const RefineOptions &o : {RefineOptions{}, realSkel(), options}) {
            const auto s = refineSkeleton(*raw, o);
            QVERIFY(s.hasValue());
            QVERIFY2(isValidSkeleton(*s), qPrintable(QStringLiteral("seed %1").arg(seed)));
            QVERIFY(s->jointCount() >= 1);
            // A ring of random points crosses itself: its even-odd inside is not the filled
            // shape the skeleton follows, so only the other kinds are checked for inside.
            // The animator rig joins separate pieces by bones across the gap between them.
            if (seed % 4 != 0 && (!o.animatorRig || raw->contour.size() == 1))
                QVERIFY2(bonesInside(*s, shape, 1.0) >= 0.99,
                         qPrintable(QStringLiteral("seed %1").arg(seed)));
        }
    }
}

QTEST_APPLESS_MAIN(TestSkeleton)
#include "tst_skeleton.moc"
