// drawTexturedMesh: a picture drawn through its mesh is the picture at rest, covers its posed
// outline exactly once (no cracks, no seams blended twice), and survives broken input.
#include <finbook/model/picture/textured_mesh.h>

#include <QImage>
#include <QRandomGenerator>
#include <QTransform>
#include <QtTest>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

using namespace finbook::model;

namespace {

// A grid mesh over [0, w] × [0, h] with cells of about `step` px (the last row and column
// end on the border), each cell split into two triangles along alternating diagonals.
struct Grid {
    Eigen::MatrixX2d V;
    Eigen::MatrixX3i F;
    int columns = 0, rows = 0; // vertices per row, per column
    std::vector<int> boundary; // the outer ring of vertex indices, in order
};

Grid grid(double w, double h, double step, Eigen::RowVector2d origin = {0, 0})
{
    Grid g;
    const int nx = std::max(1, int(std::ceil(w / step))),
              ny = std::max(1, int(std::ceil(h / step)));
    g.columns = nx + 1;
    g.rows = ny + 1;
    g.V.resize(g.columns * g.rows, 2);
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            g.V.row(j * g.columns + i) =
                origin + Eigen::RowVector2d(std::min(w, i * step), std::min(h, j * step));
    g.F.resize(2 * nx * ny, 3);
    int f = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const int a = j * g.columns + i, b = a + 1, c = a + g.columns, d = c + 1;
            if ((i + j) % 2) {
                g.F.row(f++) << a, b, d;
                g.F.row(f++) << a, d, c;
            } else {
                g.F.row(f++) << a, b, c;
                g.F.row(f++) << b, d, c;
            }
        }
    for (int i = 0; i <= nx; ++i)
        g.boundary.push_back(i);
    for (int j = 1; j <= ny; ++j)
        g.boundary.push_back(j * g.columns + nx);
    for (int i = nx - 1; i >= 0; --i)
        g.boundary.push_back(ny * g.columns + i);
    for (int j = ny - 1; j >= 1; --j)
        g.boundary.push_back(j * g.columns);
    return g;
}

// A painted RGBA picture: colour gradients, a soft-edged disc of alpha and a transparent hole.
QImage paintedPicture(int w, int h)
{
    QImage image(w, h, QImage::Format_ARGB32);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double d = std::hypot(x + 0.5 - w / 2.0, y + 0.5 - h / 2.0);
            const double edge = std::clamp(w * 0.45 - d, 0.0, 1.0);
            const double hole = std::clamp(d - w * 0.08, 0.0, 1.0);
            image.setPixel(x, y,
                           qRgba((x * 255) / w, (y * 255) / h, ((x ^ y) * 7) % 256,
                                 int(std::lround(255.0 * edge * hole))));
        }
    return image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
}

QImage transparentTarget(int w, int h)
{
    QImage target(w, h, QImage::Format_ARGB32_Premultiplied);
    target.fill(Qt::transparent);
    return target;
}

// PSNR (dB) over all channels of two same-sized premultiplied images; +inf when identical.
double psnr(const QImage &a, const QImage &b)
{
    double sum = 0.0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            for (const int d : {qRed(p) - qRed(q), qGreen(p) - qGreen(q), qBlue(p) - qBlue(q),
                                qAlpha(p) - qAlpha(q)})
                sum += double(d) * d;
        }
    const double mse = sum / (4.0 * a.width() * a.height());
    return mse == 0.0 ? std::numeric_limits<double>::infinity()
                      : 10.0 * std::log10(255.0 * 255.0 / mse);
}

// The largest channel difference of `a` and `b` (same size) over pixels at least `margin` px
// inside the picture.
int worstInside(const QImage &a, const QImage &b, int margin)
{
    int worst = 0;
    for (int y = margin; y < a.height() - margin; ++y)
        for (int x = margin; x < a.width() - margin; ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            worst = std::max({worst, std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                              std::abs(qBlue(p) - qBlue(q)), std::abs(qAlpha(p) - qAlpha(q))});
        }
    return worst;
}

