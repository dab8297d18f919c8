// The eraser on one stroke (model/erase/stroke_cut.h): pieces keep colour, width and pressure,
// and looking only at the segments near the rub gives exactly what the whole stroke gives.
#include <finbook/geometry/erase/polyline_erase.h>
#include <finbook/model/erase/stroke_cut.h>

#include <QtTest>

#include <cmath>
#include <random>

using namespace finbook;

namespace {

// The pieces of `s` that geometry::erasePolyline keeps, built from the whole stroke.
std::vector<std::vector<model::StrokePoint>> reference(const model::StrokeData &s,
                                                       const std::vector<QPointF> &rub, double r)
{
    const Eigen::Index n = Eigen::Index(s.points.size());
    Eigen::MatrixX2d P(n, 2);
    Eigen::VectorXd reach(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        P.row(i) << s.points[std::size_t(i)].x, s.points[std::size_t(i)].y;
        reach(i) = s.width / 2 * double(s.points[std::size_t(i)].pressure);
    }
    Eigen::MatrixX2d E(Eigen::Index(rub.size()), 2);
    for (std::size_t j = 0; j < rub.size(); ++j)
        E.row(Eigen::Index(j)) << rub[j].x(), rub[j].y();
    std::vector<std::vector<model::StrokePoint>> out;
    for (const geometry::KeptSpan &span : geometry::erasePolyline(P, reach, E, r).kept) {
        const auto at = [&](const geometry::PolylinePlace &p) {
            const model::StrokePoint &a = s.points[std::size_t(p.segment)];
            const model::StrokePoint &b = s.points[std::size_t(p.segment) + 1];
            if (p.t == 0.0 || p.t == 1.0)
                return p.t == 0.0 ? a : b;
            const float t = float(p.t);
            return model::StrokePoint{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y),
                                      a.pressure + t * (b.pressure - a.pressure)};
        };
        std::vector<model::StrokePoint> piece{at(span.from)};
        for (Eigen::Index i = span.from.segment + 1; i <= span.to.segment; ++i)
            piece.push_back(s.points[std::size_t(i)]);
        piece.push_back(at(span.to));
        const auto same = [](const auto &a, const auto &b) { return a.x == b.x && a.y == b.y; };
        if (piece.size() > 1 && same(piece[0], piece[1]))
            piece.erase(piece.begin());
        if (piece.size() > 1 && same(piece[piece.size() - 1], piece[piece.size() - 2]))
            piece.pop_back();
        double length = 0;
        for (std::size_t i = 1; i < piece.size(); ++i)
            length += std::hypot(piece[i].x - piece[i - 1].x, piece[i].y - piece[i - 1].y);
        if (length >= model::kMinPieceLength)
            out.push_back(piece);
    }
    return out;
}

} // namespace

class TestStrokeCut : public QObject {
    Q_OBJECT
private slots:
    void piecesKeepColourWidthAndPressure();
    void aMissIsNoCutAndADabTakesADot();
    void nearTheRubIsTheSameAsTheWholeStroke();
};

void TestStrokeCut::piecesKeepColourWidthAndPressure()
{
    model::StrokeData s;
    s.color = 0xff102030;
    s.width = 6.0f;
    for (int i = 0; i <= 100; ++i)
        s.points.push_back({float(2 * i), 50.0f, float(i) / 100});
    const auto pieces = model::cutStroke(s, {QPointF(100, 0), QPointF(100, 100)}, 4);
    QVERIFY(pieces);
    QCOMPARE(pieces->size(), std::size_t(2));
    for (const model::StrokeDataPtr &p : *pieces) {
        QCOMPARE(p->color, s.color);
        QCOMPARE(p->width, s.width);
    }
    QCOMPARE(pieces->front()->points.front(), s.points.front());
    QCOMPARE(pieces->back()->points.back(), s.points.back());
    // The cut ends carry the pressure of where they are on the line.
    const model::StrokePoint end = pieces->front()->points.back();
    QVERIFY(std::abs(end.pressure - end.x / 200) < 1e-5f);
}

void TestStrokeCut::aMissIsNoCutAndADabTakesADot()
{
    model::StrokeData line;
    line.points = {{0, 0, 1}, {100, 0, 1}};
    QVERIFY(!model::cutStroke(line, {QPointF(50, 40)}, 10));
    QVERIFY(!model::cutStroke(line, {QPointF(50, 0)}, std::nan("")));
    model::StrokeData dot;
    dot.points = {{10, 10, 1}};
    const auto gone = model::cutStroke(dot, {QPointF(12, 10)}, 3);
    QVERIFY(gone && gone->empty());
}

void TestStrokeCut::nearTheRubIsTheSameAsTheWholeStroke()
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> step(-4, 4), unit(0, 1);
    for (int trial = 0; trial < 200; ++trial) {
        model::StrokeData s;
        s.width = 1 + 8 * unit(rng);
        float x = 200, y = 200;
        for (int i = 0; i < 400; ++i) {
            s.points.push_back({x, y, unit(rng)});
            x += step(rng) + 1.5f;
            y += step(rng);
        }
        std::vector<QPointF> rub;
        const QPointF start(100 + 600 * unit(rng), 150 + 100 * unit(rng));
        for (int k = 0; k < 1 + trial % 5; ++k)
            rub.push_back(start + QPointF(30 * unit(rng), 30 * unit(rng)));
        const double radius = 1 + 10 * unit(rng);
        const auto cut = model::cutStroke(s, rub, radius);
        const auto expected = reference(s, rub, radius);
        if (!cut) {
            QCOMPARE(expected.size(), std::size_t(1));
            QCOMPARE(expected.front(), s.points);
            continue;
        }
        QCOMPARE(cut->size(), expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i)
            QCOMPARE((*cut)[i]->points, expected[i]);
    }
}

QTEST_APPLESS_MAIN(TestStrokeCut)
#include "tst_stroke_cut.moc"
