// The vector eraser's geometry: which parts of a polyline stay when a disc sweeps across it.
#include <finbook/geometry/erase/polyline_erase.h>

#include <QtTest>

#include <cmath>
#include <random>

using namespace finbook::geometry;

namespace {

Eigen::MatrixX2d horizontal(int points, double length)
{
    Eigen::MatrixX2d P(points, 2);
    for (int i = 0; i < points; ++i)
        P.row(i) << length * i / (points - 1), 0.0;
    return P;
}

Eigen::MatrixX2d path(std::initializer_list<Eigen::RowVector2d> rows)
{
    Eigen::MatrixX2d E(Eigen::Index(rows.size()), 2);
    Eigen::Index i = 0;
    for (const auto &r : rows)
        E.row(i++) = r;
    return E;
}

Eigen::RowVector2d at(const Eigen::MatrixX2d &P, const PolylinePlace &p)
{
    if (P.rows() == 1)
        return P.row(0);
    return P.row(p.segment) + p.t * (P.row(p.segment + 1) - P.row(p.segment));
}

double distanceToPath(const Eigen::RowVector2d &p, const Eigen::MatrixX2d &E)
{
    double best = HUGE_VAL;
    for (Eigen::Index j = 0; j < std::max<Eigen::Index>(E.rows() - 1, 1); ++j) {
        const Eigen::RowVector2d a = E.row(j), b = E.row(std::min(j + 1, E.rows() - 1));
        const Eigen::RowVector2d ab = b - a;
        const double len2 = ab.squaredNorm();
        const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, (p - (a + t * ab)).norm());
    }
    return best;
}

// Whether global parameter u (segment + t) lies in a kept span.
bool kept(const EraseResult &r, double u)
{
    for (const KeptSpan &s : r.kept)
        if (u >= double(s.from.segment) + s.from.t - 1e-9 &&
            u <= double(s.to.segment) + s.to.t + 1e-9)
            return true;
    return false;
}

} // namespace

class TestPolylineErase : public QObject {
    Q_OBJECT

private slots:
    void aRubAcrossTheMiddleSplitsAtTheDiscsEdge();
    void aRubAtAnEndShortensIt();
    void aMissLeavesItWhole();
    void aDabOnAOnePointLineTakesIt();
    void reachTakesAThickLineAtItsEdge();
    void keptIsExactlyWhatTheDiscMissed();
    void nonFiniteRubPointsAreIgnored();
};

void TestPolylineErase::aRubAcrossTheMiddleSplitsAtTheDiscsEdge()
{
    const Eigen::MatrixX2d P = horizontal(11, 100); // a point every 10 px
    const EraseResult r =
        erasePolyline(P, Eigen::VectorXd::Zero(11), path({{50, -20}, {50, 20}}), 5);
    QVERIFY(r.touched);
    QCOMPARE(r.kept.size(), std::size_t(2));
    QCOMPARE(at(P, r.kept[0].from).x(), 0.0);
    QVERIFY(std::abs(at(P, r.kept[0].to).x() - 45) < 1e-9);
    QVERIFY(std::abs(at(P, r.kept[1].from).x() - 55) < 1e-9);
    QCOMPARE(at(P, r.kept[1].to).x(), 100.0);
}

void TestPolylineErase::aRubAtAnEndShortensIt()
{
    const Eigen::MatrixX2d P = horizontal(11, 100);
    const EraseResult r = erasePolyline(P, Eigen::VectorXd::Zero(11), path({{-3, -9}, {-3, 9}}), 8);
    QVERIFY(r.touched);
    QCOMPARE(r.kept.size(), std::size_t(1));
    QVERIFY(std::abs(at(P, r.kept[0].from).x() - 5) < 1e-9);
    QCOMPARE(at(P, r.kept[0].to).x(), 100.0);
}

void TestPolylineErase::aMissLeavesItWhole()
{
    const Eigen::MatrixX2d P = horizontal(11, 100);
    const EraseResult r =
        erasePolyline(P, Eigen::VectorXd::Zero(11), path({{0, 10}, {100, 10}}), 9.5);
    QVERIFY(!r.touched);
    QCOMPARE(r.kept.size(), std::size_t(1));
}

