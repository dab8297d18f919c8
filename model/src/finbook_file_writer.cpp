// serializeFinbook: the canonical byte form of a document (layout in finbook_file_format.h).
//
// Speed matters here (10M points in well under a second): the output is sized up front and
// filled through a raw pointer, points stroke by stroke in one tight loop.
#include "finbook_file_byte_writer.h"
#include "picture/picture_section.h"
#include "reference/reference_section.h"

#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/sound/soundtrack.h>

#include <algorithm>
#include <unordered_map>

namespace finbook::model {

namespace {
using namespace file_format;

// A pose is only worth saving while it still matches its object's strokes; a stale one is a
// cache the renderer ignores anyway, and the reader would rightly refuse it.
bool poseMatches(const StrokeGroup &group)
{
    if (!group.deformed || group.deformed->strokes.size() != group.strokes.size())
        return false;
    for (std::size_t i = 0; i < group.strokes.size(); ++i) {
        const std::size_t rest = group.strokes[i].data ? group.strokes[i].data->points.size() : 0;
        if (group.deformed->strokes[i].size() != rest)
            return false;
    }
    return true;
}

const StrokeData &emptyStrokeData()
{
    static const StrokeData empty;
    return empty;
}

// Shared data is stored once: the tables list each distinct pointer in order of first
// appearance (frames, objects, strokes), so the same document always gives the same indices.
// A drawing of a swap set as the object record SWAP writes it (finbook_file_format.h).
StrokeGroup swapDrawingObject(const SwapDrawing &d)
{
    StrokeGroup g;
    g.id = d.id;
    g.name = d.name;
    g.strokes = d.strokes;
    g.fills = d.fills;
    g.meshDensity = d.meshDensity;
    g.rig = d.rig;
    return g;
}

struct Tables {
    std::vector<const StrokeData *> strokes;
    std::unordered_map<const StrokeData *, quint32> strokeIndex;
    std::vector<const DeformedStrokes *> poses;
    std::unordered_map<const DeformedStrokes *, quint32> poseIndex;
    PictureTable pictures; // picture/picture_section.h
    Id maxId = kNoId;
    qsizetype expectedBytes = 256;

    explicit Tables(const std::vector<Layer> &layers, const std::vector<SwapSet> &swapSets = {})
    {
        for (const SwapSet &set : swapSets) {
            noteId(set.id);
            expectedBytes += qsizetype(kSwapSetFixedBytes) + set.name.size() * 3;
            for (const SwapDrawing &d : set.drawings)
                addGroup(swapDrawingObject(d));
        }
        for (const Layer &l : layers) {
            noteId(l.id);
            expectedBytes += qsizetype(kLayerFixedBytes) + l.properties.name.size() * 3;
            for (const Frame &f : l.cels) {
                noteId(f.id);
                expectedBytes += 4 + qsizetype(kFrameFixedBytes);
                for (const StrokeGroup &g : f.groups)
                    addGroup(g);
            }
        }
    }

    void noteId(Id id) { maxId = std::max(maxId, id); }

