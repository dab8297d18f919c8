// The seed corpus of the fuzzer (tests/fuzz/seeds): small files that together use every
// section and every object chunk of the format, so mutations start from each of them. The
// test checks the seeds are what today's Finbook writes and that they cover the format;
// FINBOOK_WRITE_SEEDS=DIR writes them anew (after a format change).
#include "sound_support.h"
#include "tst_file_sample.h"

#include <finbook/model/camera/camera_commands.h>
#include <finbook/model/pins/pin_commands.h>
#include <finbook/model/recovery/recovery_store.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/scene/layer_commands.h>
#include <finbook/model/swap/mouth_chart.h>
#include <finbook/model/swap/swap_commands.h>

#include <QDir>

#include <algorithm>
#include <set>

using namespace finbook::model;
using namespace file_test;

namespace {
const QString kSeedDir = QStringLiteral(FINBOOK_SOURCE_DIR "/tests/fuzz/seeds");

StrokeGroup rigged(Id &next, const QString &name, float x0)
{
    StrokeGroup g;
    g.id = next++;
    g.name = name;
    g.strokes = {{next++, makeStroke(9, 0xff334455, 4.0f, x0, 40)},
                 {next++, makeStroke(3, 0x80aa0000, 2.0f, x0 + 5, 60)}};
    return g;
}

// Two frames, each with a caged object and a boned one, both posed, and a part joined to the
// boned one; the second frame's skeleton has a locked joint; the caged object has fills (one
// shaded), and the document its own close-gap setting and light.
void cageAndSkeleton(Document &doc)
{
    std::vector<Frame> frames(2);
    Id next = 1;
    for (Frame &f : frames) {
        f.id = next++;
        StrokeGroup caged = rigged(next, QStringLiteral("caged"), 10);
        caged.rig.cage.rest = {{0, 0}, {60, 0}, {60, 90}, {0, 90}};
        caged.rig.cage.posed = {{2, 1}, {63, 0}, {58, 95}, {-3, 88}};
        caged.deformed = shiftedPose(caged, 1.5f);
        StrokeGroup boned = rigged(next, QStringLiteral("boned"), 120);
        SkeletonRig &s = boned.rig.skeleton;
        s.joints = {{120, 40}, {130, 60}, {140, 80}};
        s.parent = {-1, 0, 1};
        s.radius = {4, 3, 2};
        s.root = 0;
        s.angles = {0.0, 0.25, -0.5};
        s.rootOffset = QPointF(3, -2);
        s.settings = {0.5, 0.1, 0.2, 0.05};
        s.mode = SkinningMode::LinearBlend;
        if (f.id != frames.front().id) // the optional lock tail, in one frame of two
            s.locked = {false, true, false};
        boned.deformed = shiftedPose(boned, -2.0f);
        // A part hanging from the boned object's last bone (a JOIN chunk).
        StrokeGroup hand = rigged(next, QStringLiteral("hand"), 140);
        SkeletonRig &h = hand.rig.skeleton;
        h.joints = {{142, 82}, {150, 95}};
        h.parent = {-1, 0};
        h.radius = {2, 1};
        h.root = 0;
        h.angles = {0.0, 0.3};
        h.join = {boned.id, QPointF(142, 82), QPointF(139, 79)};
        hand.deformed = shiftedPose(hand, 1.0f);
        // Fills (a FILL chunk): one naming both strokes, one naming a stroke erased since;
        // the first shaded (a "shad" chunk) and of two regions (an "FPLC" chunk).
        caged.fills = {{0xffe0c040,
                        QPointF(30, 45),
                        {caged.strokes[0].id, caged.strokes[1].id},
                        {ShadeRamp::ThreeTones, true},
                        {{QPointF(60, 50), {caged.strokes[1].id}}}},
                       {0x80304050, QPointF(12, 70), {caged.strokes[1].id, next + 1000}, {}, {}}};
        f.groups = {caged, boned, hand};
    }
    DocumentSettings settings;
    settings.canvasSize = QSize(320, 200);
    settings.closeGap = 14.0;
    settings.lightAzimuth = 200.0; // a "lite" section
    settings.lightElevation = 30.0;
    doc.reset(std::move(frames), settings, next + 2000);
    // A palette of its own (a "palt" section).
    Palette palette;
    palette.name = QStringLiteral("Sample");
    palette.swatches = {{0xffe0c040, QStringLiteral("Ochre")}, {0xff304050, QString()}};
    doc.setPalette(palette);
}

// The sample with a reference layer (a "refr" section): a 4×3 PNG, placed, rotated and locked.
void withReference(Document &doc)
{
    buildSample(doc);
    Reference r;
    r.kind = ReferenceKind::Image;
    r.name = QStringLiteral("tiny.png");
    r.bytes =
        QByteArray::fromBase64("iVBORw0KGgoAAAANSUhEUgAAAAQAAAADCAIAAAA7ljmRAAAAEklEQVR42mP4zwAE/"
                               "yEkA04OAOk9C/W9S6VLAAAAAElFTkSuQmCC");
    r.mediaSize = QSizeF(4, 3);
    r.center = QPointF(50, 40);
    r.scale = 10.0;
    r.rotation = 15.0;
    r.opacity = 0.25;
    r.locked = true;
    doc.referenceLayer().setReference(r);
}

// The sample with a sequence reference (refr and "rseq"): three 2×2 PNGs, held two ticks each.
void withSequence(Document &doc)
{
    buildSample(doc);
    Reference r;
    r.kind = ReferenceKind::Sequence;
    r.name = QStringLiteral("dot_01.png and 2 more");
    for (const char *png : {"iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAEElEQVR42mP4z8AARAwQCg"
                            "Af7gP9Y167WwAAAABJRU5ErkJggg==",
                            "iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAD0lEQVR42mNg+"
                            "M8AQhAKABvyA/3ULwSAAAAAAElFTkSuQmCC",
                            "iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAD0lEQVR42mNgYPgPRmAKAB"
                            "f2A/3HkIu0AAAAAElFTkSuQmCC"})
        r.pictures << QByteArray::fromBase64(png);
    r.bytes = r.pictures.front();
    r.mediaSize = QSizeF(2, 2);
    r.center = QPointF(60, 50);
    r.scale = 20.0;
    r.rate = 12.0;
    doc.referenceLayer().setReference(r);
}

// The sample with media of every kind a decoder reads (issue 47: the fuzzers decode them):
// FLAC and MP3 clips, and an animated GIF as a video reference (FFmpeg decodes it).
void withMedia(Document &doc)
{
    buildSample(doc);
    sound_test::importClip(
        doc,
        QByteArray::fromBase64(
            "ZkxhQwAAACICQAJAAADLAADLAfQA8AAAAZAilYmSioD/lQJDJEsQF/VvhAAADgYAAABmZm1wZWcAAAAA//"
            "h0CAABjyROAAAFawoyDcUPtg/NDgUKlOWZyr5sVL+vEHLfMMEs/x4AKZKJCgjFkMI5UWEwiyJrprlESQst"
            "d6YRhRIWS1fryiJEkVZDVqEwjAuF1zRhMsEYSksjEeXiiSFEpfTLKJEUIwjXMuKREURa+60iwUikxGEGSZ"
            "KJCgjFkMI5UWEwiyJrprlESQstd6YRhRIWS1fryiJEkVZDVqEwjAuF1zRhMsEYSksjEeXiiSFEpfTLKJEU"
            "IwjXMuKREURa+60iwUiA5qQ="),
        QStringLiteral("tone.flac"), 1);
    sound_test::importClip(
        doc,
        QByteArray::fromBase64(
            "SUQzBAAAAAAACgAAAAAAAAAAAAD/4xjEAArwBtW5QQAC/0dw22AGD4Pg+9QIAgcg+D5/E4Pg+iCBxEHwffgg"
            "67/DHAb9IY5d/OdPu6UmhzhZxDf8ZUQlHKELf4P/4xjEDxCZQpABlFAAbwfqB7kAGXEScA+JgOZHWB3qYe+A"
            "aAJAKisIoLr/8hHoqkQ+Hxpv//kKA0JQkDX/iU6DSv//////////4xjEBw5opjwB3gAA//////jSIRgDgBJJ"
            "BcAowKwXjB/BqMIcUoxC6XDG+E2MNsFowPQPgUBeIQAwMAqhJbTt0//++BKlUCD/4xjECA2opiwAVrxgKYkU"
            "Z9AbJyeX0YgA25x36Hmn4KmYaoLxglALlADyBEGgAIBUvrH////f5T///1r/X/98YwMhgQAB1wX/4xjEDA7o"
            "piwAp7CAggGnIgeakYjIqpzkUymryIeYeQKxgygWmBgBEbpGM5fxSvH//9n+/0////////9F///5OxVA4DBJ"
            "hA3/4xjECw1opjAABv5EmAoQInQCEYGBLISRgIoN0SARIMAODAAwBUIACyIAQQJrhv/////6P///Uv///jGA"
            "GAADfQMAIBwMCwH/4xjEEA04pkABVgAAIBALwMRoywMfZtQOrsWwN6Q/gMGwIAMAwCQAgXgJAKI+GYEKISAS"
            "P8cwgjDKf4zBUFmCCki4HaTiN4//4xjEFhKJLpQplGgAgDk0hOAuAG3AOBhIr/+Cdgr48x3iZlP//zMvm6y+"
            "Fz//Lic+Hy7//oB8BmiY1//9BNxq5Co7Vy3YAD//4xjEBgzwttG5wwAD/ZmX/jMylxgzM3GZm1UCb9VUBCn9"
            "BQYK8FBQp/goMd/QUKG+CgwU/wUKG/5IKkxBTUUzLjEwMKqqqqo="),
        QStringLiteral("tone.mp3"), 6);
    Reference r;
    r.kind = ReferenceKind::Video;
    r.name = QStringLiteral("dots.gif");
    r.bytes = QByteArray::fromBase64(
        "R0lGODlhCAAIAPcfMQAAACQAAEgAAGwAAJAAALQAANgAAPwAAAAkACQkAEgkAGwkAJAkALQkANgkAPwkAABIAC"
        "RIAEhIAGxIAJBIALRIANhIAPxIAABsACRsAEhsAGxsAJBsALRsANhsAPxsAACQACSQAEiQAGyQAJCQALSQANiQ"
        "APyQAAC0ACS0AEi0AGy0AJC0ALS0ANi0APy0AADYACTYAEjYAGzYAJDYALTYANjYAPzYAAD8ACT8AEj8AGz8AJ"
        "D8ALT8ANj8APz8AAAAVSQAVUgAVWwAVZAAVbQAVdgAVfwAVQAkVSQkVUgkVWwkVZAkVbQkVdgkVfwkVQBIVSRI"
        "VUhIVWxIVZBIVbRIVdhIVfxIVQBsVSRsVUhsVWxsVZBsVbRsVdhsVfxsVQCQVSSQVUiQVWyQVZCQVbSQVdiQVf"
        "yQVQC0VSS0VUi0VWy0VZC0VbS0Vdi0Vfy0VQDYVSTYVUjYVWzYVZDYVbTYVdjYVfzYVQD8VST8VUj8VWz8VZD8"
        "VbT8Vdj8Vfz8VQAAqiQAqkgAqmwAqpAAqrQAqtgAqvwAqgAkqiQkqkgkqmwkqpAkqrQkqtgkqvwkqgBIqiRIqk"
        "hIqmxIqpBIqrRIqthIqvxIqgBsqiRsqkhsqmxsqpBsqrRsqthsqvxsqgCQqiSQqkiQqmyQqpCQqrSQqtiQqvyQ"
        "qgC0qiS0qki0qmy0qpC0qrS0qti0qvy0qgDYqiTYqkjYqmzYqpDYqrTYqtjYqvzYqgD8qiT8qkj8qmz8qpD8qr"
        "T8qtj8qvz8qgAA/yQA/0gA/2wA/5AA/7QA/9gA//wA/wAk/yQk/0gk/2wk/5Ak/7Qk/9gk//wk/wBI/yRI/0hI"
        "/2xI/5BI/7RI/9hI//xI/wBs/yRs/0hs/2xs/5Bs/7Rs/9hs//xs/wCQ/ySQ/0iQ/2yQ/5CQ/7SQ/9iQ//yQ/w"
        "C0/yS0/0i0/2y0/5C0/7S0/9i0//y0/wDY/yTY/0jY/2zY/5DY/7TY/9jY//zY/wD8/yT8/0j8/2z8/5D8/7T8"
        "/9j8//z8/yH/C05FVFNDQVBFMi4wAwEAAAAh+QQEGQAfACwAAAAACAAIAAAINQABHMDxA9gxfP8EHgP2A8eBhP"
        "gWNjwAAEBEhg4rXpyoUWLGAzd44MEHjdihAy924CA57FhAACH5BAUZAAAALAAABgAIAAIAAAgUAC/80IELHjBj"
        "Rx4MxIMOWLFDAQEAIfkEBRkAAAAsAAAGAAgAAgAACBQAT/jAAQCcsGMHPvTAgc/gsSMBAQA7");
    r.mediaSize = QSizeF(8, 8);
    r.center = QPointF(50, 40);
    r.scale = 8.0;
    doc.referenceLayer().setReference(r);
}

// The sample with an SVG reference holding text and a <use>.
void withSvgReference(Document &doc)
{
    buildSample(doc);
    Reference r;
    r.kind = ReferenceKind::Image;
    r.name = QStringLiteral("sign.svg");
    r.bytes = "<svg xmlns=\"http://www.w3.org/2000/svg\" "
              "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"40\" height=\"20\">"
              "<rect id=\"r\" width=\"8\" height=\"8\" fill=\"#c00\"/>"
              "<use xlink:href=\"#r\" x=\"10\"/><text x=\"2\" y=\"18\">Hi</text></svg>";
    r.mediaSize = QSizeF(40, 20);
    r.center = QPointF(50, 40);
    doc.referenceLayer().setReference(r);
}

// The sample with an object of shaded fills at the editor's finest mesh (a grid of 3 × 3 pen
// lines, every cell filled and shaded), a sound clip and an SVG reference in one file: the
// mix the thumbnailer's and the 3D export's budgets guard (issue 54).
void withShadingAndMedia(Document &doc)
{
    buildSample(doc);
    std::vector<Frame> frames = doc.frames();
    Id id = doc.nextId();
    StrokeGroup grid;
    grid.id = id++;
    grid.name = QStringLiteral("shaded grid");
    grid.meshDensity = 4.0;
    std::vector<Id> rows, columns;
    for (int i = 0; i < 3; ++i) {
        const float at = 20.0f + 30.0f * float(i);
        for (std::vector<Id> *list : {&rows, &columns}) {
            auto data = std::make_shared<StrokeData>();
            data->width = 2.0f;
            data->color = qRgb(30, 30, 40);
            data->points = list == &rows ? std::vector<StrokePoint>{{10, at, 1}, {90, at, 1}}
                                         : std::vector<StrokePoint>{{at, 10, 1}, {at, 90, 1}};
            list->push_back(id);
            grid.strokes.push_back({id++, data});
        }
    }
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) {
            Fill fill;
            fill.color = qRgb(200, 90 + 60 * r, 60 + 80 * c);
            fill.seed = QPointF(35.0 + 30 * c, 35.0 + 30 * r);
            fill.strokes = {rows[std::size_t(r)], rows[std::size_t(r) + 1], columns[std::size_t(c)],
                            columns[std::size_t(c) + 1]};
            std::sort(fill.strokes.begin(), fill.strokes.end());
            fill.shading.ramp = r == c ? ShadeRamp::ThreeTones : ShadeRamp::Smooth;
            fill.shading.rim = c == 1;
            grid.fills.push_back(fill);
        }
    frames.front().groups.push_back(std::move(grid));
    doc.reset(std::move(frames), doc.settings(), id);
    sound_test::importClip(doc, sound_test::sineWav(0.01, 8000), QStringLiteral("beat.wav"), 1);
    Reference r;
    r.kind = ReferenceKind::Image;
    r.name = QStringLiteral("box.svg");
    r.bytes = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"20\" height=\"20\">"
              "<rect width=\"20\" height=\"20\" fill=\"#0a0\"/></svg>";
    r.mediaSize = QSizeF(20, 20);
    r.center = QPointF(50, 40);
    doc.referenceLayer().setReference(r);
}

