// The .finbook byte layout, shared by the writer and the reader (private to the model).
//
//   file    := magic[8] u32 version section* "FEND" u64 0 crc
//   section := tag[4] u64 length payload[length] crc
//   crc     := u32 CRC-32C of the section's tag, length and payload (format 2 on; version-1
//              files have none)
//   "DOCU"  := u32 canvasWidth u32 canvasHeight u32 background u32 fps u8 loop
//              i32 playStart i32 playEnd u64 nextId [f64 closeGap]   (format 3 on; < 0 = auto)
//   "STRK"  := u32 count strokeData*       (the stroke-data table, first appearance order)
//   strokeData := u32 color f32 width u32 n point[n]
//   point   := f32 x f32 y u16 pressure     (pressure = q / 65535; 10 bytes)
//   "POSE"  := u32 count pose*             (deformed-pose table, first appearance order)
//   pose    := u32 strokes (u32 n point[n])[strokes]
//   "FRAM"  := u32 count frame*
//   frame   := u32 length { u64 id u32 hold u32 objects object[objects] chunk* }
//   object  := u32 length { u64 id u8 flags f64 meshDensity u32 nameBytes utf8[nameBytes]
//                           u32 strokes (u64 strokeId u32 strokeDataIndex)[strokes] chunk* }
//   chunk   := tag[4] u32 length payload[length]
//   "PINS"  := u32 count (u64 id f64 restX f64 restY f64 targetX f64 targetY)[count]
//   "CAGE"  := u32 count (f64 restX f64 restY f64 posedX f64 posedY)[count]
//   "DEFM"  := u32 poseIndex
//   "SKEL"  := u32 joints (f64 x f64 y f64 radius i32 parent f64 angle)[joints] i32 root
//              f64 rootOffsetX f64 rootOffsetY f64 complexity f64 merge f64 prune
//              f64 collapse u8 skinningMode [u8 locked[joints]]   (skeleton/skeleton_rig.h)
//              The locks (0 or 1 per joint) are written only when a joint is locked, so a
//              skeleton without locks keeps the original layout and older files (which end
//              at the mode) open with no locks.
//   "limb"  := u32 joints u8 limbBase[joints]   (ancillary; skeleton/skeleton_rig.h limbBase,
//              0 or 1 per joint): where the skeleton's limbs leave the body. Written only when
//              some joint is a limb base, only after SKEL; a reader that skips it turns limbs
//              from the body's centre when dragged by their tip.
//   "FILL"  := u32 count (u32 color f64 seedX f64 seedY u32 n u64 strokeId[n])[count]
//              (format 3 on; types.h Fill): fills, drawn under the strokes in this order.
//   "shad"  := u32 count (u8 ramp u8 rim)[count]   (ancillary; types.h FillShading): how each
//              fill of the object is shaded, one entry per fill of its FILL chunk, after it.
//              Written only when a fill is shaded; a reader that skips it shows flat fills.
//   "FPLC"  := u32 count (u32 places (f64 seedX f64 seedY u32 n u64 strokeId[n])[places])[count]
//              (types.h Fill::more): each fill's further regions, one entry per fill of its
//              FILL chunk, after it. Written only when a fill has more than one region (Apply
//              Pose makes them); critical, as a Finbook that skipped it would lose colours.
//   "JOIN"  := u64 parentObjectId f64 childAtX f64 childAtY f64 parentAtX f64 parentAtY
//              (skeleton/skeleton_rig.h SkeletonJoin): the object's skeleton hangs from
//              another object's skeleton in the same frame. Only after SKEL.
//   "SOND"  := u64 id i64 start f64 volume u8 flags u32 nameBytes utf8[nameBytes]
//              u64 dataBytes bytes[dataBytes]
//              (sound/sound_clip.h): one section per sound clip of the soundtrack, after FRAM,
//              in soundtrack order. flags: 1 = muted. The bytes are the imported file as it
//              was (WAV, MP3, …). Written only when the document has sound, so a file without
//              sound is a plain format-3 file; a Finbook that does not know SOND refuses a file
//              with sound as made by a newer Finbook (it would drop the sound on saving).
//   "CAMR"  := u32 count (i64 tick f64 centerX f64 centerY f64 zoom f64 rotation u8 easing
//              f64 control1X f64 control1Y f64 control2X f64 control2Y)[count]
//              (camera/camera_track.h): the camera's keys in increasing tick order. At most
//              once, after FRAM. Written only when the document has camera keys, so a file
//              without a camera is a plain format-3 file; a Finbook that does not know CAMR
//              refuses a file with a camera as made by a newer Finbook (it would drop the
//              camera on saving).
//   "LAYR"  := u32 count { u64 id u32 cels u8 flags f64 opacity f64 depth u32 nameBytes
//              utf8[nameBytes] }[count]   (format 4 on; types.h Layer): the layers, back to
//              front. FRAM holds their cels one layer after the other: the first layer's `cels`
//              frames, then the next layer's, and so on (the counts add up to FRAM's). flags:
//              1 = hidden, 2 = locked, 4 = no onion skin. At most once, after FRAM; the writer
//              always writes it. A file without it (any older format) is one layer holding
//              all its frames.
//
//   "SWAP"  := u32 sets { u64 id u32 nameBytes utf8[nameBytes] u32 drawings object[drawings] }
//              [sets] u32 links (u64 objectId u64 setId u64 drawingId)[links]
//              (types.h SwapSet): the drawings objects swap between frame by frame, each
//              written as an object (its id, name, mesh density, strokes, fills and the rig a
//              frame switching to it starts with), then which object of FRAM shows which
//              drawing. A linked object is written in FRAM as it is shown, with its drawing's
//              stroke ids: those ids are the only ones a file holds more than once. At most
//              once, after FRAM; written only when the document has sets, so a Finbook that
//              does not know SWAP refuses the file as made by a newer Finbook (it would lose
//              every drawing not shown and the links on saving).
//
//   "PICT", and the object chunk "PICO": picture objects (picture/picture_section.h). PICT
//              comes at most once, after FRAM (the writer puts it after SWAP).
//
// Ancillary sections (between FRAM and FEND):
//   "lite"  := f64 azimuth f64 elevation   (degrees; DocumentSettings' light for shaded fills),
//              written only when the light is not the default.
//   "palt"  := u32 nameBytes utf8 u32 count (u32 color u32 nameBytes utf8)[count]
//              (palette/palette.h): the document's palette, written only when it is not the
//              default one. A Finbook that does not know it opens the file with the default.
//
// An object carries at most one rig chunk (PINS, CAGE or SKEL).
//
//   "refr"  := u8 kind u8 flags f64 mediaWidth f64 mediaHeight f64 centerX f64 centerY
//              f64 scale f64 rotation f64 opacity f64 rate u32 nameBytes utf8[nameBytes]
//              u64 mediaBytes byte[mediaBytes]   (reference/reference.h; flags as an object's)
//              The reference layer: the imported file's original bytes, once. Ancillary, at
//              most once, between FRAM and FEND: a Finbook that does not know it opens the
//              drawing without its reference.
//   "rseq"  := u32 count { u64 pictureBytes byte[pictureBytes] }[count]
//              A sequence reference's pictures after the first (the first is refr's media,
//              written there as kind Image so that a Finbook that does not know rseq shows it
//              as a still). Ancillary, at most once, right after refr.
//
// Everything is little-endian. Sections come in the order above, each exactly once; ancillary
// sections may come between FRAM and FEND. Records and chunks are length-prefixed so later
// formats can add state as new chunks: an object chunk is one row in the reader's and the
// writer's chunk tables (kObjectChunks, kObjectChunkWriters). A tag whose first letter is lower
// case is ancillary: readers that do not know it skip it; an unknown upper-case tag is
// critical and the file is refused as too new.
#pragma once

