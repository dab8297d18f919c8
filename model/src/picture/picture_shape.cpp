// isFullyOpaque, keyedOut and pictureShape: from a picture's pixels to the shape that is meshed.
#include <finbook/model/picture/picture_shape.h>

#include <algorithm>
#include <cstdlib>

namespace finbook::model {

bool isFullyOpaque(const QImage &image)
{
    if (image.isNull())
        return false;
    if (!image.hasAlphaChannel())
        return true;
    const QImage argb = image.format() == QImage::Format_ARGB32_Premultiplied ||
                                image.format() == QImage::Format_ARGB32
                            ? image
                            : image.convertToFormat(QImage::Format_ARGB32);
    for (int y = 0; y < argb.height(); ++y) {
        const auto *line = reinterpret_cast<const QRgb *>(argb.constScanLine(y));
        for (int x = 0; x < argb.width(); ++x)
            if (qAlpha(line[x]) != 255)
                return false;
    }
    return true;
}

QImage keyedOut(const QImage &image, QRgb background, int tolerance)
{
    QImage out = image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
    if (out.isNull())
        return out;
    tolerance = std::clamp(tolerance, 0, 255);
    const auto near = [&](int a, int b) { return std::abs(a - b) <= tolerance; };
    for (int y = 0; y < out.height(); ++y) {
        auto *line = reinterpret_cast<QRgb *>(out.scanLine(y));
        for (int x = 0; x < out.width(); ++x) {
            if (qAlpha(line[x]) == 0)
                continue;
            const QRgb c = qUnpremultiply(line[x]);
            if (near(qRed(c), qRed(background)) && near(qGreen(c), qGreen(background)) &&
                near(qBlue(c), qBlue(background)))
                line[x] = 0;
        }
    }
    return out;
}

std::optional<QRgb> flatBackground(const QImage &image)
{
    if (image.isNull() || image.width() < 2 || image.height() < 2 || !isFullyOpaque(image))
        return std::nullopt;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    const auto near = [](QRgb a, QRgb b, int tolerance) {
        return std::abs(qRed(a) - qRed(b)) <= tolerance &&
               std::abs(qGreen(a) - qGreen(b)) <= tolerance &&
               std::abs(qBlue(a) - qBlue(b)) <= tolerance;
    };
    const int w = rgb.width(), h = rgb.height();
    const QRgb corner = rgb.pixel(0, 0);
    for (const QPoint p : {QPoint(w - 1, 0), QPoint(0, h - 1), QPoint(w - 1, h - 1)})
        if (!near(rgb.pixel(p), corner, 8))
            return std::nullopt;
    qint64 border = 0, same = 0;
    const auto count = [&](int x, int y) {
        ++border;
        same += near(rgb.pixel(x, y), corner, 16) ? 1 : 0;
    };
    for (int x = 0; x < w; ++x) {
        count(x, 0);
        count(x, h - 1);
    }
    for (int y = 1; y < h - 1; ++y) {
        count(0, y);
        count(w - 1, y);
    }
    if (same * 5 < border * 4)
        return std::nullopt;
    return qRgb(qRed(corner), qGreen(corner), qBlue(corner));
}

Expected<geometry::Region, geometry::GeometryError>
pictureShape(const QImage &image, const geometry::AlphaOutlineOptions &options)
{
    if (image.isNull() || image.width() <= 0 || image.height() <= 0)
        return geometry::Region{};
    if (isFullyOpaque(image)) {
        const double w = image.width(), h = image.height();
        Eigen::MatrixX2d rectangle(4, 2);
        // Positive shoelace area on the y-down coordinates as given (region.h).
        rectangle << 0, 0, w, 0, w, h, 0, h;
        return geometry::Region{geometry::Polygon{rectangle, {}}};
    }
    const QImage alpha = image.convertToFormat(QImage::Format_Alpha8);
    if (alpha.isNull())
        return unexpected(geometry::GeometryError{geometry::GeometryErrorCode::InvalidOptions,
                                                  "There is not enough memory for the outline."});
    return geometry::traceAlphaOutline(alpha.constBits(), alpha.width(), alpha.height(),
                                       long(alpha.bytesPerLine()), 1, options);
}

} // namespace finbook::model