// The sample with a camera: one key of each easing, the Bézier's handles off the diagonal.
void withCamera(Document &doc)
{
    buildSample(doc);
    for (int e = 0; e < kCameraEasingCount; ++e) {
        CameraKey k;
        k.tick = 3 * e;
        k.center = QPointF(40 + 10 * e, 30 - 5 * e);
        k.zoom = 1.0 + 0.5 * e;
        k.rotation = 15.0 * e;
        k.easing = CameraEasing(e);
        k.control1 = QPointF(0.2, -0.3);
        k.control2 = QPointF(0.6, 1.4);
        doc.undoStack()->push(setCameraKeyCommand(&doc, k).release());
    }
}

// Three layers (LAYR): the sample's frames on one, a duplicate at depth and half opacity,
// hidden and locked, and a layer of one long cel; a camera over them.
void withLayers(Document &doc)
{
    withCamera(doc);
    doc.undoStack()->push(new DuplicateLayerCommand(&doc, doc.currentLayerId()));
    LayerProperties p = doc.layerAt(1).properties;
    p.opacity = 0.5;
    p.depth = 2.0;
    p.visible = false;
    p.locked = true;
    p.onionSkin = false;
    doc.undoStack()->push(new SetLayerPropertiesCommand(&doc, doc.layerAt(1).id, p, "p"));
    doc.undoStack()->push(new AddLayerCommand(&doc, 0, QStringLiteral("Background")));
}

