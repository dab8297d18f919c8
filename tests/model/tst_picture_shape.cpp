// The shape of a picture object: the rectangle of an opaque picture, the alpha outline of a
// cut-out one, and a flat background keyed out.
#include <finbook/geometry/polyline.h>
#include <finbook/geometry/region.h>
#include <finbook/model/picture/picture_shape.h>

#include <QImage>
#include <QPainter>
#include <QtTest>

using namespace finbook;
using namespace finbook::model;

class TestPictureShape : public QObject {
    Q_OBJECT
private slots:
    void opaquePictureIsItsRectangle();
    void cutOutPictureFollowsAlpha();
    void keyedOutBackground();
    void flatBackgroundIsFound();
};

void TestPictureShape::opaquePictureIsItsRectangle()
{
    QImage opaque(70, 40, QImage::Format_RGB32);
    opaque.fill(qRgb(10, 200, 30));
    QVERIFY(isFullyOpaque(opaque));
    const auto shape = pictureShape(opaque);
    QVERIFY(shape.hasValue());
    QCOMPARE(shape->size(), std::size_t(1));
    QCOMPARE(geometry::regionArea(*shape), 70.0 * 40.0); // exact, corners and all
    QVERIFY(geometry::signedArea((*shape)[0].outer) > 0.0);
    QCOMPARE((*shape)[0].outer.col(0).maxCoeff(), 70.0);
    QCOMPARE((*shape)[0].outer.col(1).maxCoeff(), 40.0);
    // An alpha channel that is everywhere 255 counts as opaque; one pixel less does not.
    QImage argb = opaque.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    QVERIFY(isFullyOpaque(argb));
    argb.setPixel(3, 3, qRgba(0, 0, 0, 254));
    QVERIFY(!isFullyOpaque(argb));
    QVERIFY(!isFullyOpaque(QImage()));
    QVERIFY(pictureShape(QImage())->empty());
}

void TestPictureShape::cutOutPictureFollowsAlpha()
{
    QImage picture(100, 80, QImage::Format_ARGB32_Premultiplied);
    picture.fill(Qt::transparent);
    QPainter painter(&picture);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(200, 50, 50));
    painter.drawEllipse(QPointF(50, 40), 30.0, 30.0);
    painter.end();
    QVERIFY(!isFullyOpaque(picture));
    const auto shape = pictureShape(picture);
    QVERIFY(shape.hasValue());
    QCOMPARE(shape->size(), std::size_t(1));
    const double area = geometry::regionArea(*shape);
    QVERIFY2(std::abs(area - M_PI * 900.0) < 0.02 * M_PI * 900.0,
             qPrintable(QString::number(area)));
    QVERIFY(geometry::regionContains(*shape, 50, 40));
    QVERIFY(!geometry::regionContains(*shape, 5, 5));
}

void TestPictureShape::keyedOutBackground()
{
    // A photo-like picture: a white background with a little noise, a dark square on it.
    QImage photo(60, 50, QImage::Format_RGB32);
    for (int y = 0; y < 50; ++y)
        for (int x = 0; x < 60; ++x) {
            const int noise = (x * 7 + y * 3) % 5; // 0..4
            photo.setPixel(x, y, qRgb(255 - noise, 252 - noise, 255 - noise));
        }
    for (int y = 10; y < 30; ++y)
        for (int x = 20; x < 45; ++x)
            photo.setPixel(x, y, qRgb(30, 60, 90));
    const QImage keyed = keyedOut(photo, qRgb(255, 255, 255), 8);
    QCOMPARE(keyed.format(), QImage::Format_ARGB32_Premultiplied);
    QCOMPARE(keyed.size(), photo.size());
    for (int y = 0; y < 50; ++y)
        for (int x = 0; x < 60; ++x) {
            const bool square = x >= 20 && x < 45 && y >= 10 && y < 30;
            QCOMPARE(keyed.pixel(x, y), square ? qRgb(30, 60, 90) : qRgba(0, 0, 0, 0));
        }
    // Tolerance 0 keys out only the exact colour; the noise keeps most of the background.
    const QImage exact = keyedOut(photo, qRgb(255, 252, 255), 0);
    QCOMPARE(qAlpha(exact.pixel(0, 0)), 0);   // noise 0: the key itself
    QCOMPARE(qAlpha(exact.pixel(1, 0)), 255); // noise 2
    // The keyed picture's shape is the square.
    const auto shape = pictureShape(keyed);
    QVERIFY(shape.hasValue());
    QCOMPARE(shape->size(), std::size_t(1));
    QVERIFY(std::abs(geometry::regionArea(*shape) - 25.0 * 20.0) < 1.0 + 0.5 * 90.0);
    QVERIFY(geometry::regionContains(*shape, 30, 20));
}

void TestPictureShape::flatBackgroundIsFound()
{
    QImage scan(100, 80, QImage::Format_RGB32);
    scan.fill(qRgb(250, 248, 240));
    {
        QPainter p(&scan);
        p.fillRect(QRect(20, 10, 60, 60), QColor(30, 30, 30));
        p.fillRect(QRect(0, 30, 10, 10), QColor(30, 30, 30)); // a line touching the edge
    }
    const auto found = flatBackground(scan);
    QVERIFY(found.has_value());
    QCOMPARE(*found, qRgb(250, 248, 240));
    // Corners of different colours: no flat background.
    QImage gradient(100, 80, QImage::Format_RGB32);
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 100; ++x)
            gradient.setPixel(x, y, qRgb(x * 2, y * 3, 100));
    QVERIFY(!flatBackground(gradient));
    // Corners alike but most of the border another colour (a photo whose corners happen to be
    // alike).
    QImage framed = scan;
    {
        QPainter p(&framed);
        p.fillRect(QRect(2, 0, 96, 80), QColor(30, 90, 30));
    }
    QVERIFY(!flatBackground(framed));
    // Transparency: the picture has a shape already.
    QImage clear(50, 50, QImage::Format_ARGB32_Premultiplied);
    clear.fill(Qt::transparent);
    QVERIFY(!flatBackground(clear));
    QVERIFY(!flatBackground(QImage()));
}

QTEST_GUILESS_MAIN(TestPictureShape)
#include "tst_picture_shape.moc"