// Signed distance-like test: whether (x, y) is inside the ring (even-odd) and how far it is from
// the ring's nearest edge.
std::pair<bool, double> insideRing(const Eigen::MatrixX2d &ring, double x, double y)
{
    bool inside = false;
    double nearest = std::numeric_limits<double>::max();
    const Eigen::Index n = ring.rows();
    for (Eigen::Index i = 0, j = n - 1; i < n; j = i++) {
        const double xi = ring(i, 0), yi = ring(i, 1), xj = ring(j, 0), yj = ring(j, 1);
        if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi)
            inside = !inside;
        const double dx = xj - xi, dy = yj - yi;
        const double t =
            std::clamp(((x - xi) * dx + (y - yi) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
        nearest = std::min(nearest, std::hypot(x - (xi + t * dx), y - (yi + t * dy)));
    }
    return {inside, nearest};
}

bool allTrianglesPositive(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F)
{
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const Eigen::RowVector2d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
        const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
        if (area <= 1.0)
            return false;
    }
    return true;
}

// Moves every vertex by up to `amount` px in x and y (seeded), keeping each triangle's winding.
Eigen::MatrixX2d perturbed(const Grid &g, double amount, quint32 seed)
{
    QRandomGenerator random(seed);
    for (int attempt = 0; attempt < 100; ++attempt) {
        Eigen::MatrixX2d V = g.V;
        for (Eigen::Index i = 0; i < V.rows(); ++i)
            V.row(i) += Eigen::RowVector2d(random.bounded(2.0 * amount) - amount,
                                           random.bounded(2.0 * amount) - amount);
        if (allTrianglesPositive(V, g.F))
            return V;
    }
    qFatal("no non-overlapping perturbation found");
}

Eigen::MatrixX2d ringOf(const Grid &g, const Eigen::MatrixX2d &V)
{
    Eigen::MatrixX2d ring(Eigen::Index(g.boundary.size()), 2);
    for (std::size_t i = 0; i < g.boundary.size(); ++i)
        ring.row(Eigen::Index(i)) = V.row(g.boundary[i]);
    return ring;
}

// Draws a flat opaque texture at half opacity through (V, F) onto a transparent target and
// checks that every pixel centre inside the ring got alpha ½ exactly once, and none outside.
void checkCoveredOnce(const Grid &g, const Eigen::MatrixX2d &V, const QTransform &view, int w,
                      int h)
{
    QImage flat(256, 256, QImage::Format_ARGB32_Premultiplied); // covers every uv used here
    flat.fill(qRgba(40, 80, 160, 255));
    QImage target = transparentTarget(w, h);
    drawTexturedMesh(target, view, flat, g.V, V, g.F, 0.5);
    const Eigen::MatrixX2d ring = ringOf(g, V);
    const QTransform back = view.inverted();
    int inside = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const QPointF c = back.map(QPointF(x + 0.5, y + 0.5));
            const auto [in, distance] = insideRing(ring, c.x(), c.y());
            const int alpha = qAlpha(target.pixel(x, y));
            QVERIFY2(alpha == 0 || alpha == 128,
                     qPrintable(QStringLiteral("alpha %1 at %2, %3").arg(alpha).arg(x).arg(y)));
            if (distance < 0.01)
                continue; // on the outline: either way
            QVERIFY2((alpha == 128) == in,
                     qPrintable(QStringLiteral("alpha %1 at %2, %3").arg(alpha).arg(x).arg(y)));
            inside += in;
        }
    QVERIFY(inside > 100);
}

} // namespace

class TestTexturedMesh : public QObject {
    Q_OBJECT
private slots:
    void restReproducesPicture();
    void posedCoversOutlineOnce();
    void edgesThroughPixelCentresCoveredOnce();
    void rigidPoseUndoneByViewIsOriginal();
    void posedThenRestIsOriginal();
    void bilinearAndPremultipliedEdges();
    void opacityAndSourceOver();
    void brokenInputSkipped();
    void drawingOrderKeepsTheTrianglesAndThePicture();
    void kernelsDrawTheSamePixels();
};

