// Lottie export (.json) and dotLottie (.lottie: the same JSON in a zip with a manifest).
//
// The file mirrors the scene. Each Finbook layer is a precomposition layer named after it, at
// its opacity (a precomposition is composited as a whole, as the canvas lays a translucent
// layer); every layer hangs under the camera of its depth (a null layer whose anchor, scale and
// rotation are cameraTransform's, keyed where the camera moves), and the cameras under the
// page (a null that scales the canvas to the output and centres it, as renderFrame does). The
// background is a solid under everything, the whole output as in a render through a camera.
//
// Inside a layer each object is a shape layer: its fills, their tones and its strokes as
// filled groups in painting order (a cut-out pose as its pieces, each piece's fills over the
// pieces below: paintLayers), every stroke as its pressure-following outline (lottie_shapes.h).
// A drawing held for several ticks is one shape layer that lasts them all. Where an object
// keeps its look's layout from one drawing to the next — the same items in the same colours
// with the same vertex counts, as a pose or an in-between of one drawing does — the drawings
// share one shape layer whose paths are keyed (hold keys: each drawing shows until the next),
// and a path that does not move is written once.
//
// A picture object's picture is an image layer under its shape layer (Lottie has no textured
// meshes): the picture as posed in each drawing, drawn at the output's scale into a PNG asset
// embedded in the file, each such picture once however often it shows (an unposed picture held
// through a scene is one asset).
//
// Numbers are canvas pixels rounded to 1/100, colours to 1/10000 (players that
// truncate still get the same 8-bit channel). No reference picture and no
// sound: Lottie has neither (the result's note says so when the document has them).
#include "decimal_text.h"
#include "export_formats.h"
#include "export_text.h"
#include "lottie_shapes.h"

#include <finbook/model/fill/fill_render.h>
#include <finbook/model/picture/picture_object.h>
#include <finbook/model/render.h>
#include <finbook/model/scene/shot.h>

#include <QBuffer>
#include <QCryptographicHash>
#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <quazip/quazip.h>
#include <quazip/quazipfile.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace finbook::model {

namespace {
// Drawings whose shapes take at least this many bytes are written once however often they show.
constexpr qsizetype kShareBytes = 2048;
// Far beyond any canvas, yet a number every player reads exactly.
constexpr double kLargest = 1e7;

void number(QByteArray &out, double value, int decimals = 2)
{
    appendDecimal(out, value, decimals, kLargest);
}

QByteArray numberText(double value, int decimals = 2)
{
    QByteArray out;
    number(out, value, decimals);
    return out;
}

void point(QByteArray &out, QPointF p)
{
    out += '[';
    number(out, p.x());
    out += ',';
    number(out, p.y());
    out += ']';
}

// A JSON string, escaped as Qt's JSON writer escapes it.
QByteArray string(const QString &text)
{
    const QByteArray list = QJsonDocument(QJsonArray{text}).toJson(QJsonDocument::Compact);
    return list.mid(1, list.size() - 2); // ["..."] without its brackets
}

QByteArray bezier(const BezierPath &path)
{
    QByteArray out = "{\"c\":true,\"v\":[";
    const auto list = [&](const std::vector<QPointF> &points) {
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (i)
                out += ',';
            point(out, points[i]);
        }
    };
    list(path.vertices);
    out += "],\"i\":[";
    list(path.in);
    out += "],\"o\":[";
    list(path.out);
    return out + "]}";
}

QByteArray staticValue(const QByteArray &value)
{
    return "{\"a\":0,\"k\":" + value + '}';
}

// Hold keys (each value stays until the next key); one value is written static.
QByteArray heldValue(const std::vector<std::pair<qint64, QByteArray>> &keys)
{
    if (keys.size() == 1)
        return staticValue(keys.front().second);
    QByteArray out = "{\"a\":1,\"k\":[";
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (i)
            out += ',';
        out += "{\"t\":" + QByteArray::number(keys[i].first) + ",\"s\":" + keys[i].second;
        if (i + 1 < keys.size()) // the last key lasts to the end anyway
            out += ",\"h\":1";
        out += '}';
    }
    return out + "]}";
}