    void addGroup(const StrokeGroup &g)
    {
        noteId(g.id);
        pictures.add(g);
        for (const Pin &p : g.rig.pins)
            noteId(p.id);
        for (const Fill &f : g.fills) {
            expectedBytes += qsizetype(kFillFixedBytes + 2 + 8 * f.strokes.size()); // + "shad"
            for (Id id : f.strokes)
                noteId(id);
            for (const FillPlace &p : f.more) {
                expectedBytes += qsizetype(kFillFixedBytes + 8 * p.strokes.size());
                for (Id id : p.strokes)
                    noteId(id);
            }
        }
        expectedBytes += 4 + qsizetype(kObjectFixedBytes) + 3 * qsizetype(kChunkHeaderBytes) +
                         g.name.size() * 3 + qsizetype(g.rig.pins.size() * kPinBytes + 4) +
                         qsizetype(g.strokes.size() * kStrokeRefBytes);
        for (const Stroke &s : g.strokes) {
            noteId(s.id);
            const StrokeData *data = s.data ? s.data.get() : &emptyStrokeData();
            if (strokeIndex.try_emplace(data, quint32(strokes.size())).second) {
                strokes.push_back(data);
                expectedBytes +=
                    qsizetype(kStrokeDataHeaderBytes + data->points.size() * kPointBytes);
            }
        }
        if (poseMatches(g) &&
            poseIndex.try_emplace(g.deformed.get(), quint32(poses.size())).second) {
            poses.push_back(g.deformed.get());
            for (const auto &stroke : g.deformed->strokes)
                expectedBytes += qsizetype(4 + stroke.size() * kPointBytes);
        }
    }
};

void writeDocumentSection(ByteWriter &w, const DocumentSettings &s, Id maxId)
{
    w.u32(quint32(s.canvasSize.width()));
    w.u32(quint32(s.canvasSize.height()));
    w.u32(s.background);
    w.u32(quint32(s.fps));
    w.u8(s.loop ? 1 : 0);
    w.i32(s.playStart);
    w.i32(s.playEnd);
    // The next id is derived from the content, not the in-memory counter: commands allocate
    // ids when they are created, and undo does not give them back, so the counter depends on
    // history. Past every stored id is all a reopened document needs (its undo stack is new).
    w.u64(maxId + 1);
    w.f64(s.closeGap < 0.0 ? -1.0 : s.closeGap);
}

void writeStrokeTable(ByteWriter &w, const Tables &tables)
{
    w.u32(quint32(tables.strokes.size()));
    for (const StrokeData *data : tables.strokes) {
        w.u32(data->color);
        w.f32(data->width);
        w.points(data->points);
    }
}

void writePoseTable(ByteWriter &w, const Tables &tables)
{
    w.u32(quint32(tables.poses.size()));
    for (const DeformedStrokes *pose : tables.poses) {
        w.u32(quint32(pose->strokes.size()));
        for (const auto &points : pose->strokes)
            w.points(points);
    }
}

void writePins(ByteWriter &w, const std::vector<Pin> &pins)
{
    w.u32(quint32(pins.size()));
    for (const Pin &p : pins) {
        w.u64(p.id);
        w.f64(p.rest.x());
        w.f64(p.rest.y());
        w.f64(p.target.x());
        w.f64(p.target.y());
    }
}

void writeCage(ByteWriter &w, const CageRig &cage)
{
    w.u32(quint32(cage.rest.size()));
    for (std::size_t i = 0; i < cage.rest.size(); ++i) {
        w.f64(cage.rest[i].x());
        w.f64(cage.rest[i].y());
        w.f64(cage.posed[i].x());
        w.f64(cage.posed[i].y());
    }
}

void writeSkeleton(ByteWriter &w, const SkeletonRig &s)
{
    w.u32(quint32(s.joints.size()));
    for (std::size_t j = 0; j < s.joints.size(); ++j) {
        w.f64(s.joints[j].x());
        w.f64(s.joints[j].y());
        w.f64(j < s.radius.size() ? s.radius[j] : 0.0);
        w.i32(j < s.parent.size() ? s.parent[j] : -1);
        w.f64(j < s.angles.size() ? s.angles[j] : 0.0);
    }
    w.i32(s.root);
    w.f64(s.rootOffset.x());
    w.f64(s.rootOffset.y());
    for (double v :
         {s.settings.complexity, s.settings.merge, s.settings.prune, s.settings.collapse})
        w.f64(v);
    w.u8(quint8(s.mode));
    if (std::find(s.locked.begin(), s.locked.end(), true) != s.locked.end())
        for (std::size_t j = 0; j < s.joints.size(); ++j)
            w.u8(j < s.locked.size() && s.locked[j] ? 1 : 0);
}

// The chunks an object may carry, in the order they are written. A new kind of object state
// (a bone chunk, say) is one more row here and one in the reader's table.
struct ObjectChunkWriter {
    quint32 tag;
    bool (*present)(const StrokeGroup &);
    void (*write)(ByteWriter &, const StrokeGroup &, const Tables &);
};
const ObjectChunkWriter kObjectChunkWriters[] = {
    {kTagPins, [](const StrokeGroup &g) { return !g.rig.pins.empty(); },
     [](ByteWriter &w, const StrokeGroup &g, const Tables &) { writePins(w, g.rig.pins); }},
    {kTagCage, [](const StrokeGroup &g) { return !g.rig.cage.empty(); },
     [](ByteWriter &w, const StrokeGroup &g, const Tables &) { writeCage(w, g.rig.cage); }},
    {kTagSkeleton, [](const StrokeGroup &g) { return !g.rig.skeleton.empty(); },
     [](ByteWriter &w, const StrokeGroup &g, const Tables &) { writeSkeleton(w, g.rig.skeleton); }},
    {kTagJoin,
     [](const StrokeGroup &g) { return !g.rig.skeleton.empty() && g.rig.skeleton.join.joined(); },
     [](ByteWriter &w, const StrokeGroup &g, const Tables &) {
         const SkeletonJoin &j = g.rig.skeleton.join;
         w.u64(j.parent);
         for (double v : {j.childAt.x(), j.childAt.y(), j.parentAt.x(), j.parentAt.y()})
             w.f64(v);
     }},
    {kTagLimbBases,
     [](const StrokeGroup &g) {
         const std::vector<bool> &b = g.rig.skeleton.limbBase;
         return !g.rig.skeleton.empty() && std::find(b.begin(), b.end(), true) != b.end();
     },
     [](ByteWriter &w, const StrokeGroup &g, const Tables &) {
         const SkeletonRig &s = g.rig.skeleton;
         w.u32(quint32(s.joints.size()));
         for (std::size_t j = 0; j < s.joints.size(); ++j)
             w.u8(s.isLimbBase(int(j)) ? 1 : 0);
     }},
    {kTagFills, [](const StrokeGroup &g) { return !g.fills.empty(); },
     [](ByteWriter &w, const StrokeGroup &g, const Tables &) {
         w.u32(quint32(g.fills.size()));
         for (const Fill &f : g.fills) {
             w.u32(f.color);
             w.f64(f.seed.x());
             w.f64(f.seed.y());
             w.u32(quint32(f.strokes.size()));
             for (Id id : f.strokes)
                 w.u64(id);
         }
     }},
    {kTagFillPlaces,
     [](const StrokeGroup &g) {
         return std::any_of(g.fills.begin(), g.fills.end(),
                            [](const Fill &f) { return !f.more.empty(); });
     },
     [](ByteWriter &w, const StrokeGroup &g, const Tables &) {
         w.u32(quint32(g.fills.size()));
         for (const Fill &f : g.fills) {
             w.u32(quint32(f.more.size()));
             for (const FillPlace &p : f.more) {
                 w.f64(p.seed.x());
                 w.f64(p.seed.y());
                 w.u32(quint32(p.strokes.size()));
                 for (Id id : p.strokes)
                     w.u64(id);
             }
         }
     }},
    {kTagShading,
     [](const StrokeGroup &g) {
         return std::any_of(g.fills.begin(), g.fills.end(),
                            [](const Fill &f) { return f.shading != FillShading(); });
     },
     [](ByteWriter &w, const StrokeGroup &g, const Tables &) {
         w.u32(quint32(g.fills.size()));
         for (const Fill &f : g.fills) {
             w.u8(quint8(f.shading.ramp));
             w.u8(f.shading.rim ? 1 : 0);
         }
     }},
    {kTagPictureObject, hasPictureChunk,
     [](ByteWriter &w, const StrokeGroup &g, const Tables &tables) {
         writePictureChunk(w, g, tables.pictures, poseMatches(g));
     }},
    {kTagDeformed, poseMatches,
     [](ByteWriter &w, const StrokeGroup &g, const Tables &tables) {
         w.u32(tables.poseIndex.at(g.deformed.get()));
     }},
};

void writeObject(ByteWriter &w, const StrokeGroup &g, const Tables &tables)
{
    const qsizetype length = w.beginLength(4);
    w.u64(g.id);
    w.u8((g.visible ? kFlagVisible : 0) | (g.locked ? kFlagLocked : 0));
    w.f64(g.meshDensity);
    const QByteArray name = g.name.toUtf8();
    w.u32(quint32(name.size()));
    w.raw(name.constData(), std::size_t(name.size()));
    w.u32(quint32(g.strokes.size()));
    for (const Stroke &s : g.strokes) {
        w.u64(s.id);
        w.u32(tables.strokeIndex.at(s.data ? s.data.get() : &emptyStrokeData()));
    }
    for (const ObjectChunkWriter &chunk : kObjectChunkWriters) {
        if (!chunk.present(g))
            continue;
        w.u32(chunk.tag);
        const qsizetype chunkLength = w.beginLength(4);
        chunk.write(w, g, tables);
        w.endLength32(chunkLength);
    }
    w.endLength32(length);
}

// Every layer's cels, one layer after the other ("LAYR" says how many each has).
void writeFrames(ByteWriter &w, const std::vector<Layer> &layers, const Tables &tables)
{
    std::size_t count = 0;
    for (const Layer &l : layers)
        count += l.cels.size();
    w.u32(quint32(count));
    for (const Layer &l : layers)
        for (const Frame &f : l.cels) {
            const qsizetype length = w.beginLength(4);
            w.u64(f.id);
            w.u32(quint32(f.hold));
            w.u32(quint32(f.groups.size()));
            for (const StrokeGroup &g : f.groups)
                writeObject(w, g, tables);
            w.endLength32(length);
        }
}

// The "LAYR" section's payload (scene/layer_section.cpp reads it).
void writeLayers(ByteWriter &w, const std::vector<Layer> &layers)
{
    w.u32(quint32(layers.size()));
    for (const Layer &l : layers) {
        const LayerProperties &p = l.properties;
        w.u64(l.id);
        w.u32(quint32(l.cels.size()));
        w.u8(quint8((p.visible ? 0 : kLayerFlagHidden) | (p.locked ? kLayerFlagLocked : 0) |
                    (p.onionSkin ? 0 : kLayerFlagNoOnion)));
        w.f64(p.opacity);
        w.f64(p.depth);
        const QByteArray name = p.name.toUtf8();
        w.u32(quint32(name.size()));
        w.raw(name.constData(), std::size_t(name.size()));
    }
}

// One "SOND" section's payload (sound/sound_section.cpp reads it).
void writeSoundClip(ByteWriter &w, const SoundClip &clip)
{
    w.u64(clip.id);
    w.u64(quint64(clip.start));
    w.f64(clip.volume);
    w.u8(clip.muted ? kSoundFlagMuted : 0);
    const QByteArray name = clip.name.toUtf8();
    w.u32(quint32(name.size()));
    w.raw(name.constData(), std::size_t(name.size()));
    w.u64(quint64(clip.bytes.size()));
    w.raw(clip.bytes.constData(), std::size_t(clip.bytes.size()));
}

// The "CAMR" section's payload (camera/camera_section.cpp reads it).
void writeCamera(ByteWriter &w, const CameraTrack &camera)
{
    w.u32(quint32(camera.keys.size()));
    for (const CameraKey &k : camera.keys) {
        w.u64(quint64(k.tick));
        w.f64(k.center.x());
        w.f64(k.center.y());
        w.f64(k.zoom);
        w.f64(k.rotation);
        w.u8(quint8(k.easing));
        w.f64(k.control1.x());
        w.f64(k.control1.y());
        w.f64(k.control2.x());
        w.f64(k.control2.y());
    }
}

// The "SWAP" section's payload (swap/swap_section.cpp reads it).
void writeSwapSets(ByteWriter &w, const std::vector<SwapSet> &sets,
                   const std::vector<Layer> &layers, const Tables &tables)
{
    w.u32(quint32(sets.size()));
    for (const SwapSet &set : sets) {
        w.u64(set.id);
        const QByteArray name = set.name.toUtf8();
        w.u32(quint32(name.size()));
        w.raw(name.constData(), std::size_t(name.size()));
        w.u32(quint32(set.drawings.size()));
        for (const SwapDrawing &d : set.drawings)
            writeObject(w, swapDrawingObject(d), tables);
    }
    std::vector<std::pair<Id, SwapLink>> links;
    for (const Layer &l : layers)
        for (const Frame &f : l.cels)
            for (const StrokeGroup &g : f.groups)
                if (g.swap.linked())
                    links.emplace_back(g.id, g.swap);
    w.u32(quint32(links.size()));
    for (const auto &[object, link] : links) {
        w.u64(object);
        w.u64(link.set);
        w.u64(link.drawing);
    }
}

// A section and, from format 2 on, the CRC-32C of its tag, length and payload.
template <class WriteBody> void writeSection(ByteWriter &w, quint32 sectionTag, WriteBody body)
{
    const qsizetype start = w.size();
    w.u32(sectionTag);
    const qsizetype length = w.beginLength(8);
    body();
    w.endLength64(length);
    w.u32(w.crcSince(start));
}
} // namespace

QByteArray serializeFinbook(const Document &document)
{
    std::vector<AncillarySection> extra;
    if (!document.referenceLayer().isEmpty())
        for (AncillarySection &section : referenceSections(document.referenceLayer().reference()))
            extra.push_back(std::move(section));
    if (document.palette() != defaultPalette())
        extra.push_back(paletteSection(document.palette()));
    return serializeFinbook(document.layers(), document.settings(), extra,
                            document.soundtrack().clips(), document.camera(), document.swapSets());
}

AncillarySection paletteSection(const Palette &palette)
{
    return {"palt", paletteSectionPayload(palette)};
}

QByteArray serializeFinbook(const std::vector<Frame> &frames, const DocumentSettings &settings,
                            const std::vector<AncillarySection> &ancillary,
                            const std::vector<SoundClip> &sound, const CameraTrack &camera)
{
    std::vector<Layer> one(1);
    one.front().cels = frames;
    one.front().id = Tables(one).maxId + 1;
    return serializeFinbook(one, settings, ancillary, sound, camera);
}

QByteArray serializeFinbook(const std::vector<Layer> &layers, const DocumentSettings &settings,
                            const std::vector<AncillarySection> &ancillary,
                            const std::vector<SoundClip> &sound, const CameraTrack &camera,
                            const std::vector<SwapSet> &swapSets)
{
    const Tables tables(layers, swapSets);
    qsizetype extra = 0;
    for (const AncillarySection &a : ancillary)
        extra += qsizetype(kSectionHeaderBytes + kSectionCrcBytes) + a.payload.size();
    for (const SoundClip &clip : sound)
        extra += qsizetype(kSectionHeaderBytes + kSectionCrcBytes + kSoundFixedBytes) +
                 clip.name.size() * 3 + clip.bytes.size();
    if (!camera.isEmpty())
        extra += qsizetype(kSectionHeaderBytes + kSectionCrcBytes + 4) +
                 qsizetype(camera.keys.size() * kCameraKeyBytes);
    if (!tables.pictures.empty())
        extra +=
            qsizetype(kSectionHeaderBytes + kSectionCrcBytes) + tables.pictures.expectedBytes();
    ByteWriter w(tables.expectedBytes + extra);
    w.raw(kMagic, sizeof(kMagic));
    w.u32(kFinbookFormatVersion);
    Id maxId = tables.maxId;
    for (const SoundClip &clip : sound)
        maxId = std::max(maxId, clip.id);
    writeSection(w, kTagDocument, [&] { writeDocumentSection(w, settings, maxId); });
    writeSection(w, kTagStrokes, [&] { writeStrokeTable(w, tables); });
    writeSection(w, kTagPoses, [&] { writePoseTable(w, tables); });
    writeSection(w, kTagFrames, [&] { writeFrames(w, layers, tables); });
    writeSection(w, kTagLayers, [&] { writeLayers(w, layers); });
    if (!swapSets.empty())
        writeSection(w, kTagSwap, [&] { writeSwapSets(w, swapSets, layers, tables); });
    if (!tables.pictures.empty())
        writeSection(w, kTagPictures, [&] { tables.pictures.write(w); });
    for (const SoundClip &clip : sound)
        writeSection(w, kTagSound, [&] { writeSoundClip(w, clip); });
    if (!camera.isEmpty())
        writeSection(w, kTagCamera, [&] { writeCamera(w, camera); });
    const DocumentSettings defaults;
    if (settings.lightAzimuth != defaults.lightAzimuth ||
        settings.lightElevation != defaults.lightElevation)
        writeSection(w, kTagLight, [&] {
            w.f64(settings.lightAzimuth);
            w.f64(settings.lightElevation);
        });
    for (const AncillarySection &a : ancillary)
        writeSection(w, tag(a.tag),
                     [&] { w.raw(a.payload.constData(), std::size_t(a.payload.size())); });
    writeSection(w, kTagEnd, [] {});
    return w.take();
}

} // namespace finbook::model