// Swap sets (SWAP): an object made swappable with a second drawing (a copy), shown by the
// frame after it too; and a mouth chart on a new object, one of its drawings posed by a pin.
void withSwaps(Document &doc)
{
    buildSample(doc);
    const Frame &first = doc.frameAt(0);
    const Id object = first.groups.front().id;
    doc.undoStack()->push(
        new NewSwapSetCommand(&doc, object, QStringLiteral("Hand"), QStringLiteral("open")));
    doc.undoStack()->push(new AddSwapDrawingCommand(&doc, object, QStringLiteral("closed"),
                                                    AddSwapDrawingCommand::Content::Copy));
    doc.undoStack()->push(new DuplicateFrameCommand(&doc, first.id, 1));
    doc.undoStack()->push(stepSwapDrawing(&doc, object, 1));
    auto *mouth = new AddObjectCommand(&doc, doc.frameAt(0).id, -1, QStringLiteral("Mouth"));
    doc.undoStack()->push(mouth);
    doc.undoStack()->push(new NewSwapSetCommand(
        &doc, mouth->groupId(), mouthChart(doc, QPointF(60, 40), 30, 0xff101010, 2.0f), 3));
    doc.undoStack()->push(
        new AddPinCommand(&doc, mouth->groupId(), QPointF(60, 40), QPointF(64, 42)));
}

