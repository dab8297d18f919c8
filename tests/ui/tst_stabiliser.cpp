// The pen's stabiliser (tools/stabiliser.h) on a recorded shaky hand: off, the ink is the
// cursor; on, the line it draws wobbles measurably less the stronger it is, its pressure
// flickers less, and it still starts where the pen touched down and ends where it lifted.
#include "stabiliser_support.h"

#include <finbook/ui/tools/stabiliser.h>

#include <QtTest>

using namespace finbook;
using namespace finbook::test;

namespace {
// The stroke the stabiliser makes of `input` with a string `length` long.
std::vector<model::StrokePoint> stabilised(const std::vector<model::StrokePoint> &input,
                                           double length)
{
    ui::LazyString string(length);
    std::vector<model::StrokePoint> out{input.front()};
    string.start(input.front());
    for (std::size_t i = 1; i + 1 < input.size(); ++i)
        if (const auto ink = string.follow(input[i]))
            out.push_back(*ink);
    out.push_back(string.finish(input.back()));
    return out;
}
} // namespace

class TestStabiliser : public QObject {
    Q_OBJECT
private slots:
    void offIsTheCursor();
    void steadiesAShakyHand();
    void smoothsThePressure();
    void inkNeverLeavesTheString();
    void lengthFollowsTheZoom();
};

void TestStabiliser::offIsTheCursor()
{
    const auto input = shakyCircle();
    ui::LazyString string(0.0);
    string.start(input.front());
    for (std::size_t i = 1; i < input.size(); ++i) {
        const auto ink = string.follow(input[i]);
        QVERIFY(ink.has_value());
        QCOMPARE(ink->x, input[i].x);
        QCOMPARE(ink->y, input[i].y);
        QCOMPARE(ink->pressure, input[i].pressure);
    }
    QCOMPARE(stabilised(input, 0.0).size(), input.size());
    // A string of no length, negative or not a number is no stabiliser.
    QCOMPARE(ui::LazyString(-3).length(), 0.0);
    QCOMPARE(ui::LazyString(std::nan("")).length(), 0.0);
}

void TestStabiliser::steadiesAShakyHand()
{
    const auto input = shakyCircle();
    const double raw = wobbleOf(input);
    double previous = raw;
    for (int strength : {2, 5, 10}) {
        const auto out = stabilised(input, ui::stabiliserLength(strength, 1.0));
        const double wobble = wobbleOf(out);
        qInfo("strength %d (string %.0f px): wobble %.1f rad against %.1f rad unsteadied, %zu of "
              "%zu samples",
              strength, ui::stabiliserLength(strength, 1.0), wobble, raw, out.size(), input.size());
        QVERIFY2(wobble < previous, qPrintable(QString::number(wobble)));
        previous = wobble;
        // Ends exact: where the pen touched down and where it lifted.
        QCOMPARE(out.front().x, input.front().x);
        QCOMPARE(out.front().y, input.front().y);
        QCOMPARE(out.back().x, input.back().x);
        QCOMPARE(out.back().y, input.back().y);
        QCOMPARE(out.back().pressure, input.back().pressure);
    }
    // At strength 5 (20 px) the ±2 px jitter is as good as gone: a twentieth of the turning or
    // less, and under three times the circle's own 2π (unsteadied: over seventy times).
    const double steady = wobbleOf(stabilised(input, ui::stabiliserLength(5, 1.0)));
    QVERIFY2(steady < raw / 20, qPrintable(QString::number(steady)));
    QVERIFY(steady < 3 * 2 * M_PI);
}

void TestStabiliser::smoothsThePressure()
{
    const auto input = shakyCircle();
    const double raw = pressureFlicker(input);
    const double steady = pressureFlicker(stabilised(input, ui::stabiliserLength(5, 1.0)));
    qInfo("pressure flicker: %.3f unsteadied, %.3f at strength 5", raw, steady);
    QVERIFY(steady < raw / 3);
}

void TestStabiliser::inkNeverLeavesTheString()
{
    // However the cursor jumps, the ink stays within the string's length of it, and it only
    // moves when the string is taut.
    const auto input = shakyCircle({200, 200}, 60, 300, 8.0, 11);
    const double length = 12.0;
    ui::LazyString string(length);
    string.start(input.front());
    for (std::size_t i = 1; i < input.size(); ++i) {
        const model::StrokePoint before = string.ink();
        const auto ink = string.follow(input[i]);
        const double reach = std::hypot(string.ink().x - input[i].x, string.ink().y - input[i].y);
        QVERIFY(reach <= length + 1e-3);
        if (!ink) {
            QCOMPARE(string.ink().x, before.x);
            QCOMPARE(string.ink().y, before.y);
        } else {
            QVERIFY(std::abs(reach - length) < 1e-3); // pulled taut
        }
    }
}

void TestStabiliser::lengthFollowsTheZoom()
{
    QCOMPARE(ui::stabiliserLength(0, 1.0), 0.0);
    QCOMPARE(ui::stabiliserLength(5, 1.0), 20.0);
    QCOMPARE(ui::stabiliserLength(5, 2.0), 10.0);  // zoomed in: the same pull on screen
    QCOMPARE(ui::stabiliserLength(50, 1.0), 40.0); // at most strength 10
    QCOMPARE(ui::stabiliserLength(5, 0.0), 0.0);
}

QTEST_MAIN(TestStabiliser)
#include "tst_stabiliser.moc"
