#include "inflate_sheet.h"

#include <QPainter>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace finbook::bench {
namespace {

constexpr int kTile = 240;  // px per rendering
constexpr int kLabel = 18;  // px of caption under each pair
constexpr int kColumns = 3; // pairs per row
constexpr double kMargin = 8.0;

// Canvas axes (y down), z toward the viewer: light from the upper left, in front.
const Eigen::Vector3d kLight = Eigen::Vector3d(-0.45, -0.6, 0.66).normalized();
const QColor kBase(226, 170, 128);

QRgb shade(double lambert, bool cel)
{
    double tone = 0.0;
    if (cel)
        tone = lambert > 0.75 ? 1.0 : lambert > 0.3 ? 0.7 : 0.42;
    else
        tone = 0.2 + 0.8 * std::max(0.0, lambert);
    return qRgb(int(kBase.red() * tone), int(kBase.green() * tone), int(kBase.blue() * tone));
}

// Rasterizes the mesh with normals interpolated per pixel (Phong), into image at x offset.
void render(const geometry::Inflation &in, QImage &image, int offsetX, bool cel)
{
    const Eigen::RowVector2d lo = in.V.colwise().minCoeff(), hi = in.V.colwise().maxCoeff();
    const double scale = (kTile - 2.0 * kMargin) / std::max((hi - lo).maxCoeff(), 1e-9);
    const Eigen::RowVector2d centre = 0.5 * (lo + hi);
    const auto toImage = [&](Eigen::Index v) {
        return Eigen::Vector2d((in.V(v, 0) - centre.x()) * scale + kTile / 2.0,
                               (in.V(v, 1) - centre.y()) * scale + kTile / 2.0);
    };
    for (Eigen::Index f = 0; f < in.F.rows(); ++f) {
        const Eigen::Vector2d a = toImage(in.F(f, 0)), b = toImage(in.F(f, 1)),
                              c = toImage(in.F(f, 2));
        const double area = (b - a).x() * (c - a).y() - (c - a).x() * (b - a).y();
        if (std::abs(area) < 1e-12)
            continue;
        const int x0 = std::max(0, int(std::floor(std::min({a.x(), b.x(), c.x()}))));
        const int x1 = std::min(kTile - 1, int(std::ceil(std::max({a.x(), b.x(), c.x()}))));
        const int y0 = std::max(0, int(std::floor(std::min({a.y(), b.y(), c.y()}))));
        const int y1 = std::min(kTile - 1, int(std::ceil(std::max({a.y(), b.y(), c.y()}))));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const Eigen::Vector2d p(x + 0.5, y + 0.5);
                const double wa = ((b - p).x() * (c - p).y() - (c - p).x() * (b - p).y()) / area;
                const double wb = ((c - p).x() * (a - p).y() - (a - p).x() * (c - p).y()) / area;
                const double wc = 1.0 - wa - wb;
                if (wa < 0.0 || wb < 0.0 || wc < 0.0)
                    continue;
                const Eigen::Vector3d n =
                    (wa * in.normal.row(in.F(f, 0)) + wb * in.normal.row(in.F(f, 1)) +
                     wc * in.normal.row(in.F(f, 2)))
                        .transpose()
                        .normalized();
                image.setPixel(offsetX + x, y, shade(n.dot(kLight), cel));
            }
        }
    }
}

} // namespace

void InflateSheet::add(const geometry::Inflation &inflation, const QString &label)
{
    QImage tile(2 * kTile, kTile + kLabel, QImage::Format_RGB32);
    tile.fill(Qt::white);
    render(inflation, tile, 0, false);
    render(inflation, tile, kTile, true);
    QPainter painter(&tile);
    painter.setPen(Qt::black);
    painter.drawText(QRect(0, kTile, 2 * kTile, kLabel), Qt::AlignCenter, label);
    painter.setPen(QColor(200, 200, 200));
    painter.drawLine(kTile, 0, kTile, kTile);
    m_tiles.push_back(tile);
}

bool InflateSheet::save(const QString &path) const
{
    if (m_tiles.empty())
        return false;
    const int rows = int((m_tiles.size() + kColumns - 1) / kColumns);
    QImage sheet(kColumns * 2 * kTile, rows * (kTile + kLabel), QImage::Format_RGB32);
    sheet.fill(QColor(235, 235, 235));
    QPainter painter(&sheet);
    for (std::size_t i = 0; i < m_tiles.size(); ++i)
        painter.drawImage(int(i % kColumns) * 2 * kTile, int(i / kColumns) * (kTile + kLabel),
                          m_tiles[i]);
    painter.end();
    return sheet.save(path);
}

} // namespace finbook::bench