void TestTexturedMesh::restReproducesPicture()
{
    const QImage picture = paintedPicture(160, 120);
    for (const double step : {16.0, 7.3}) {
        const Grid g = grid(160, 120, step);
        QImage target = transparentTarget(160, 120);
        drawTexturedMesh(target, QTransform(), picture, g.V, g.V, g.F);
        const double db = psnr(target, picture);
        QVERIFY2(db >= 40.0, qPrintable(QString::number(db)));
        QCOMPARE(worstInside(target, picture, 2) <= 1, true);
        // Moved by whole pixels with the view, the same pixels land shifted.
        QImage shifted = transparentTarget(200, 150);
        drawTexturedMesh(shifted, QTransform::fromTranslate(20, 10), picture, g.V, g.V, g.F);
        QVERIFY(psnr(shifted.copy(20, 10, 160, 120), picture) >= 40.0);
        QCOMPARE(qAlpha(shifted.pixel(5, 5)), 0);
    }
    // Large enough to be drawn in two bands of rows by two threads: still the picture.
    const QImage large = paintedPicture(300, 280);
    const Grid g = grid(300, 280, 12.0);
    QImage target = transparentTarget(300, 280);
    drawTexturedMesh(target, QTransform(), large, g.V, g.V, g.F);
    QCOMPARE(target, large);
}

void TestTexturedMesh::posedCoversOutlineOnce()
{
    const Grid g = grid(96, 80, 8.0, {20.0, 16.0});
    for (const quint32 seed : {1u, 2u, 3u}) {
        const Eigen::MatrixX2d V = perturbed(g, 3.0, seed);
        checkCoveredOnce(g, V, QTransform(), 140, 120);
        // Through a rotating, scaling view too.
        QTransform view;
        view.translate(70, 10).rotate(23).scale(1.3, 1.1);
        checkCoveredOnce(g, V, view, 220, 220);
    }
}

void TestTexturedMesh::edgesThroughPixelCentresCoveredOnce()
{
    // Vertices on pixel centres: every grid line and diagonal passes through pixel centres,
    // where only the top-left rule decides which triangle owns them.
    const Grid g = grid(64, 48, 8.0, {10.5, 12.5});
    checkCoveredOnce(g, g.V, QTransform(), 90, 80);
    // A fan of thin triangles meeting at one pixel centre.
    Grid fan;
    const int spokes = 24;
    fan.V.resize(spokes + 1, 2);
    fan.V.row(0) << 40.5, 40.5;
    fan.F.resize(spokes, 3);
    for (int i = 0; i < spokes; ++i) {
        const double angle = 2.0 * M_PI * i / spokes;
        fan.V.row(i + 1) << 40.5 + std::round(30 * std::cos(angle)),
            40.5 + std::round(30 * std::sin(angle));
        fan.F.row(i) << 0, i + 1, (i + 1) % spokes + 1;
        fan.boundary.push_back(i + 1);
    }
    checkCoveredOnce(fan, fan.V, QTransform(), 80, 80);
}

void TestTexturedMesh::rigidPoseUndoneByViewIsOriginal()
{
    // The mesh turned and moved rigidly, seen through the inverse motion: the picture.
    const QImage picture = paintedPicture(128, 128);
    const Grid g = grid(128, 128, 10.0);
    QTransform pose;
    pose.translate(300, -40).rotate(31);
    Eigen::MatrixX2d V(g.V.rows(), 2);
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
        const QPointF p = pose.map(QPointF(g.V(i, 0), g.V(i, 1)));
        V.row(i) << p.x(), p.y();
    }
    QImage target = transparentTarget(128, 128);
    drawTexturedMesh(target, pose.inverted(), picture, g.V, V, g.F);
    QVERIFY(worstInside(target, picture, 2) <= 1);
    QVERIFY(psnr(target, picture) >= 40.0);
}

