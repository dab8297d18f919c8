// FINBOOK_KEEP_PICTURES=DIR keeps both pictures of every tick that agrees less than 98 %.
//
// The Lottie export played by a real Lottie player: Samsung's rlottie renders every frame of the
// exported file and each is compared with Finbook's own export of the same tick (a pixel agrees
// when each channel is within 24/255; anti-aliased edges may differ). Also the file's shape:
// holds as durations, a pose as one keyed layer, the scene's layers and camera, dotLottie's zip.
#include "lottie_support.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/export/exporter.h>

#include <QTemporaryDir>
#include <QtTest>
#include <quazip/quazip.h>
#include <quazip/quazipfile.h>

#include <rlottie_capi.h>

using namespace finbook;
using namespace finbook::test;

namespace {

// rlottie's picture of frame `frame` at `size`, or a null image when it cannot load the file.
class Player {
public:
    explicit Player(const QByteArray &json)
    {
        static int loaded = 0; // rlottie caches by key: a new key for every file
        const QByteArray key = "finbook-test-" + QByteArray::number(++loaded);
        m_animation = lottie_animation_from_data(json.constData(), key.constData(), "");
    }
    ~Player()
    {
        if (m_animation)
            lottie_animation_destroy(m_animation);
    }
    Player(const Player &) = delete;
    Player &operator=(const Player &) = delete;
    bool loaded() const { return m_animation != nullptr; }
    std::size_t frames() const { return lottie_animation_get_totalframe(m_animation); }
    double fps() const { return lottie_animation_get_framerate(m_animation); }
    QImage render(std::size_t frame, QSize size) const
    {
        QImage image(size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::transparent);
        lottie_animation_render(m_animation, frame, reinterpret_cast<uint32_t *>(image.bits()),
                                std::size_t(size.width()), std::size_t(size.height()),
                                std::size_t(image.bytesPerLine()));
        return image;
    }

private:
    Lottie_Animation *m_animation = nullptr;
};

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

struct Played {
    double worst = 1.0, worstInk = 1.0;
    qint64 worstTick = -1;
    double inkRatio = 1.0; // the player's ink over Finbook's, the furthest from 1 of any tick
};

// Exports `source` as Lottie to `path` and compares every tick rlottie plays with Finbook's.
Played playAndCompare(const model::ExportSource &source, model::ExportOptions o,
                      const QString &path)
{
    o.format = model::ExportFormat::Lottie;
    o.target = path;
    const auto result = model::exportAnimation(source, o);
    if (!result) {
        qWarning("%s", qPrintable(result.error().message));
        return {0, 0, -1};
    }
    const auto plan = model::planExport(source, o);
    Player player(readAll(path));
    if (!player.loaded() || qint64(player.frames()) != plan->ticks) {
        qWarning("rlottie: loaded %d, %zu frames for %lld ticks", player.loaded(),
                 player.loaded() ? player.frames() : 0, plan->ticks);
        return {0, 0, -1};
    }
    Played played;
    for (qint64 tick = 0; tick < plan->ticks; ++tick) {
        const QImage ours = finbookFrame(source, *plan, tick);
        const QImage theirs = player.render(std::size_t(tick), plan->size);
        const double all = agreement(ours, theirs);
        const double ink =
            inkAgreement(ours, theirs, plan->transparent ? 0u : (plan->background | 0xff000000u));
        if (all < played.worst) {
            played.worst = all;
            played.worstTick = tick;
        }
        played.worstInk = std::min(played.worstInk, ink);
        const QRgb bg = plan->transparent ? 0u : (plan->background | 0xff000000u);
        const double ratio = inkOf(theirs, bg) / std::max(1e-9, inkOf(ours, bg));
        if (std::abs(std::log(ratio)) > std::abs(std::log(played.inkRatio)))
            played.inkRatio = ratio;
        if (all < 0.98 && qEnvironmentVariableIsSet("FINBOOK_KEEP_PICTURES")) {
            const QString keep = qEnvironmentVariable("FINBOOK_KEEP_PICTURES") + QLatin1Char('/') +
                                 QFileInfo(path).completeBaseName();
            ours.save(keep + QStringLiteral(".tick%1.finbook.png").arg(tick));
            theirs.save(keep + QStringLiteral(".tick%1.rlottie.png").arg(tick));
        }
    }
    return played;
}

// One drawing on the small page exported to `path` and played (playAndCompare).
Played playDrawing(const model::Frame &drawing, const QString &path,
                   const model::ExportOptions &options = {})
{
    model::ExportSource source;
    source.settings = smallPage();
    source.frames = {drawing};
    return playAndCompare(source, options, path);
}

// The shape layers and nulls inside the first Finbook layer's precomposition.
QJsonArray innerLayers(const QString &path)
{
    return readJson(path)[QStringLiteral("assets")]
        .toArray()[0]
        .toObject()[QStringLiteral("layers")]
        .toArray();
}

int countLayers(const QJsonArray &layers, int type)
{
    int n = 0;
    for (const QJsonValue &l : layers)
        n += l.toObject()[QStringLiteral("ty")].toInt() == type;
    return n;
}

} // namespace

