// Tone regions of shaded fills (shade/fill_shading.h).
#include "rest_shade.h"

#include <finbook/geometry/object_mesh.h>
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

// Taubin pairs on each tone's edge. The contour of a coarse mesh zigzags over a few crossings;
// three pairs took out only the shortest zigzags (two crossings long), and round heads showed
// a sawtooth (tst_fill_shading: 14 of 101 turns against the one before, 6 with ten pairs).
// Ten pairs still keep the curve (a Taubin pair neither shrinks nor grows it) and cost
// nothing next to tracing it.
constexpr geometry::ToneOptions kToneOptions{10};

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

// A face's shading mesh as shown (posed vertices and turned normals) and its outline rings:
// all that a pose decides, so a new light or ramp re-lights without posing again.
struct PosedShape {
    Eigen::MatrixX2d V;
    Eigen::MatrixX3d normals;
    std::vector<Eigen::MatrixX2d> clip;
};
using PosedShapePtr = std::shared_ptr<const PosedShape>;
struct ShapeKey {
    const ObjectRegions *regions = nullptr;
    int face = -1;
    double density = 0.0;
    DeformedStrokesPtr pose;
    bool operator==(const ShapeKey &) const = default;
};
struct ShapeEntry {
    ShapeKey key;
    std::weak_ptr<const ObjectRegions> alive;
    PosedShapePtr shape;
};
constexpr std::size_t kShapeEntries = 96; // a face's mesh as shown: about 50 kB
std::mutex g_shapeMutex;
std::list<ShapeEntry> g_shapes;

PosedShapePtr computeShape(const StrokeGroup &group, const RestShade &rest,
                           const QPainterPath &facePath)
{
    auto shape = std::make_shared<PosedShape>();
    const geometry::Inflation &inflation = rest.inflation;
    if (group.isDeformed()) {
        Eigen::MatrixX2d shown(Eigen::Index(rest.controls.size()), 2);
        for (std::size_t c = 0; c < rest.controls.size(); ++c) {
            const auto [stroke, point] = rest.controls[c];
            const std::vector<StrokePoint> &points = displayedPoints(group, std::size_t(stroke));
            const StrokePoint p =
                std::size_t(point) < points.size() ? points[std::size_t(point)] : StrokePoint{};
            shown.row(Eigen::Index(c)) << p.x, p.y;
        }
        geometry::PosedPoints posed = geometry::applyPose(rest.weights, shown, false);
        shape->V = std::move(posed.V);
        shape->normals = geometry::rotateNormals(inflation.normal, posed.turn);
    } else {
        shape->V = inflation.V;
        shape->normals = inflation.normal;
    }
    shape->clip = ringsOf(facePath);

    return shape;
}

PosedShapePtr posedShape(const StrokeGroup &group, const ObjectRegionsPtr &regions, int face,
                         const RestShade &rest, const QPainterPath &facePath)
{
    ShapeKey key{regions.get(), face, group.meshDensity,
                 group.isDeformed() ? group.deformed : nullptr};
    {
        std::lock_guard lock(g_shapeMutex);
        for (auto it = g_shapes.begin(); it != g_shapes.end(); ++it)
            if (it->key == key && !it->alive.expired()) {
                g_shapes.splice(g_shapes.begin(), g_shapes, it);
                return g_shapes.front().shape;
            }
    }
    PosedShapePtr shape = computeShape(group, rest, facePath);
    std::lock_guard lock(g_shapeMutex);
    g_shapes.push_front({std::move(key), regions, shape});
    if (g_shapes.size() > kShapeEntries)
        g_shapes.pop_back();
    return shape;
}

std::vector<ToneItem> computeTones(const RestShade &rest, const PosedShape &shape,
                                   const FillShading &shading, QRgb color,
                                   const DocumentSettings &settings)
{
    const geometry::Inflation &inflation = rest.inflation;
    const Eigen::MatrixX2d &V = shape.V;
    const Eigen::MatrixX3d &normals = shape.normals;
    const std::vector<Eigen::MatrixX2d> &clip = shape.clip;
    const Eigen::Vector3d light =
        geometry::lightDirection(settings.lightAzimuth, settings.lightElevation);
    const Eigen::VectorXd lit = geometry::diffuseTerm(normals, light);
    std::vector<ToneItem> tones;
    const auto add = [&](const Eigen::VectorXd &value, double from, QRgb tone) {
        QPainterPath path = pathOf(
            geometry::toneRegion(V, inflation.F, rest.edges, value, from, clip, kToneOptions));
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
    const PosedShapePtr shape = posedShape(group, regions, face, *rest, facePath);
    std::vector<ToneItem> tones = computeTones(*rest, *shape, shading, color, settings);
    std::lock_guard lock(g_posedMutex);
    g_posed.push_front({std::move(key), regions, tones});
    if (g_posed.size() > kPosedEntries)
        g_posed.pop_back();
    return tones;
}

qint64 shadingVertexEstimate(const Frame &frame)
{
    geometry::MeshOptions options;
    qint64 total = 0;
    for (const StrokeGroup &group : frame.groups) {
        if (!group.visible)
            continue;
        const double density = group.meshDensity > 0.0 ? std::min(group.meshDensity, 100.0) : 1.0;
        const double perFace =
            std::min(double(options.maxVertices), kShadeTargetVertices * density * density);
        for (const Fill &fill : group.fills)
            if (fill.shading.shaded())
                total += qint64(perFace);
    }
    return total;
}

} // namespace finbook::model