#include <finbook/model/finbook_file.h>

#include <QtEndian>

#include <bit>
#include <cstdint>
#include <cstring>

namespace finbook::model::file_format {

static_assert(std::endian::native == std::endian::little ||
              std::endian::native == std::endian::big);

// PNG-style: the high bit catches 7-bit transfers, CR LF and LF catch newline conversion,
// ^Z stops `type` on DOS.
constexpr char kMagic[8] = {'\x89', 'F', 'B', 'K', '\r', '\n', '\x1a', '\n'};
constexpr std::size_t kHeaderBytes = sizeof(kMagic) + 4;
constexpr quint32 kOldestVersion = 1;
// Versions up to kFinbookFormatVersion + this are "made by a newer Finbook"; any other
// version word is damage (one flipped bit turns 2 into 3, 0, 6, 10, …, 2^31 + 2).
constexpr quint32 kNewerVersionsKnown = 2;

constexpr quint32 tag(const char (&name)[5])
{
    return quint32(quint8(name[0])) | quint32(quint8(name[1])) << 8 |
           quint32(quint8(name[2])) << 16 | quint32(quint8(name[3])) << 24;
}
constexpr quint32 kTagDocument = tag("DOCU");
constexpr quint32 kTagStrokes = tag("STRK");
constexpr quint32 kTagPoses = tag("POSE");
constexpr quint32 kTagFrames = tag("FRAM");
constexpr quint32 kTagEnd = tag("FEND");
constexpr quint32 kTagPins = tag("PINS");
constexpr quint32 kTagDeformed = tag("DEFM");
constexpr quint32 kTagCage = tag("CAGE");
constexpr quint32 kTagSkeleton = tag("SKEL");
constexpr quint32 kTagJoin = tag("JOIN");
constexpr quint32 kTagFills = tag("FILL");
constexpr quint32 kTagReference = tag("refr");
constexpr quint32 kTagReferenceSequence = tag("rseq");
constexpr quint32 kTagSound = tag("SOND");
constexpr quint32 kTagCamera = tag("CAMR");
constexpr quint32 kTagLayers = tag("LAYR");
constexpr quint32 kTagSwap = tag("SWAP");
constexpr quint32 kTagPictures = tag("PICT");      // picture/picture_section.h
constexpr quint32 kTagPictureObject = tag("PICO"); // picture/picture_section.h
constexpr std::size_t kSwapSetFixedBytes = 8 + 4 + 4;
constexpr std::size_t kSwapLinkBytes = 8 + 8 + 8;
constexpr quint8 kLayerFlagHidden = 1;
constexpr quint8 kLayerFlagLocked = 2;
constexpr quint8 kLayerFlagNoOnion = 4;
constexpr std::size_t kLayerFixedBytes = 8 + 4 + 1 + 8 + 8 + 4;
constexpr quint32 kTagFillPlaces = tag("FPLC");
constexpr quint32 kTagShading = tag("shad");
constexpr quint32 kTagLimbBases = tag("limb");
constexpr quint32 kTagLight = tag("lite");
constexpr quint32 kTagPalette = tag("palt");

inline bool isAncillary(quint32 t)
{
    const char first = char(t & 0xff);
    return first >= 'a' && first <= 'z';
}

constexpr std::size_t kSectionHeaderBytes = 4 + 8;
constexpr std::size_t kSectionCrcBytes = 4;
constexpr quint32 kFirstVersionWithCrc = 2;
constexpr std::size_t kChunkHeaderBytes = 4 + 4;
constexpr std::size_t kDocumentBytes = 4 * 4 + 1 + 4 + 4 + 8;
constexpr quint32 kFirstVersionWithFills = 3;
constexpr std::size_t kFillFixedBytes = 4 + 8 + 8 + 4;
constexpr std::size_t kPointBytes = 4 + 4 + 2;
constexpr std::size_t kStrokeDataHeaderBytes = 4 + 4 + 4;
constexpr std::size_t kStrokeRefBytes = 8 + 4;
constexpr std::size_t kPinBytes = 8 + 4 * 8;
constexpr std::size_t kCageCornerBytes = 4 * 8;
constexpr std::size_t kCameraKeyBytes = 8 + 4 * 8 + 1 + 4 * 8;
constexpr std::size_t kJointBytes = 3 * 8 + 4 + 8;
constexpr std::size_t kSkeletonTailBytes = 4 + 6 * 8 + 1;
constexpr std::size_t kFrameFixedBytes = 8 + 4 + 4;
constexpr std::size_t kObjectFixedBytes = 8 + 1 + 8 + 4 + 4;
constexpr std::size_t kMaxNameBytes = 4096;
constexpr std::size_t kReferenceFixedBytes = 1 + 1 + 8 * 8 + 4 + 8;
constexpr std::size_t kSoundFixedBytes = 8 + 8 + 8 + 1 + 4 + 8;
constexpr quint8 kSoundFlagMuted = 0x01;

constexpr quint8 kFlagVisible = 0x01;
constexpr quint8 kFlagLocked = 0x02;
constexpr quint8 kKnownFlags = kFlagVisible | kFlagLocked;

// Pressure lives on a 1/65535 grid in the file. Loading yields q / 65535.0f exactly, and
// quantising that value gives q back, so save → open → save is byte-identical.
inline quint16 quantisePressure(float pressure)
{
    if (!(pressure > 0.0f)) // also NaN
        return 0;
    if (pressure >= 1.0f)
        return 65535;
    return quint16(pressure * 65535.0f + 0.5f);
}
inline float dequantisePressure(quint16 q)
{
    return float(q) / 65535.0f;
}

// A float's exponent bits all set means infinity or NaN; cheaper than std::isfinite per point.
inline bool isFiniteBits(quint32 bits)
{
    return (bits & 0x7f800000u) != 0x7f800000u;
}

// What went wrong reading a file, before it is dressed as a sentence for the user.
struct ReadFailure {
    FileErrorCode code;
    QString what; // e.g. "frame 3, object "arm", stroke 7: point 12 has a non-finite coordinate"
};

// Check runs every validation but stores no points: saveFinbook checks its own output
// with it at a fraction of the time and memory of a full load. Recover reads what it can of a
// damaged file and notes each problem instead of failing (recoverFinbook).
enum class ParseMode { Load, Check, Recover };

// readFinbook without the sentence. In Recover mode `problems` gets what was left out.
Expected<LoadedDocument, ReadFailure> parseFinbook(const QByteArray &bytes,
                                                   ParseMode mode = ParseMode::Load,
                                                   QStringList *problems = nullptr);

// The first bytes of a file (at least kHeaderBytes when the file has them): whether they
// start a .finbook of a version this Finbook reads. Lets loadFinbook refuse a wrong file before
// reading the rest of it.
std::optional<ReadFailure> checkHeader(QByteArrayView head);

// "What. What to do.": the message of a FileError for a file that failed to parse.
QString failureSentence(FileErrorCode code, const QString &what);

// Migration hook: a loaded document of an older format version is upgraded one version at a
// time until it matches kFinbookFormatVersion.
void migrateLoadedDocument(LoadedDocument &document, quint32 fromVersion);

} // namespace finbook::model::file_format