class TestExportLottie : public QObject {
    Q_OBJECT
private slots:
    void exampleMatchesEveryTick();
    void pressureStrokesMatch();
    void nestedFillsMatch();
    void shadedFillsMatch();
    void holdsAreDurations();
    void aPoseIsOneKeyedLayer();
    void aCycleIsWrittenOnce();
    void layersAndCameraMatch();
    void dotLottieHoldsTheSameAnimation();
    void cancelledLeavesNothing();
    void picturesArePosedImages();
};

void TestExportLottie::exampleMatchesEveryTick()
{
    QTemporaryDir dir;
    const model::ExportSource source = exampleWithHolds(); // 12 drawings, 18 ticks
    QVERIFY(!source.frames.empty());
    const QString path = dir.filePath(QStringLiteral("walk.json"));
    model::ExportOptions o;
    const Played played = playAndCompare(source, o, path);
    qInfo("walk: worst tick %lld agrees %.2f %% (drawing alone %.2f %%), ink ratio %.3f",
          played.worstTick, 100 * played.worst, 100 * played.worstInk, played.inkRatio);
    QVERIFY2(played.worst >= 0.98, qPrintable(QString::number(played.worst)));
    // The drawing itself, not only the empty page around it: its pixels agree (its lines are
    // 1–2 px wide, so most of them are anti-aliased edges) and it holds as much ink.
    QVERIFY(played.worstInk >= 0.85);
    QVERIFY2(std::abs(played.inkRatio - 1.0) < 0.05, qPrintable(QString::number(played.inkRatio)));

    // Holds are durations: a shape layer per object and drawing, not per tick.
    const QJsonObject json = readJson(path);
    QCOMPARE(json[QStringLiteral("op")].toInt(), 18);
    QCOMPARE(json[QStringLiteral("fr")].toInt(), source.settings.fps);
    const QJsonArray assets = json[QStringLiteral("assets")].toArray();
    QCOMPARE(assets.size(), 1); // one layer
    int objects = 0;
    for (const model::Frame &f : source.frames)
        for (const model::StrokeGroup &g : f.groups)
            objects += g.visible && !g.strokes.empty();
    const QJsonArray inner = assets[0].toObject()[QStringLiteral("layers")].toArray();
    QVERIFY(countLayers(inner, 4) <= objects);
    QVERIFY(countLayers(inner, 4) >= 12);
}

void TestExportLottie::pressureStrokesMatch()
{
    QTemporaryDir dir;
    model::ExportOptions o;
    o.scale = 2.0; // the widths' detail at twice the size
    o.transparent = true;
    const Played played =
        playDrawing(pressureStrokes(), dir.filePath(QStringLiteral("pen.json")), o);
    qInfo("pressure strokes, transparent, 2x: agree %.2f %% (ink %.2f %%), ink ratio %.3f",
          100 * played.worst, 100 * played.worstInk, played.inkRatio);
    QVERIFY(played.worst >= 0.98);
    QVERIFY2(played.worstInk >= 0.95, qPrintable(QString::number(played.worstInk)));
    QVERIFY(std::abs(played.inkRatio - 1.0) < 0.03);
}

void TestExportLottie::nestedFillsMatch()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("fills.json"));
    const Played played = playDrawing(nestedFills(), path);
    qInfo("nested fills: agree %.2f %% (ink %.2f %%)", 100 * played.worst, 100 * played.worstInk);
    QVERIFY(played.worst >= 0.98);
    QVERIFY(played.worstInk >= 0.97);
    // The hole shows its own colour, the ring its own: both fills made it.
    Player player(readAll(path));
    const QImage shown = player.render(0, smallPage().canvasSize);
    const auto near = [](QRgb a, QRgb b) { // players round colours their own way
        return std::abs(qRed(a) - qRed(b)) <= 2 && std::abs(qGreen(a) - qGreen(b)) <= 2 &&
               std::abs(qBlue(a) - qBlue(b)) <= 2;
    };
    QVERIFY(near(shown.pixel(200, 150), 0xfff0c020));
    QVERIFY(near(shown.pixel(90, 70), 0xff4080e0));
}