// Every seed by name.
std::vector<std::pair<QString, QByteArray>> seeds()
{
    Document sample;
    buildSample(sample);
    Document rigs;
    cageAndSkeleton(rigs);
    Document referenced;
    withReference(referenced);
    Document sequence;
    withSequence(sequence);
    // Two sound clips (SOND sections): a tiny WAV, and a muted, quieter one further on.
    Document sound;
    buildSample(sound);
    sound_test::importClip(sound, sound_test::sineWav(0.01, 8000), QStringLiteral("beat.wav"), 2);
    const Id quiet = sound_test::importClip(sound, sound_test::sineWav(0.005, 8000, 880),
                                            QStringLiteral("voice.wav"), 30);
    sound.undoStack()->push(soundClipMutedCommand(&sound, quiet, true).release());
    sound.undoStack()->push(soundClipVolumeCommand(&sound, quiet, 0.5).release());
    Document media;
    withMedia(media);
    Document svg;
    withSvgReference(svg);
    Document shaded;
    withShadingAndMedia(shaded);
    Document camera;
    withCamera(camera);
    Document layered;
    withLayers(layered);
    Document swaps;
    withSwaps(swaps);
    std::vector<std::pair<QString, QByteArray>> all{
        {QStringLiteral("shading_and_media.finbook"), serializeFinbook(shaded)},
        {QStringLiteral("media.finbook"), serializeFinbook(media)},
        {QStringLiteral("camera.finbook"), serializeFinbook(camera)},
        {QStringLiteral("layers.finbook"), serializeFinbook(layered)},
        {QStringLiteral("swaps.finbook"), serializeFinbook(swaps)},
        {QStringLiteral("svg_reference.finbook"), serializeFinbook(svg)},
        {QStringLiteral("sample.finbook"), serializeFinbook(sample)},
        {QStringLiteral("cage_skeleton.finbook"), serializeFinbook(rigs)},
        {QStringLiteral("reference.finbook"), serializeFinbook(referenced)},
        {QStringLiteral("reference_sequence.finbook"), serializeFinbook(sequence)},
        {QStringLiteral("sound.finbook"), serializeFinbook(sound)},
        {QStringLiteral("recovery_copy.finbook"),
         recoveryCopyBytes(rigs.layers(), rigs.settings(),
                           {QStringLiteral("rigs.finbook"), QStringLiteral("/tmp/rigs.finbook"),
                            QDateTime(QDate(2024, 11, 23), QTime(10, 0), Qt::UTC), 2})},
        {QStringLiteral("format_v1.finbook"),
         fileBytes(QStringLiteral(FINBOOK_SOURCE_DIR "/tests/data/format_v1_sample.finbook"))}};
    return all;
}