void TestTexturedMesh::posedThenRestIsOriginal()
{
    const QImage picture = paintedPicture(128, 96);
    const Grid g = grid(128, 96, 9.0);
    const Eigen::MatrixX2d posed = perturbed(g, 2.5, 7);
    QImage drawnPosed = transparentTarget(128, 96);
    drawTexturedMesh(drawnPosed, QTransform(), picture, g.V, posed, g.F);
    QVERIFY(psnr(drawnPosed, picture) < 30.0); // the pose shows
    // Back to rest the way an undo or in-between computes it: the rest plus a zero offset,
    // which leaves rounding noise in the last bits.
    const Eigen::MatrixX2d back = posed + (g.V - posed);
    QImage rest = transparentTarget(128, 96);
    drawTexturedMesh(rest, QTransform(), picture, g.V, back, g.F);
    QVERIFY(worstInside(rest, picture, 2) <= 1);
    QVERIFY(psnr(rest, picture) >= 40.0);
}

void TestTexturedMesh::bilinearAndPremultipliedEdges()
{
    // Two texels, opaque red and fully transparent, magnified 50×: the colour between them
    // fades in alpha only; unpremultiplied it stays red (no dark fringe).
    QImage texture(2, 1, QImage::Format_ARGB32_Premultiplied);
    texture.setPixel(0, 0, qRgba(255, 0, 0, 255));
    texture.setPixel(1, 0, qRgba(0, 0, 0, 0));
    Eigen::MatrixX2d uv(4, 2), V(4, 2);
    uv << 0, 0, 2, 0, 2, 1, 0, 1;
    V = uv * 50.0;
    Eigen::MatrixX3i F(2, 3);
    F << 0, 1, 2, 0, 2, 3;
    QImage target = transparentTarget(100, 50);
    drawTexturedMesh(target, QTransform(), texture, uv, V, F);
    int previous = 256;
    for (int x = 0; x < 100; ++x) {
        const QRgb c = target.pixel(x, 25);
        QVERIFY(qAlpha(c) <= previous); // falls monotonically from red to clear
        previous = qAlpha(c);
        QCOMPARE(qGreen(c), 0);
        QCOMPARE(qBlue(c), 0);
        QVERIFY(std::abs(qRed(c) - qAlpha(c)) <= 1); // premultiplied pure red
    }
    QCOMPARE(qAlpha(target.pixel(10, 25)), 255); // before the first centre: the edge texel
    QCOMPARE(qAlpha(target.pixel(90, 25)), 0);
    const int middle = qAlpha(target.pixel(50, 25)); // half way between the centres
    QVERIFY2(std::abs(middle - 128) <= 4, qPrintable(QString::number(middle)));
    // Beyond the texture's rectangle nothing is drawn even where the mesh reaches.
    Eigen::MatrixX2d wide = uv;
    wide.col(0) *= 1.5;
    QImage outside = transparentTarget(100, 50);
    drawTexturedMesh(outside, QTransform(), texture, wide, V, F);
    QCOMPARE(qAlpha(outside.pixel(95, 25)), 0);
    QCOMPARE(qAlpha(outside.pixel(5, 25)), 255);
}