struct Transform {
    QByteArray anchor = "[0,0]", position = "[0,0]", scale = "[100,100]", rotation = "0";
    QByteArray opacity = "100";
    bool animated = false; // the fields are already keyed values, not plain ones
};

QByteArray transformJson(const Transform &t)
{
    const auto value = [&](const QByteArray &v) { return t.animated ? v : staticValue(v); };
    return "{\"o\":" + staticValue(t.opacity) + ",\"r\":" + value(t.rotation) +
           ",\"p\":" + value(t.position) + ",\"a\":" + value(t.anchor) +
           ",\"s\":" + value(t.scale) + '}';
}

QByteArray colourJson(QRgb rgb)
{
    QByteArray out = "[";
    number(out, qRed(rgb) / 255.0, 4);
    out += ',';
    number(out, qGreen(rgb) / 255.0, 4);
    out += ',';
    number(out, qBlue(rgb) / 255.0, 4);
    return out + ",1]";
}

const QByteArray kGroupTransform =
    "{\"ty\":\"tr\",\"p\":{\"a\":0,\"k\":[0,0]},\"a\":{\"a\":0,\"k\":[0,0]},\"s\":{\"a\":0,\"k\":"
    "[100,100]},\"r\":{\"a\":0,\"k\":0},\"o\":{\"a\":0,\"k\":100}}";

// One filled item of an object's look: a fill, a tone or a stroke.
struct Item {
    QRgb color = 0;
    std::vector<BezierPath> paths;
};

// A picture as an image asset: its id and where its top-left corner lies (canvas px).
struct PictureRef {
    QByteArray asset;
    QPointF at;
};

// The pictures of an export as PNG assets drawn at `scale` output px per canvas px, each the
// same PNG once.
class PictureAssets {
public:
    explicit PictureAssets(double scale)
        : m_scale(scale)
    {}
    // The group's picture as it shows; nullopt when none of it shows or it cannot be drawn.
    std::optional<PictureRef> add(const StrokeGroup &group)
    {
        if (!group.picture || !pictureIsValid(*group.picture))
            return std::nullopt;
        // The same picture shown the same way again (a still picture in every drawing) is
        // not drawn and encoded again.
        const QByteArray seen = showingKey(group);
        if (const auto known = m_seen.find(seen); known != m_seen.end())
            return known.value();
        std::optional<PictureRef> made = draw(group);
        m_seen.insert(seen, made);
        return made;
    }
    // The assets' entries, comma-separated.
    const QByteArray &json() const { return m_json; }

private:
    // What decides how a group's picture shows: its pixels and mesh, its place and its pose.
    static QByteArray showingKey(const StrokeGroup &group)
    {
        const ObjectPicture &picture = *group.picture;
        QByteArray key;
        const auto add = [&key](const void *data, std::size_t bytes) {
            key.append(static_cast<const char *>(data), qsizetype(bytes));
        };
        const void *pointers[2] = {picture.data.get(), picture.mesh.get()};
        add(pointers, sizeof pointers);
        const qreal place[6] = {picture.place.m11(), picture.place.m12(), picture.place.m21(),
                                picture.place.m22(), picture.place.dx(),  picture.place.dy()};
        add(place, sizeof place);
        if (group.isDeformed()) {
            const DeformedStrokes &pose = *group.deformed;
            add(pose.pictureVertices.data(), pose.pictureVertices.size() * sizeof(QPointF));
            add(pose.pictureLayers.vertices.data(),
                pose.pictureLayers.vertices.size() * sizeof(QPointF));
            add(pose.pictureLayers.faces.data(),
                pose.pictureLayers.faces.size() * sizeof(std::array<int, 3>));
        }
        return key;
    }

