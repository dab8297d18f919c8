// Thin parts keep their bones (issue 21): the outline's vertex budget is spent where the shape
// is thin, so a long, wavy antenna a few px wide on a detailed body gets a bone that follows it
// to its tip without leaving the shape.
#include "skeleton_test_support.h"

#include <finbook/geometry/polyline.h>
#include <finbook/geometry/skeleton/raw_skeleton.h>
#include <finbook/geometry/skeleton/skeleton.h>
#include <finbook/geometry/skeleton/skeleton_refine.h>

#include <QtTest>

#include <cmath>
#include <vector>

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

// A body of radius 100 with a crinkled outline (37 lobes of ±1.5 px: detail that spends the
// vertex budget) and, on top, an antenna `width` px wide and `length` long whose centre line
// swings `swing` px sideways every `wave` px. Returns the outline (positive area) and sets
// `tip` to the antenna's end.
Eigen::MatrixX2d bodyWithAntenna(double width, double length, double swing, double wave,
                                 Eigen::RowVector2d &tip)
{
    std::vector<Eigen::RowVector2d> points;
    const double half = width / 2, gap = std::asin(half / 100.0);
    const int bodyPoints = 720;
    for (int i = 0; i <= bodyPoints; ++i) {
        const double t = M_PI / 2 + gap + (2 * M_PI - 2 * gap) * i / bodyPoints;
        const double r = 100 + 1.5 * std::sin(37 * t);
        points.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    const double base = std::sqrt(100.0 * 100.0 - half * half);
    auto centre = [&](double s) {
        return Eigen::RowVector2d(swing * (1 - std::cos(2 * M_PI * s / wave)), base + s);
    };
    auto normal = [&](double s) {
        const Eigen::RowVector2d d = (centre(s + 0.01) - centre(s - 0.01)).normalized();
        return Eigen::RowVector2d(-d.y(), d.x());
    };
    const int steps = int(length);
    for (int i = 0; i <= steps; ++i) { // right side, outwards
        const double s = length * i / steps;
        points.push_back(centre(s) - half * normal(s));
    }
    for (int k = 1; k < 6; ++k) { // round end
        const double a = M_PI * k / 6;
        const Eigen::RowVector2d d = (centre(length) - centre(length - 0.01)).normalized();
        points.push_back(centre(length) - half * std::cos(a) * normal(length) +
                         half * std::sin(a) * d);
    }
    for (int i = steps; i >= 0; --i) { // left side, back
        const double s = length * i / steps;
        points.push_back(centre(s) + half * normal(s));
    }
    tip = centre(length) + half * (centre(length) - centre(length - 0.01)).normalized();
    Eigen::MatrixX2d ring(Eigen::Index(points.size()), 2);
    for (std::size_t i = 0; i < points.size(); ++i)
        ring.row(Eigen::Index(i)) = points[i];
    return ring;
}

double distanceToBones(const Skeleton &s, const Eigen::RowVector2d &p)
{
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < s.jointCount(); ++j) {
        if (s.parent(j) < 0)
            continue;
        const Eigen::RowVector2d a = s.joints.row(s.parent(j)), ab = s.joints.row(j) - a;
        const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (p - (a + t * ab)).norm());
    }
    return best;
}

} // namespace

class TestSkeletonThinParts : public QObject {
    Q_OBJECT
private slots:
    void antennaKeepsItsBone_data();
    void antennaKeepsItsBone();
};

void TestSkeletonThinParts::antennaKeepsItsBone_data()
{
    QTest::addColumn<double>("width");
    QTest::addColumn<double>("swing");
    QTest::newRow("4 px, gentle waves") << 4.0 << 12.0;
    QTest::newRow("3 px, strong waves") << 3.0 << 20.0;
    QTest::newRow("6 px, gentle waves") << 6.0 << 12.0;
}

void TestSkeletonThinParts::antennaKeepsItsBone()
{
    QFETCH(double, width);
    QFETCH(double, swing);
    Eigen::RowVector2d tip;
    const Region shape = regionOf(bodyWithAntenna(width, 200.0, swing, 60.0, tip));
    QVERIFY(signedArea(shape.front().outer) > 0.0);
    const SkeletonOptions options;
    const auto raw = rawSkeleton(shape, options);
    QVERIFY(raw.hasValue());
    QVERIFY(raw->polygonVertices <= options.maxVertices);
    for (const bool animatorRig : {true, false}) {
        RefineOptions refine;
        refine.animatorRig = animatorRig;
        const auto s = refineSkeleton(*raw, refine);
        QVERIFY(s.hasValue());
        // A bone reaches into the antenna's last few px ...
        const double reach = distanceToBones(*s, tip);
        QVERIFY2(reach <= 2.0 * width, qPrintable(QStringLiteral("tip %1 px from the bones (%2)")
                                                      .arg(reach)
                                                      .arg(animatorRig ? "rig" : "RealSkel")));
        // ... and the bones follow its waves instead of cutting across them.
        const double inside = bonesInside(*s, shape);
        QVERIFY2(
            inside >= 0.995,
            qPrintable(
                QStringLiteral("%1 % of the bone length outside").arg(100.0 * (1.0 - inside))));
    }
}

QTEST_APPLESS_MAIN(TestSkeletonThinParts)
#include "tst_skeleton_thin_parts.moc"