// Tags of the sections and object chunks a file holds.
void collectTags(const QByteArray &bytes, std::set<QByteArray> &tags)
{
    const qsizetype trailer = sectionTrailer(bytes);
    qsizetype at = 12;
    while (at + 12 <= bytes.size()) {
        tags.insert(bytes.mid(at, 4));
        const quint64 length = qFromLittleEndian<quint64>(bytes.constData() + at + 4);
        at += 12 + qsizetype(length) + trailer;
    }
    // Object chunks: look for their tags followed by a plausible length (good enough for
    // files this small, whose points never spell these letters).
    for (const char *chunk : {"PINS", "CAGE", "SKEL", "JOIN", "DEFM", "FILL", "FPLC", "shad"})
        if (bytes.contains(chunk))
            tags.insert(chunk);
}
} // namespace

class TestFuzzSeeds : public QObject {
    Q_OBJECT
private slots:
    void writeSeedsWhenAsked();
    void seedsAreCurrent();
    void seedsCoverTheFormat();
};

void TestFuzzSeeds::writeSeedsWhenAsked()
{
    const QString out = qEnvironmentVariable("FINBOOK_WRITE_SEEDS");
    if (out.isEmpty())
        QSKIP("set FINBOOK_WRITE_SEEDS=DIR to write the seeds");
    QVERIFY(QDir().mkpath(out));
    for (const auto &[name, bytes] : seeds()) {
        QFile f(QDir(out).filePath(name));
        QVERIFY(f.open(QIODevice::WriteOnly));
        QCOMPARE(f.write(bytes), bytes.size());
    }
}

void TestFuzzSeeds::seedsAreCurrent()
{
    for (const auto &[name, bytes] : seeds()) {
        QVERIFY2(!bytes.isEmpty(), qPrintable(name));
        QVERIFY2(fileBytes(QDir(kSeedDir).filePath(name)) == bytes,
                 qPrintable(name + QStringLiteral(" is stale: FINBOOK_WRITE_SEEDS=") + kSeedDir));
        QVERIFY2(readFinbook(bytes), qPrintable(name));
    }
}

void TestFuzzSeeds::seedsCoverTheFormat()
{
    std::set<QByteArray> tags;
    for (const auto &[name, bytes] : seeds())
        collectTags(bytes, tags);
    for (const char *tag : {"DOCU", "STRK", "POSE", "FRAM", "FEND", "rcvy", "thmb", "PINS",
                            "CAGE", "SKEL", "JOIN", "DEFM", "FILL", "FPLC", "refr", "rseq",
                            "SOND", "shad", "lite", "CAMR", "LAYR", "palt", "SWAP"})
        QVERIFY2(tags.count(tag), tag);
}

QTEST_GUILESS_MAIN(TestFuzzSeeds)
#include "tst_fuzz_seeds.moc"