void TestTexturedMesh::opacityAndSourceOver()
{
    QImage texture(4, 4, QImage::Format_ARGB32_Premultiplied);
    texture.fill(qRgba(0, 0, 200, 200)); // premultiplied blue, alpha 200
    Eigen::MatrixX2d uv(4, 2);
    uv << 0, 0, 4, 0, 4, 4, 0, 4;
    Eigen::MatrixX3i F(2, 3);
    F << 0, 1, 2, 0, 2, 3;
    QImage target(4, 4, QImage::Format_ARGB32_Premultiplied);
    target.fill(qRgba(255, 0, 0, 255));
    drawTexturedMesh(target, QTransform(), texture, uv, uv, F, 0.5);
    const QRgb c = target.pixel(2, 2);
    // source: 100/255 blue at alpha 100; over opaque red: red × (1 − 100/255).
    QVERIFY(std::abs(qAlpha(c) - 255) <= 1);
    QVERIFY(std::abs(qBlue(c) - 100) <= 1);
    QVERIFY(std::abs(qRed(c) - 155) <= 1);
    // A non-premultiplied target is converted, then drawn on.
    QImage plain(4, 4, QImage::Format_RGB32);
    plain.fill(qRgb(0, 255, 0));
    drawTexturedMesh(plain, QTransform(), texture, uv, uv, F);
    QCOMPARE(plain.format(), QImage::Format_ARGB32_Premultiplied);
    QVERIFY(std::abs(qBlue(plain.pixel(1, 1)) - 200) <= 1);
    QVERIFY(std::abs(qGreen(plain.pixel(1, 1)) - 55) <= 1);
}

void TestTexturedMesh::brokenInputSkipped()
{
    const QImage picture = paintedPicture(32, 32);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    Eigen::MatrixX2d uv(12, 2), V(12, 2);
    uv << 0, 0, 32, 0, 0, 32, 5, 5, 10, 10, 20, 20, // a good triangle, a collinear one
        0, 0, 32, 32, 0, 32, 1, 1, 2, 2, 3, 3;
    V = uv;
    V.row(6) << nan, 4;       // a NaN vertex
    V.row(7) << inf, 4;       // an infinite one
    V.row(9) << -5000, -5000; // a triangle far off the target
    V.row(10) << -5100, -5000;
    V.row(11) << -5000, -5100;
    Eigen::MatrixX3i F(9, 3);
    F << 3, 4, 5,  // collinear: no area
        6, 1, 2,   // NaN
        7, 1, 2,   // infinity
        9, 10, 11, // far away
        1, 1, 2,   // repeated vertex
        0, 1, 40,  // index out of range
        -1, 1, 2,  // negative index
        0, 1, 2,   // the good one
        8, 1, 6;   // NaN again, after it
    QImage target = transparentTarget(32, 32);
    drawTexturedMesh(target, QTransform(), picture, uv, V, F);
    // Only the good triangle (the upper left half) is drawn, and it is the picture there.
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const bool good = x + y + 1 < 32; // centre strictly inside the good triangle
            const bool outside = x + y + 1 > 32;
            if (good)
                QCOMPARE(target.pixel(x, y), picture.pixel(x, y));
            else if (outside)
                QCOMPARE(target.pixel(x, y), qRgba(0, 0, 0, 0));
        }
    // NaN uv, huge coordinates, a view that maps everything to NaN, mismatched sizes, null
    // images: nothing drawn, no crash.
    Eigen::MatrixX2d badUv = uv;
    badUv.row(0) << nan, 0;
    QImage untouched = transparentTarget(32, 32);
    Eigen::MatrixX3i one(1, 3);
    one << 0, 1, 2;
    drawTexturedMesh(untouched, QTransform(), picture, badUv, uv, one);
    Eigen::MatrixX2d huge = uv;
    huge.row(0) << 1e12, -1e12;
    drawTexturedMesh(untouched, QTransform(), picture, uv, huge, one);
    drawTexturedMesh(untouched, QTransform(nan, 0, 0, 1, 0, 0), picture, uv, uv, one);
    drawTexturedMesh(untouched, QTransform(), picture, uv.topRows(3), uv, one);
    drawTexturedMesh(untouched, QTransform(), QImage(), uv, uv, one);
    drawTexturedMesh(untouched, QTransform(), picture, uv, uv, one, nan);
    QImage none;
    drawTexturedMesh(none, QTransform(), picture, uv, uv, one);
    QVERIFY(none.isNull());
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            QCOMPARE(qAlpha(untouched.pixel(x, y)), 0);
    // A sliver holding no pixel centre draws nothing.
    Eigen::MatrixX2d sliver(3, 2);
    sliver << 10, 10, 10.2, 10, 10, 10.2;
    drawTexturedMesh(untouched, QTransform(), picture, uv.topRows(3), sliver, one);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            QCOMPARE(qAlpha(untouched.pixel(x, y)), 0);
    // A triangle covering the target many times over with a speck of a flat texture: every
    // pixel gets that colour (edge functions of 300,000 px stay exact).
    QImage flat(8, 8, QImage::Format_ARGB32_Premultiplied);
    flat.fill(qRgba(10, 20, 30, 255));
    Eigen::MatrixX2d big(3, 2), tiny(3, 2);
    big << -1e5, -1e5, 3e5, -1e5, -1e5, 3e5;
    tiny << 0, 0, 1e-4, 0, 0, 1e-4;
    drawTexturedMesh(untouched, QTransform(), flat, tiny, big, one);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            QCOMPARE(untouched.pixel(x, y), qRgba(10, 20, 30, 255));
}