    std::optional<PictureRef> draw(const StrokeGroup &group)
    {
        const QRectF shown = shownPictureBounds(group);
        if (!shown.isValid())
            return std::nullopt;
        const double left = std::floor(shown.left() * m_scale),
                     top = std::floor(shown.top() * m_scale);
        const double width = std::ceil(shown.right() * m_scale) - left,
                     height = std::ceil(shown.bottom() * m_scale) - top;
        if (!(width >= 1 && height >= 1 && width <= kMaxPictureSide && height <= kMaxPictureSide))
            return std::nullopt;
        QImage image(int(width), int(height), QImage::Format_ARGB32_Premultiplied);
        if (image.isNull())
            return std::nullopt;
        image.fill(Qt::transparent);
        drawPicture(
            image, QTransform::fromScale(m_scale, m_scale) * QTransform::fromTranslate(-left, -top),
            group);
        QByteArray png;
        QBuffer buffer(&png);
        if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG"))
            return std::nullopt;
        const QByteArray hash = QCryptographicHash::hash(png, QCryptographicHash::Sha256);
        auto id = m_ids.find(hash);
        if (id == m_ids.end()) {
            id = m_ids.insert(hash, "picture_" + QByteArray::number(m_ids.size() + 1));
            if (!m_json.isEmpty())
                m_json += ',';
            m_json += "{\"id\":\"" + *id + "\",\"w\":" + QByteArray::number(image.width()) +
                      ",\"h\":" + QByteArray::number(image.height()) +
                      ",\"u\":\"\",\"p\":\"data:image/png;base64," + png.toBase64() + "\",\"e\":1}";
        }
        return PictureRef{*id, QPointF(left / m_scale, top / m_scale)};
    }

    double m_scale;
    QHash<QByteArray, QByteArray> m_ids;                 // the PNG's SHA-256, its asset's id
    QHash<QByteArray, std::optional<PictureRef>> m_seen; // showingKey, what it drew
    QByteArray m_json;
};

// What an object shows in one drawing, in painting order: its picture, if any, under its items.
struct Look {
    Id id = kNoId;
    QString name;
    std::optional<PictureRef> picture;
    std::vector<Item> items;
    bool isEmpty() const { return items.empty() && !picture; }
};

Look lookOf(const StrokeGroup &group, const DocumentSettings &settings, PictureAssets &pictures)
{
    Look look{group.id, group.name, pictures.add(group), {}};
    // A posed stroke's rest points, by the posed points paintLayers paints.
    std::unordered_map<const std::vector<StrokePoint> *, const std::vector<StrokePoint> *> rest;
    for (std::size_t i = 0; group.isDeformed() && i < group.strokes.size(); ++i)
        if (group.strokes[i].data)
            rest[&displayedPoints(group, i)] = &group.strokes[i].data->points;
    for (const PaintLayer &layer : paintLayers(group, settings)) {
        for (const FillItem &fill : layer.fills) {
            look.items.push_back({fill.color, areaOutline(fill.path)});
            for (const ToneItem &tone : fill.tones)
                look.items.push_back({tone.color, areaOutline(tone.path.simplified())});
        }
        for (const PaintItem &stroke : layer.strokes)
            if (stroke.points) {
                // An opaque stroke's runs are groups of their own (rlottie drops stretches of a
                // long outline painted at once: lottie_shapes.h); a translucent one stays one
                // group, so where its runs overlap it is not painted twice.
                const auto atRest = rest.find(stroke.points);
                std::vector<BezierPath> runs = strokeOutline(
                    *stroke.points, stroke.width, atRest != rest.end() ? atRest->second : nullptr);
                if (qAlpha(stroke.color) < 255) {
                    look.items.push_back({stroke.color, std::move(runs)});
                    continue;
                }
                for (BezierPath &run : runs)
                    look.items.push_back({stroke.color, {std::move(run)}});
            }
    }
    std::erase_if(look.items, [](const Item &item) { return item.paths.empty(); });
    return look;
}

// Whether two looks can share a shape layer: the same items, colours and vertex layout.
bool sameLayout(const Look &a, const Look &b)
{
    if (a.items.size() != b.items.size() || a.picture.has_value() != b.picture.has_value())
        return false;
    for (std::size_t i = 0; i < a.items.size(); ++i) {
        const Item &x = a.items[i], &y = b.items[i];
        if (x.color != y.color || x.paths.size() != y.paths.size())
            return false;
        for (std::size_t k = 0; k < x.paths.size(); ++k)
            if (x.paths[k].vertices.size() != y.paths[k].vertices.size())
                return false;
    }
    return true;
}