void TestPolylineErase::aDabOnAOnePointLineTakesIt()
{
    const Eigen::MatrixX2d dot = path({{10, 10}});
    QVERIFY(erasePolyline(dot, Eigen::VectorXd::Zero(1), path({{12, 10}}), 3).kept.empty());
    const EraseResult missed = erasePolyline(dot, Eigen::VectorXd::Zero(1), path({{20, 10}}), 3);
    QVERIFY(!missed.touched);
    QCOMPARE(missed.kept.size(), std::size_t(1));
}

void TestPolylineErase::reachTakesAThickLineAtItsEdge()
{
    const Eigen::MatrixX2d P = horizontal(11, 100);
    const Eigen::MatrixX2d rub = path({{30, 12}, {70, 12}}); // 12 px above the centre line
    QVERIFY(!erasePolyline(P, Eigen::VectorXd::Zero(11), rub, 5).touched);
    const EraseResult thick = erasePolyline(P, Eigen::VectorXd::Constant(11, 8), rub, 5);
    QVERIFY(thick.touched);
    QCOMPARE(thick.kept.size(), std::size_t(2));
    // Distance 13 from the rub's ends: the cut is sqrt(13² - 12²) = 5 beyond them.
    QVERIFY(std::abs(at(P, thick.kept[0].to).x() - 25) < 1e-9);
    QVERIFY(std::abs(at(P, thick.kept[1].from).x() - 75) < 1e-9);
}

void TestPolylineErase::keptIsExactlyWhatTheDiscMissed()
{
    std::mt19937 rng(22);
    std::uniform_real_distribution<double> coord(0, 200), step(-6, 6);
    for (int trial = 0; trial < 50; ++trial) {
        Eigen::MatrixX2d P(300, 2);
        P.row(0) << coord(rng), coord(rng);
        for (Eigen::Index i = 1; i < P.rows(); ++i)
            P.row(i) = P.row(i - 1) + Eigen::RowVector2d(step(rng), step(rng));
        Eigen::MatrixX2d E(8, 2);
        for (Eigen::Index j = 0; j < E.rows(); ++j)
            E.row(j) << coord(rng), coord(rng);
        const double radius = 4 + coord(rng) / 20;
        const EraseResult r = erasePolyline(P, Eigen::VectorXd::Zero(P.rows()), E, radius);
        // Every kept span's ends are on the disc's edge (or the polyline's ends) and sample
        // points are kept exactly when they are outside the swept disc.
        for (const KeptSpan &s : r.kept) {
            QVERIFY(distanceToPath(at(P, s.from), E) >= radius - 1e-6);
            QVERIFY(distanceToPath(at(P, s.to), E) >= radius - 1e-6);
        }
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            const double d = distanceToPath(P.row(i), E);
            if (d > radius + 1e-6)
                QVERIFY2(kept(r, double(i)), qPrintable(QString::number(d)));
            else if (d < radius - 1e-6)
                QVERIFY2(!kept(r, double(i)), qPrintable(QString::number(d)));
        }
    }
}

void TestPolylineErase::nonFiniteRubPointsAreIgnored()
{
    const Eigen::MatrixX2d P = horizontal(11, 100);
    const double nan = std::nan("");
    const EraseResult r =
        erasePolyline(P, Eigen::VectorXd::Zero(11), path({{nan, 0}, {50, -20}, {50, 20}}), 5);
    QCOMPARE(r.kept.size(), std::size_t(2));
    QVERIFY(!erasePolyline(P, Eigen::VectorXd::Zero(11), path({{nan, nan}}), 5).touched);
    QVERIFY(!erasePolyline(P, Eigen::VectorXd::Zero(11), path({{50, 0}}), nan).touched);
}

QTEST_APPLESS_MAIN(TestPolylineErase)
#include "tst_polyline_erase.moc"