void TestTexturedMesh::drawingOrderKeepsTheTrianglesAndThePicture()
{
    // A grid whose triangles come in a scrambled order, as a mesher's may.
    const Grid g = grid(200, 150, 10.0);
    Eigen::MatrixX3i scrambled = g.F;
    std::vector<Eigen::Index> rows(std::size_t(g.F.rows()));
    std::iota(rows.begin(), rows.end(), 0);
    std::mt19937 random(7);
    std::shuffle(rows.begin(), rows.end(), random);
    for (std::size_t r = 0; r < rows.size(); ++r)
        scrambled.row(Eigen::Index(r)) = g.F.row(rows[r]);
    const Eigen::MatrixX3i ordered = drawingOrder(g.V, scrambled);
    // The same triangles, each once, each with its corners in the same order.
    const auto sortedRows = [](const Eigen::MatrixX3i &F) {
        std::vector<std::array<int, 3>> out;
        for (Eigen::Index f = 0; f < F.rows(); ++f)
            out.push_back({F(f, 0), F(f, 1), F(f, 2)});
        std::sort(out.begin(), out.end());
        return out;
    };
    QCOMPARE(sortedRows(ordered), sortedRows(scrambled));
    // Band by band of 32 rows, left to right within a band.
    double lastBand = -1, lastX = -1;
    for (Eigen::Index f = 0; f < ordered.rows(); ++f) {
        const Eigen::RowVector2d centre =
            (g.V.row(ordered(f, 0)) + g.V.row(ordered(f, 1)) + g.V.row(ordered(f, 2))) / 3.0;
        const double band = std::floor(centre.y() / 32.0);
        QVERIFY(band > lastBand || (band == lastBand && centre.x() >= lastX));
        lastBand = band;
        lastX = centre.x();
    }
    // Posed (no folds), the picture drawn is the same pixel for pixel.
    const QImage picture = paintedPicture(200, 150);
    const Eigen::MatrixX2d V = perturbed(g, 2.5, 11);
    QImage a = transparentTarget(220, 170), b = transparentTarget(220, 170);
    drawTexturedMesh(a, QTransform::fromTranslate(5, 7), picture, g.V, V, scrambled);
    drawTexturedMesh(b, QTransform::fromTranslate(5, 7), picture, g.V, V, ordered);
    QCOMPARE(a, b);
    // A face out of range goes last, unchanged.
    Eigen::MatrixX3i broken = scrambled;
    broken.row(0) << 0, 1, int(g.V.rows()) + 5;
    const Eigen::MatrixX3i brokenOrdered = drawingOrder(g.V, broken);
    QCOMPARE(Eigen::RowVector3i(brokenOrdered.row(brokenOrdered.rows() - 1)),
             Eigen::RowVector3i(broken.row(0)));
}