// An object's shape layer in the making: the drawings it lasts and its paths' keys.
struct Run {
    qint64 start = 0, end = 0;
    Look layout;                                                               // the first look
    std::vector<std::vector<std::vector<std::pair<qint64, QByteArray>>>> keys; // item, path
    std::vector<std::pair<qint64, PictureRef>> pictures; // from which tick each shows
    void add(const Look &look, qint64 tick)
    {
        if (look.picture &&
            (pictures.empty() || pictures.back().second.asset != look.picture->asset ||
             pictures.back().second.at != look.picture->at))
            pictures.emplace_back(tick, *look.picture);
        keys.resize(look.items.size());
        for (std::size_t i = 0; i < look.items.size(); ++i) {
            keys[i].resize(look.items[i].paths.size());
            for (std::size_t k = 0; k < look.items[i].paths.size(); ++k) {
                QByteArray value = bezier(look.items[i].paths[k]);
                auto &pathKeys = keys[i][k];
                if (pathKeys.empty() || pathKeys.back().second != value)
                    pathKeys.emplace_back(tick, std::move(value));
            }
        }
    }
};

// An image layer under a shape layer: a picture from ip to op.
struct ImageShowing {
    qint64 ip = 0, op = 0;
    PictureRef picture;
};

struct ShapeLayer {
    QByteArray name;
    qint64 ip = 0, op = 0;
    QByteArray shapes;                // empty: an object with only a picture
    std::vector<ImageShowing> images; // under the shapes, in time order
    int segment = 0, slot = 0;        // the stretch of drawings and the place in it, back to front
};

ShapeLayer shapeLayerOf(const Run &run, int segment, int slot)
{
    ShapeLayer layer;
    layer.name =
        string(run.layout.name.trimmed().isEmpty() ? QStringLiteral("Object %1").arg(run.layout.id)
                                                   : run.layout.name.trimmed());
    layer.ip = run.start;
    layer.op = run.end;
    layer.segment = segment;
    layer.slot = slot;
    for (std::size_t k = 0; k < run.pictures.size(); ++k)
        layer.images.push_back({run.pictures[k].first,
                                k + 1 < run.pictures.size() ? run.pictures[k + 1].first : run.end,
                                run.pictures[k].second});
    if (run.layout.items.empty())
        return layer;
    // Lottie draws a layer's first shape on top: the items go in reverse painting order.
    QByteArray shapes = "[";
    for (std::size_t i = run.layout.items.size(); i-- > 0;) {
        const Item &item = run.layout.items[i];
        if (shapes.size() > 1)
            shapes += ',';
        shapes += "{\"ty\":\"gr\",\"it\":[";
        for (std::size_t k = 0; k < item.paths.size(); ++k) {
            auto keys = run.keys[i][k];
            if (keys.size() > 1) // a keyed path's value is a list of one path
                for (auto &key : keys)
                    key.second = '[' + key.second + ']';
            shapes += "{\"ty\":\"sh\",\"ks\":" + heldValue(keys) + "},";
        }
        shapes += "{\"ty\":\"fl\",\"c\":" + staticValue(colourJson(item.color)) +
                  ",\"o\":" + staticValue(numberText(qAlpha(item.color) / 2.55)) + ",\"r\":1},";
        shapes += kGroupTransform + "]}";
    }
    layer.shapes = shapes + ']';
    return layer;
}

// One Finbook layer through the export: its objects' shape layers as they close.
struct LayerTrack {
    Id id = kNoId;
    QString name;
    double opacity = 1.0, depth = 0.0;
    std::vector<Id> segmentKey; // the objects of the current stretch, back to front
    std::vector<Run> open;      // one per object of the stretch
    int segment = -1;
    std::vector<ShapeLayer> done;