void TestExportLottie::shadedFillsMatch()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("shaded.json"));
    const Played played = playDrawing(shadedBody(), path);
    qInfo("shaded fill: agree %.2f %% (ink %.2f %%)", 100 * played.worst, 100 * played.worstInk);
    QVERIFY(played.worst >= 0.98);
    QVERIFY(played.worstInk >= 0.97);
    // The tones are fills of their own over the base colour: more than one fill colour.
    QSet<QString> colours;
    for (const QJsonValue &l : innerLayers(path))
        for (const QJsonValue &group : l.toObject()[QStringLiteral("shapes")].toArray())
            for (const QJsonValue &item : group.toObject()[QStringLiteral("it")].toArray())
                if (item.toObject()[QStringLiteral("ty")].toString() == QLatin1String("fl"))
                    colours.insert(QJsonDocument(item.toObject()[QStringLiteral("c")].toObject())
                                       .toJson(QJsonDocument::Compact));
    QVERIFY2(colours.size() >= 4, qPrintable(QString::number(colours.size()))); // ink, base, tones
}

void TestExportLottie::holdsAreDurations()
{
    QTemporaryDir dir;
    model::ExportSource source;
    source.settings = smallPage();
    model::Frame a = nestedFills(), b = pressureStrokes(), c = nestedFills();
    a.hold = 1;
    b.hold = 5;
    c.hold = 2;
    c.groups.front().fills.front().color = 0xff30a030;
    source.frames = {a, b, c};
    const QString path = dir.filePath(QStringLiteral("holds.json"));
    const Played played = playAndCompare(source, {}, path);
    QVERIFY(played.worst >= 0.98);
    QCOMPARE(readJson(path)[QStringLiteral("op")].toInt(), 8);
    const QJsonArray inner = innerLayers(path);
    // One shape layer per drawing, lasting its hold.
    std::vector<std::pair<int, int>> spans;
    for (const QJsonValue &l : inner)
        if (l.toObject()[QStringLiteral("ty")].toInt() == 4)
            spans.emplace_back(l.toObject()[QStringLiteral("ip")].toInt(),
                               l.toObject()[QStringLiteral("op")].toInt());
    std::sort(spans.begin(), spans.end());
    QCOMPARE(spans.size(), std::size_t(3));
    QCOMPARE(spans[0], std::make_pair(0, 1));
    QCOMPARE(spans[1], std::make_pair(1, 6));
    QCOMPARE(spans[2], std::make_pair(6, 8));
}

void TestExportLottie::aPoseIsOneKeyedLayer()
{
    // Six drawings of one object whose strokes keep their points, turned a little more each
    // time (as a pose or an in-between does): one shape layer with keyed paths.
    QTemporaryDir dir;
    model::ExportSource source;
    source.settings = smallPage();
    const model::Frame rest = pressureStrokes();
    for (int i = 0; i < 6; ++i) {
        model::Frame f = rest;
        f.id = 60 + i;
        QTransform turn;
        turn.translate(200, 150).rotate(6.0 * i).translate(-200, -150);
        for (model::Stroke &s : f.groups.front().strokes) {
            auto moved = std::make_shared<model::StrokeData>(*s.data);
            for (model::StrokePoint &p : moved->points) {
                const QPointF q = turn.map(QPointF(p.x, p.y));
                p.x = float(q.x());
                p.y = float(q.y());
            }
            s.data = moved;
        }
        source.frames.push_back(f);
    }
    const QString path = dir.filePath(QStringLiteral("pose.json"));
    const Played played = playAndCompare(source, {}, path);
    qInfo("turning pose: agree %.2f %% (ink %.2f %%)", 100 * played.worst, 100 * played.worstInk);
    QVERIFY(played.worst >= 0.98);
    const QJsonArray inner = innerLayers(path);
    QCOMPARE(countLayers(inner, 4), 1);
    // Its paths carry a key per drawing.
    int keyed = 0;
    for (const QJsonValue &l : inner) {
        for (const QJsonValue &group : l.toObject()[QStringLiteral("shapes")].toArray())
            for (const QJsonValue &item : group.toObject()[QStringLiteral("it")].toArray()) {
                const QJsonObject shape = item.toObject();
                if (shape[QStringLiteral("ty")].toString() != QLatin1String("sh"))
                    continue;
                const QJsonObject ks = shape[QStringLiteral("ks")].toObject();
                QCOMPARE(ks[QStringLiteral("a")].toInt(), 1);
                QCOMPARE(ks[QStringLiteral("k")].toArray().size(), 6);
                ++keyed;
            }
    }
    QVERIFY(keyed >= int(rest.groups.front().strokes.size()));
    // Smaller than six separate drawings would be.
    model::ExportSource apart = source;
    for (std::size_t i = 0; i < apart.frames.size(); ++i)
        apart.frames[i].groups.front().id = model::Id(900 + i);
    model::ExportOptions o;
    o.format = model::ExportFormat::Lottie;
    o.target = dir.filePath(QStringLiteral("apart.json"));
    QVERIFY(model::exportAnimation(apart, o));
    const qint64 keyedBytes = QFileInfo(path).size(), apartBytes = QFileInfo(o.target).size();
    qInfo("keyed: %lld bytes; as six drawings: %lld bytes", keyedBytes, apartBytes);
    QVERIFY(keyedBytes < apartBytes);
}