void TestTexturedMesh::kernelsDrawTheSamePixels()
{
#if defined(__x86_64__)
    QVERIFY(texturedMeshKernelAvailable(TexturedMeshKernel::Sse2)); // every x86-64 has SSE2
#endif
    // A texture of random premultiplied pixels: opaque, translucent and clear ones mixed, and
    // whole opaque and clear patches (the wide kernels' shortcuts).
    std::mt19937 random(7);
    QImage texture(97, 83, QImage::Format_ARGB32_Premultiplied);
    for (int y = 0; y < texture.height(); ++y)
        for (int x = 0; x < texture.width(); ++x) {
            const bool patch = (x / 24 + y / 20) % 3 == 0, clear = (x / 24 + y / 20) % 3 == 1;
            const int a = patch ? 255 : clear && x % 5 ? 0 : int(random() % 256);
            texture.setPixel(x, y,
                             qRgba(int(random() % (a + 1)), int(random() % (a + 1)),
                                   int(random() % (a + 1)), a));
        }
    QImage background(230, 190, QImage::Format_ARGB32_Premultiplied);
    for (int y = 0; y < background.height(); ++y)
        for (int x = 0; x < background.width(); ++x) {
            const int a = x < 80 ? 255 : int(random() % 256);
            background.setPixel(x, y,
                                qRgba(int(random() % (a + 1)), int(random() % (a + 1)),
                                      int(random() % (a + 1)), a));
        }
    // The mesh reaches past the texture on two sides (clamped and clear samples), is posed
    // with folds, and is drawn magnified (long spans), shrunk, turned, and off the target's
    // right edge (spans that end at the last column).
    const Grid g = grid(105, 90, 9.0, {-4.0, -3.0});
    struct Case {
        QTransform view;
        double fold, opacity;
    };
    QTransform turned;
    turned.translate(120, -20).rotate(37).scale(1.7, 1.4);
    const std::array<Case, 5> cases = {{{QTransform::fromScale(2.3, 2.1), 0.0, 1.0},
                                        {QTransform::fromTranslate(150, 40), 6.0, 1.0},
                                        {turned, 3.0, 0.6},
                                        {QTransform::fromScale(0.55, 0.6), 2.0, 0.85},
                                        {QTransform(), 0.0, 1.0}}};
    int compared = 0;
    for (const Case &c : cases) {
        Eigen::MatrixX2d V = g.V;
        std::uniform_real_distribution<double> move(-c.fold, c.fold);
        for (Eigen::Index i = 0; i < V.rows(); ++i)
            V.row(i) += Eigen::RowVector2d(move(random), move(random));
        QImage reference = background;
        drawTexturedMesh(reference, c.view, texture, g.V, V, g.F, c.opacity,
                         TexturedMeshKernel::Scalar);
        QVERIFY(reference != background);
        for (const auto kernel :
             {TexturedMeshKernel::Sse2, TexturedMeshKernel::Avx2, TexturedMeshKernel::Automatic}) {
            if (!texturedMeshKernelAvailable(kernel))
                continue;
            QImage drawn = background;
            drawTexturedMesh(drawn, c.view, texture, g.V, V, g.F, c.opacity, kernel);
            for (int y = 0; y < drawn.height(); ++y)
                for (int x = 0; x < drawn.width(); ++x)
                    if (drawn.pixel(x, y) != reference.pixel(x, y))
                        QFAIL(qPrintable(QStringLiteral("kernel %1 differs at (%2, %3): %4 "
                                                        "against %5")
                                             .arg(int(kernel))
                                             .arg(x)
                                             .arg(y)
                                             .arg(drawn.pixel(x, y), 8, 16)
                                             .arg(reference.pixel(x, y), 8, 16)));
            ++compared;
        }
    }
    QVERIFY(compared >= int(cases.size())); // at least the automatic kernel each time
}

QTEST_GUILESS_MAIN(TestTexturedMesh)
#include "tst_textured_mesh.moc"