    void closeAll()
    {
        for (std::size_t slot = 0; slot < open.size(); ++slot)
            done.push_back(shapeLayerOf(open[slot], segment, int(slot)));
        open.clear();
        segmentKey.clear();
    }
    void show(std::vector<Look> looks, qint64 start, qint64 end)
    {
        std::vector<Id> key;
        for (const Look &look : looks)
            key.push_back(look.id);
        if (key != segmentKey) { // other objects, or the layer showed nothing before
            closeAll();
            segmentKey = key;
            ++segment;
        }
        // Within a stretch the drawings follow one another, so a run goes on unless its
        // object's layout changed. A run not yet begun has no end.
        open.resize(looks.size());
        for (std::size_t slot = 0; slot < looks.size(); ++slot) {
            Run &run = open[slot];
            if (run.end != 0 && !sameLayout(run.layout, looks[slot])) {
                done.push_back(shapeLayerOf(run, segment, int(slot)));
                run = Run();
            }
            if (run.end == 0) {
                run.start = start;
                run.layout = looks[slot];
            }
            run.add(looks[slot], start);
            run.end = end;
        }
    }
};

// A layer with the properties the Lottie specification names for it, and "st" (its start
// time, which the specification gives precompositions only) on every layer: lottie-web reads it
// from each, and Bodymovin's "ddd":0 (2D), without which rlottie misplaces keyed transforms.
QByteArray layerJson(int ind, int type, const QByteArray &name, int parent, const Transform &ks,
                     qint64 ip, qint64 op, const QByteArray &extra)
{
    QByteArray out = "{\"ddd\":0,\"ind\":" + QByteArray::number(ind) +
                     ",\"ty\":" + QByteArray::number(type) + ",\"nm\":" + name;
    if (parent > 0)
        out += ",\"parent\":" + QByteArray::number(parent);
    out += type == 0 ? ",\"sr\":1,\"st\":0" : ",\"st\":0";
    out += ",\"ks\":" + transformJson(ks) + ",\"ao\":0" + extra +
           ",\"ip\":" + QByteArray::number(ip) + ",\"op\":" + QByteArray::number(op) + '}';
    return out;
}

QByteArray pair(double x, double y, int decimals = 2)
{
    return '[' + numberText(x, decimals) + ',' + numberText(y, decimals) + ']';
}

QByteArray layerKey(Id id)
{
    return "layer_" + QByteArray::number(id == kNoId ? 0 : id);
}
} // namespace