void TestExportLottie::aCycleIsWrittenOnce()
{
    // Four drawings played three times: each drawing's shapes are written once, as an asset
    // that each showing places.
    QTemporaryDir dir;
    const QString once = dir.filePath(QStringLiteral("once.json"));
    const QString thrice = dir.filePath(QStringLiteral("thrice.json"));
    QVERIFY(playAndCompare(cycle(1), {}, once).worst >= 0.98);
    const Played played = playAndCompare(cycle(3), {}, thrice);
    qInfo("a cycle played three times: worst tick %lld agrees %.2f %%; %lld bytes against %lld "
          "for one cycle",
          played.worstTick, 100 * played.worst, QFileInfo(thrice).size(), QFileInfo(once).size());
    QVERIFY(played.worst >= 0.98);
    int drawings = 0;
    for (const QJsonValue &a : readJson(thrice)[QStringLiteral("assets")].toArray())
        drawings +=
            a.toObject()[QStringLiteral("id")].toString().startsWith(QLatin1String("drawing_"));
    QCOMPARE(drawings, 4);
    QVERIFY(QFileInfo(thrice).size() < QFileInfo(once).size() * 5 / 4);
}

void TestExportLottie::layersAndCameraMatch()
{
    QTemporaryDir dir;
    const model::ExportSource source = layeredScene();
    const QString path = dir.filePath(QStringLiteral("scene.json"));
    const Played played = playAndCompare(source, {}, path);
    qInfo("two layers through a moving camera: worst tick %lld agrees %.2f %% (ink %.2f %%)",
          played.worstTick, 100 * played.worst, 100 * played.worstInk);
    QVERIFY2(played.worst >= 0.98, qPrintable(QString::number(played.worst)));
    QVERIFY(played.worstInk >= 0.90);
    // The layers are Lottie layers named after them, under cameras that are null layers.
    const QJsonObject json = readJson(path);
    const QJsonArray layers = json[QStringLiteral("layers")].toArray();
    QStringList precomps, nulls;
    for (const QJsonValue &v : layers) {
        const QJsonObject l = v.toObject();
        if (l[QStringLiteral("ty")].toInt() == 0)
            precomps << l[QStringLiteral("nm")].toString();
        if (l[QStringLiteral("ty")].toInt() == 3)
            nulls << l[QStringLiteral("nm")].toString();
    }
    QCOMPARE(precomps, QStringList({QStringLiteral("Figure"), QStringLiteral("Sky")}));
    QVERIFY(nulls.contains(QStringLiteral("Camera")));
    QVERIFY(nulls.contains(QStringLiteral("Camera (depth 1)")));
    for (const QJsonValue &v : layers)
        if (v.toObject()[QStringLiteral("nm")].toString() == QLatin1String("Sky"))
            QCOMPARE(v.toObject()[QStringLiteral("ks")]
                         .toObject()[QStringLiteral("o")]
                         .toObject()[QStringLiteral("k")]
                         .toDouble(),
                     50.0);
}

