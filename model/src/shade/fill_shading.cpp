// Tone regions of shaded fills (shade/fill_shading.h).
#include "rest_shade.h"

#include <finbook/geometry/shade/pose.h>
#include <finbook/geometry/shade/shading.h>
#include <finbook/geometry/shade/tone_region.h>
#include <finbook/model/render.h>
#include <finbook/model/shade/fill_shading.h>

#include <QColor>

#include <algorithm>
#include <list>
#include <mutex>

namespace finbook::model {

namespace {
QRgb mix(QRgb a, QRgb b, double t)
{
    const auto channel = [t](int x, int y) { return int(std::lround(x + (y - x) * t)); };
    return qRgba(channel(qRed(a), qRed(b)), channel(qGreen(a), qGreen(b)),
                 channel(qBlue(a), qBlue(b)), qAlpha(a));
}

QPainterPath pathOf(const geometry::Pieces &pieces)
{
    QPainterPath path;
    path.setFillRule(Qt::WindingFill);
    path.reserve(int(pieces.points.size()) + 2 * pieces.count());
    for (int k = 0; k < pieces.count(); ++k) {
        const int begin = pieces.starts[std::size_t(k)], end = pieces.starts[std::size_t(k) + 1];
        const auto at = [&](int i) {
            return QPointF(pieces.points[std::size_t(i)].x(), pieces.points[std::size_t(i)].y());
        };
        path.moveTo(at(begin));
        for (int i = begin + 1; i < end; ++i)
            path.lineTo(at(i));
        path.closeSubpath();
    }
    return path;
}

struct PosedKey {
    const ObjectRegions *regions = nullptr;
    int face = -1;
    double density = 0.0;
    DeformedStrokesPtr pose; // held, so its address cannot be reused while cached
    FillShading shading;
    QRgb color = 0;
    double azimuth = 0.0, elevation = 0.0;
    bool operator==(const PosedKey &) const = default;
};
struct PosedEntry {
    PosedKey key;
    std::weak_ptr<const ObjectRegions> alive;
    std::vector<ToneItem> tones;
};
// A few hundred kB a face (its tone polygons): enough for playing a short scene from memory.
constexpr std::size_t kPosedEntries = 160;
std::mutex g_posedMutex;
std::list<PosedEntry> g_posed;

// The face's rings as shown (the tones are clipped to them).
std::vector<Eigen::MatrixX2d> ringsOf(const QPainterPath &path)
{
    std::vector<Eigen::MatrixX2d> rings;
    for (const QPolygonF &polygon : path.toSubpathPolygons()) {
        Eigen::MatrixX2d ring(polygon.size(), 2);
        for (qsizetype i = 0; i < polygon.size(); ++i)
            ring.row(Eigen::Index(i)) << polygon[i].x(), polygon[i].y();
        rings.push_back(std::move(ring));
    }
    return rings;
}

std::vector<ToneItem> computeTones(const StrokeGroup &group, const RestShade &rest,
                                   const QPainterPath &facePath, const FillShading &shading,
                                   QRgb color, const DocumentSettings &settings)
{
    const geometry::Inflation &inflation = rest.inflation;
    Eigen::MatrixX2d V = inflation.V;
    Eigen::MatrixX3d normals = inflation.normal;
    if (group.isDeformed()) {
        Eigen::MatrixX2d shown(Eigen::Index(rest.controls.size()), 2);
        for (std::size_t c = 0; c < rest.controls.size(); ++c) {
            const auto [stroke, point] = rest.controls[c];
            const std::vector<StrokePoint> &points = displayedPoints(group, std::size_t(stroke));
            const StrokePoint p =
                std::size_t(point) < points.size() ? points[std::size_t(point)] : StrokePoint{};
            shown.row(Eigen::Index(c)) << p.x, p.y;
        }
        const geometry::PosedPoints posed = geometry::applyPose(rest.weights, shown);
        V = posed.V;
        normals = geometry::rotateNormals(normals, posed.turn);
    }
    const Eigen::Vector3d light =
        geometry::lightDirection(settings.lightAzimuth, settings.lightElevation);
    const Eigen::VectorXd lit = geometry::diffuseTerm(normals, light);
    const std::vector<Eigen::MatrixX2d> clip = ringsOf(facePath);
    std::vector<ToneItem> tones;
    const auto add = [&](const Eigen::VectorXd &value, double from, QRgb tone) {
        QPainterPath path =
            pathOf(geometry::toneRegion(V, inflation.F, rest.edges, value, from, clip));
        if (!path.isEmpty())
            tones.push_back({std::move(path), tone});
    };
    switch (shading.ramp) {
    case ShadeRamp::Off:
        return {};
    case ShadeRamp::TwoTones:
        add(-lit, -kShadowBelow, shadowTone(color));
        break;
    case ShadeRamp::ThreeTones:
        add(-lit, -kShadowBelow, shadowTone(color));
        add(lit, kHighlightAbove, highlightTone(color));
        break;
    case ShadeRamp::Smooth:
        for (int level = 1; level < kSmoothLevels; ++level)
            add(lit, double(level) / kSmoothLevels,
                mix(shadowTone(color), highlightTone(color), double(level) / (kSmoothLevels - 1)));
        break;
    }
    if (shading.rim)
        add(geometry::rimTerm(normals, light), kRimFrom, rimTone(color));
    return tones;
}
} // namespace

QRgb shadowTone(QRgb color)
{
    QColor c = QColor::fromRgba(color).toHsv();
    const float h = c.hsvHueF(), s = c.hsvSaturationF(), v = c.valueF();
    c.setHsvF(h, std::min(1.0f, s * 1.1f), v * 0.62f, c.alphaF());
    return c.rgba();
}

QRgb highlightTone(QRgb color)
{
    return mix(color, qRgba(255, 255, 255, qAlpha(color)), 0.4);
}

QRgb rimTone(QRgb color)
{
    return mix(color, qRgba(255, 255, 255, qAlpha(color)), 0.65);
}

QRgb baseTone(QRgb color, const FillShading &shading)
{
    return shading.ramp == ShadeRamp::Smooth ? shadowTone(color) : color;
}

std::vector<ToneItem> faceTones(const StrokeGroup &group, const ObjectRegionsPtr &regions, int face,
                                const QPainterPath &facePath, const FillShading &shading,
                                QRgb color, const DocumentSettings &settings)
{
    if (!shading.shaded() || !regions || face < 0 || face >= regions->faceCount())
        return {};
    PosedKey key{
        regions.get(), face,  group.meshDensity,     group.isDeformed() ? group.deformed : nullptr,
        shading,       color, settings.lightAzimuth, settings.lightElevation};
    {
        std::lock_guard lock(g_posedMutex);
        for (auto it = g_posed.begin(); it != g_posed.end(); ++it)
            if (it->key == key && !it->alive.expired()) {
                g_posed.splice(g_posed.begin(), g_posed, it);
                return g_posed.front().tones;
            }
    }
    const RestShadePtr rest = restShade(group, regions, face);
    if (!rest)
        return {};
    std::vector<ToneItem> tones = computeTones(group, *rest, facePath, shading, color, settings);
    std::lock_guard lock(g_posedMutex);
    g_posed.push_front({std::move(key), regions, tones});
    if (g_posed.size() > kPosedEntries)
        g_posed.pop_back();
    return tones;
}

} // namespace finbook::model