// The animation as Lottie JSON; empty when cancelled.
QByteArray lottieJson(const ExportContext &context)
{
    const ExportPlan &plan = context.plan;
    const DocumentSettings &settings = context.source.settings;
    const QSizeF canvas(settings.canvasSize);

    // Every Finbook layer, back to front: the source's order, then any other a frame names.
    std::vector<LayerTrack> tracks;
    const auto track = [&](Id id) -> LayerTrack & {
        for (LayerTrack &t : tracks)
            if (t.id == id)
                return t;
        LayerTrack t;
        t.id = id;
        tracks.push_back(std::move(t));
        return tracks.back();
    };
    for (const auto &[id, name] : context.source.layerNames) {
        track(id).name = name;
    }

    // The page: canvas pixels to output pixels, centred (renderFrame's fit).
    const double fit =
        std::min(plan.size.width() / canvas.width(), plan.size.height() / canvas.height());
    PictureAssets pictures(fit);

    qint64 tick = 0;
    for (std::size_t e = 0; e < plan.frames.size(); ++e) {
        if (context.cancelled(qint64(e), qint64(plan.frames.size())))
            return {};
        const Frame &frame = context.frame(e);
        const qint64 start = tick, end = tick + plan.holds[e];
        tick = end;
        // The same drawing again (a hold the camera moves through, split into ticks): what
        // shows lasts longer, nothing is worked out again.
        if (e > 0 && plan.frames[e] == plan.frames[e - 1]) {
            for (LayerTrack &t : tracks)
                for (Run &run : t.open)
                    if (run.end == start)
                        run.end = end;
            continue;
        }
        std::vector<FramePlane> planes = frame.planes;
        if (planes.empty()) // a plain layer's cel: one plane of everything
            planes.push_back({int(frame.groups.size()), 1.0, 0.0,
                              context.source.layerNames.size() == 1
                                  ? context.source.layerNames.front().first
                                  : kNoId});
        std::vector<Id> shown;
        int begin = 0;
        for (const FramePlane &plane : planes) {
            const int stop = std::clamp(plane.groupEnd, begin, int(frame.groups.size()));
            LayerTrack &t = track(plane.layer);
            t.opacity = std::clamp(plane.opacity, 0.0, 1.0);
            t.depth = std::isfinite(plane.depth) ? plane.depth : 0.0;
            std::vector<Look> looks;
            for (int g = begin; g < stop; ++g) {
                const StrokeGroup &group = frame.groups[std::size_t(g)];
                if (!group.visible)
                    continue;
                Look look = lookOf(group, settings, pictures);
                if (!look.isEmpty())
                    looks.push_back(std::move(look));
            }
            begin = stop;
            shown.push_back(plane.layer);
            if (looks.empty())
                t.closeAll();
            else
                t.show(std::move(looks), start, end);
        }
        for (LayerTrack &t : tracks) // layers that show nothing now
            if (std::find(shown.begin(), shown.end(), t.id) == shown.end())
                t.closeAll();
    }
    for (LayerTrack &t : tracks)
        t.closeAll();

    const qint64 ticks = plan.ticks;
    QByteArray assets, layers;
    int ind = 0;
    const int page = ++ind;
    Transform pageTransform;
    pageTransform.position = pair((plan.size.width() - canvas.width() * fit) / 2,
                                  (plan.size.height() - canvas.height() * fit) / 2);
    pageTransform.scale = pair(fit * 100, fit * 100, 4);
    QByteArray nulls = layerJson(page, 3, "\"Page\"", 0, pageTransform, 0, ticks, {});

    // A camera per depth, keyed where its view changes.
    std::map<double, int> cameras;
    const bool filmed = !plan.cameras.empty();
    for (const LayerTrack &t : tracks) {
        if (t.done.empty() || !filmed || cameras.count(t.depth))
            continue;
        const int camera = ++ind;
        cameras[t.depth] = camera;
        std::vector<std::pair<qint64, QByteArray>> anchor, scale, rotation;
        qint64 at = 0;
        for (std::size_t e = 0; e < plan.frames.size(); ++e) {
            const CameraState seen = planeCamera(plan.cameras[e], t.depth, canvas);
            const QByteArray a = pair(seen.center.x(), seen.center.y(), 3);
            const QByteArray s = pair(seen.zoom * 100, seen.zoom * 100, 4);
            const QByteArray r = '[' + numberText(seen.rotation, 4) + ']';
            if (anchor.empty() || anchor.back().second != a)
                anchor.emplace_back(at, a);
            if (scale.empty() || scale.back().second != s)
                scale.emplace_back(at, s);
            if (rotation.empty() || rotation.back().second != r)
                rotation.emplace_back(at, r);
            at += plan.holds[e];
        }
        if (rotation.size() == 1) // a static rotation is a plain number
            rotation.front().second = rotation.front().second.mid(1).chopped(1);
        Transform view;
        view.animated = true;
        view.anchor = heldValue(anchor);
        view.scale = heldValue(scale);
        view.rotation = heldValue(rotation);
        view.position = staticValue(pair(canvas.width() / 2, canvas.height() / 2));
        const QByteArray name = t.depth == 0.0
                                    ? QByteArray("\"Camera\"")
                                    : string(QStringLiteral("Camera (depth %1)").arg(t.depth));
        nulls += ',' + layerJson(camera, 3, name, page, view, 0, ticks, {});
    }

    // A precomposition per Finbook layer, front to back. Players clip a precomposition to its
    // size, so its content sits `margin` in from its corner (a null inside moves it there) and
    // the layer's anchor takes it back: what lies up to a canvas beyond the page still shows.
    const double margin = std::max(canvas.width(), canvas.height());
    const QSizeF compSize(canvas.width() + 2 * margin, canvas.height() + 2 * margin);
    QByteArray front;
    int layerNumber = 0;
    // A drawing shown more than once (a cycle played again, a drawing repeated after others)
    // is written once, as an asset of its own that each showing places (a precomposition,
    // `margin` in as the layers are): a walk cycle played four times costs one cycle.
    QHash<QByteArray, int> showings;
    for (const LayerTrack &t : tracks)
        for (const ShapeLayer &s : t.done)
            if (s.shapes.size() >= kShareBytes)
                ++showings[s.shapes];
    QHash<QByteArray, QByteArray> shared; // the shapes, the asset holding them
    const QByteArray compKeys =
        ",\"w\":" + numberText(compSize.width(), 0) + ",\"h\":" + numberText(compSize.height(), 0);
    Transform offset;
    offset.position = pair(margin, margin);
    Transform placedShared;
    placedShared.anchor = pair(margin, margin);
    for (auto t = tracks.rbegin(); t != tracks.rend(); ++t) {
        if (t->done.empty())
            continue;
        ++layerNumber;
        std::stable_sort(t->done.begin(), t->done.end(), [](const auto &a, const auto &b) {
            return a.segment != b.segment ? a.segment < b.segment : a.slot > b.slot;
        });
        QByteArray inner;
        inner += layerJson(1, 3, "\"Page\"", 0, offset, 0, ticks, {});
        int innerInd = 1;
        for (const ShapeLayer &s : t->done) {
            // The object's picture under its shapes: an image layer per pose, at the scale it
            // was drawn.
            const auto images = [&] {
                QByteArray out;
                for (const ImageShowing &image : s.images) {
                    Transform placed;
                    placed.position = pair(image.picture.at.x(), image.picture.at.y());
                    placed.scale = pair(100 / fit, 100 / fit, 4);
                    out += ',' + layerJson(++innerInd, 2, s.name, 1, placed, image.ip, image.op,
                                           ",\"refId\":\"" + image.picture.asset + '"');
                }
                return out;
            };
            if (s.shapes.isEmpty()) {
                inner += images();
                continue;
            }
            if (showings.value(s.shapes) < 2) {
                inner += ',' + layerJson(++innerInd, 4, s.name, 1, Transform(), s.ip, s.op,
                                         ",\"shapes\":" + s.shapes);
                inner += images();
                continue;
            }
            auto asset = shared.find(s.shapes);
            if (asset == shared.end()) {
                const QByteArray id = "drawing_" + QByteArray::number(shared.size() + 1);
                asset = shared.insert(s.shapes, id);
                if (!assets.isEmpty())
                    assets += ',';
                assets +=
                    "{\"id\":\"" + id + "\",\"nm\":" + s.name + ",\"layers\":[" +
                    layerJson(1, 3, "\"Page\"", 0, offset, 0, ticks, {}) + ',' +
                    layerJson(2, 4, s.name, 1, Transform(), 0, ticks, ",\"shapes\":" + s.shapes) +
                    "]}";
            }
            inner += ',' + layerJson(++innerInd, 0, s.name, 1, placedShared, s.ip, s.op,
                                     ",\"refId\":\"" + *asset + '"' + compKeys);
            inner += images();
        }
        if (!assets.isEmpty())
            assets += ',';
        assets +=
            "{\"id\":\"" + layerKey(t->id) + "\",\"nm\":" +
            string(t->name.isEmpty() ? QStringLiteral("Layer %1").arg(layerNumber) : t->name) +
            ",\"layers\":[" + inner + "]}";
        Transform placed;
        placed.anchor = pair(margin, margin);
        placed.opacity = numberText(t->opacity * 100);
        const auto camera = cameras.find(t->depth);
        const int parent = camera != cameras.end() ? camera->second : page;
        if (!front.isEmpty())
            front += ',';
        front += layerJson(
            ++ind, 0,
            string(t->name.isEmpty() ? QStringLiteral("Layer %1").arg(layerNumber) : t->name),
            parent, placed, 0, ticks, ",\"refId\":\"" + layerKey(t->id) + '"' + compKeys);
    }
    if (!pictures.json().isEmpty())
        assets += (assets.isEmpty() ? "" : ",") + pictures.json();
    layers = front;
    if (!layers.isEmpty())
        layers += ',';
    layers += nulls;
    if (!plan.transparent) {
        const QColor colour = QColor::fromRgb(plan.background);
        layers += ',' + layerJson(++ind, 1, "\"Background\"", 0, Transform(), 0, ticks,
                                  ",\"sc\":\"" + colour.name(QColor::HexRgb).toLatin1() +
                                      "\",\"sw\":" + QByteArray::number(plan.size.width()) +
                                      ",\"sh\":" + QByteArray::number(plan.size.height()));
    }
    QString title = context.options.title.trimmed();
    if (title.isEmpty())
        title = QFileInfo(context.options.target).completeBaseName();
    return "{\"v\":\"5.7.4\",\"fr\":" + QByteArray::number(plan.fps) +
           ",\"ip\":0,\"op\":" + QByteArray::number(ticks) +
           ",\"w\":" + QByteArray::number(plan.size.width()) +
           ",\"h\":" + QByteArray::number(plan.size.height()) + ",\"nm\":" + string(title) +
           ",\"meta\":{\"g\":\"Finbook\"},\"assets\":[" + assets + "],\"layers\":[" + layers +
           "]}\n";
}