void TestExportLottie::dotLottieHoldsTheSameAnimation()
{
    QTemporaryDir dir;
    const model::ExportSource source = exampleWithHolds();
    model::ExportOptions o;
    o.scale = 0.5;
    o.format = model::ExportFormat::Lottie;
    o.target = dir.filePath(QStringLiteral("walk.json"));
    QVERIFY(model::exportAnimation(source, o));
    o.format = model::ExportFormat::DotLottie;
    o.target = dir.filePath(QStringLiteral("walk.lottie"));
    o.loop = false;
    const auto result = model::exportAnimation(source, o);
    QVERIFY(result);
    QCOMPARE(result->files, QStringList{o.target});

    QuaZip zip(o.target);
    QVERIFY(zip.open(QuaZip::mdUnzip));
    QStringList names = zip.getFileNameList();
    names.sort();
    QCOMPARE(names, QStringList(
                        {QStringLiteral("animations/walk.json"), QStringLiteral("manifest.json")}));
    const auto entry = [&](const QString &name) {
        zip.setCurrentFile(name);
        QuaZipFile file(&zip);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    };
    const QJsonObject manifest = QJsonDocument::fromJson(entry(QStringLiteral("manifest.json")))
                                     .object()[QStringLiteral("animations")]
                                     .toArray()[0]
                                     .toObject();
    QCOMPARE(manifest[QStringLiteral("id")].toString(), QStringLiteral("walk"));
    QCOMPARE(manifest[QStringLiteral("loop")].toBool(), false);
    const QByteArray inside = entry(QStringLiteral("animations/walk.json"));
    QCOMPARE(inside, readAll(dir.filePath(QStringLiteral("walk.json"))));
    QVERIFY(QFileInfo(o.target).size() * 3 < inside.size()); // deflated
    Player player(inside);
    QVERIFY(player.loaded());
    QCOMPARE(player.frames(), std::size_t(18));
}

void TestExportLottie::cancelledLeavesNothing()
{
    QTemporaryDir dir;
    const model::ExportSource source = exampleWithHolds();
    model::ExportOptions o;
    o.format = model::ExportFormat::Lottie;
    o.target = dir.filePath(QStringLiteral("walk.json"));
    int calls = 0;
    const auto result =
        model::exportAnimation(source, o, [&](qint64, qint64) { return ++calls < 4; });
    QVERIFY(!result);
    QCOMPARE(result.error().code, model::ExportErrorCode::Cancelled);
    QCOMPARE(filesIn(dir.path()), QStringList());
}

void TestExportLottie::picturesArePosedImages()
{
    const model::ExportSource source = picturesScene();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("pictures.json"));
    const Played played = playAndCompare(source, model::ExportOptions(), path);
    qInfo("pictures: worst tick %lld agrees %.2f %% (drawing alone %.2f %%), ink ratio %.3f",
          played.worstTick, 100 * played.worst, 100 * played.worstInk, played.inkRatio);
    QVERIFY2(played.worst >= 0.98, qPrintable(QString::number(played.worst)));
    QVERIFY2(played.worstInk >= 0.95, qPrintable(QString::number(played.worstInk)));
    // Each picture once as it shows: the still one once, the posed one once per drawing.
    const QJsonObject json = readJson(path);
    int images = 0;
    for (const QJsonValue &asset : json[QStringLiteral("assets")].toArray()) {
        const QJsonObject a = asset.toObject();
        if (!a.contains(QStringLiteral("p")))
            continue;
        ++images;
        QCOMPARE(a[QStringLiteral("e")].toInt(), 1);
        QVERIFY(
            a[QStringLiteral("p")].toString().startsWith(QStringLiteral("data:image/png;base64,")));
    }
    QCOMPARE(images, 4);
    const QJsonArray inner = innerLayers(path);
    QCOMPARE(countLayers(inner, 2), 4); // the still picture's one layer, the posed one's three
    // The line's layer lies over the pictures' (Lottie draws its first layers on top).
    int line = -1, firstImage = -1;
    for (int i = 0; i < inner.size(); ++i) {
        const int type = inner[i].toObject()[QStringLiteral("ty")].toInt();
        if (type == 4 && line < 0)
            line = i;
        if (type == 2 && firstImage < 0)
            firstImage = i;
    }
    QVERIFY(line >= 0 && line < firstImage);
}

QTEST_GUILESS_MAIN(TestExportLottie)
#include "tst_export_lottie.moc"