namespace {
// The name of the animation inside a dotLottie file: the target's base name in the letters
// its identifiers allow.
QString animationId(const QString &target)
{
    QString id = QFileInfo(target).completeBaseName();
    id.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_-]")), QStringLiteral("_"));
    return id.isEmpty() ? QStringLiteral("animation") : id;
}

// A dotLottie container: manifest.json and animations/<id>.json, deflated. Empty on failure.
QByteArray dotLottie(const QByteArray &json, const QString &id, bool loop)
{
    QByteArray zipped;
    QBuffer buffer(&zipped);
    QuaZip zip(&buffer);
    if (!zip.open(QuaZip::mdCreate))
        return {};
    const QByteArray manifest =
        "{\"version\":\"1\",\"generator\":\"Finbook\",\"author\":\"\",\"animations\":[{\"id\":" +
        string(id) + ",\"speed\":1,\"loop\":" + (loop ? "true" : "false") +
        ",\"autoplay\":true,\"direction\":1,\"playMode\":\"normal\"}]}\n";
    const auto add = [&](const QString &name, const QByteArray &bytes) {
        QuaZipFile file(&zip);
        if (!file.open(QIODevice::WriteOnly, QuaZipNewInfo(name)))
            return false;
        const bool written = file.write(bytes) == bytes.size();
        file.close();
        return written && file.getZipError() == ZIP_OK;
    };
    if (!add(QStringLiteral("manifest.json"), manifest) ||
        !add(QStringLiteral("animations/%1.json").arg(id), json))
        return {};
    zip.close();
    if (zip.getZipError() != ZIP_OK)
        return {};
    return zipped;
}
} // namespace

ExportOutcome exportLottie(const ExportContext &context)
{
    const ExportOptions &options = context.options;
    const QString target = options.target;
    const auto written = writeSingleFile(options, [&]() -> Expected<QByteArray, ExportError> {
        QByteArray bytes = lottieJson(context);
        if (bytes.isEmpty())
            return unexpected(cancelledError());
        if (options.format == ExportFormat::DotLottie) {
            bytes = dotLottie(bytes, animationId(target), context.plan.loop);
            if (bytes.isEmpty())
                return unexpected(writeFailed(target, Export::tr("the zip container failed")));
        }
        return bytes;
    });
    if (written)
        return unexpected(*written);
    context.cancelled(qint64(context.plan.frames.size()), qint64(context.plan.frames.size()));

    ExportResult result;
    result.files << target;
    result.fileCount = 1;
    result.images = qint64(context.plan.frames.size());
    result.ticks = context.plan.ticks;
    result.size = context.plan.size;
    QStringList left;
    if (options.includeReference && !context.reference.isEmpty())
        left << Export::tr("Lottie has no place for the reference picture; it is left out.");
    if (!context.source.sound.empty())
        left << Export::tr("Lottie carries no sound; the soundtrack is left out.");
    result.note = left.join(QLatin1Char(' '));
    return result;
}

} // namespace finbook::model
