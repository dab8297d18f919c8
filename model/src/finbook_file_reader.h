// The .finbook parser behind readFinbook and recoverFinbook (private to the model). The
// sections are read in finbook_file_reader.cpp, frames, objects and their chunks in
// finbook_file_reader_frames.cpp, the shared tables in finbook_file_reader_tables.cpp, and
// what only recovery does (finding sections again, new ids) in finbook_file_recover.cpp.
#pragma once

#include "finbook_file_cursor.h"

#include <finbook/model/picture/picture_object.h>

#include <unordered_set>
#include <vector>

namespace finbook::model::file_format {

class Reader {
public:
    // `fileBytes` sizes the memory budget (kLoadMemoryFactor). `huntedId`: an id known to be
    // used twice, reported where it is used the second time.
    Reader(ParseMode mode, qint64 fileBytes, Id huntedId = kNoId);
    // Thrown by finish() when an id is used twice, for parseFinbook to read again and say where.
    struct DuplicateId {
        Id id;
    };
    // Parses a whole file; throws ReadFailure.
    LoadedDocument read(const QByteArray &bytes);
    // Recover mode: what was left out or repaired, one sentence each.
    const QStringList &problems() const { return m_problems; }
    // Magic and version; throws ReadFailure for a file this Finbook cannot read at all.
    // The format version; a damaged one (neither a known version nor one of the next few)
    // fails as damage unless `tolerateDamagedVersion` (recovering).
    static quint32 readHeader(Cursor &c, bool tolerateDamagedVersion = false);
    static QString damagedVersion(quint32 version);
    // Whether the first section (at `c`, after the header) ends in a matching checksum.
    static bool firstSectionHasCrc(const Cursor &c);
    // Whether the file ends with its end marker: then it is complete.
    static bool endsWithEndMarker(const QByteArray &bytes);

    // One kind of object chunk: its tag, whether it is a rig (an object carries one rig at
    // most), and how to read it into the object.
    struct ObjectChunk {
        quint32 tag;
        bool isRig;
        void (Reader::*read)(Cursor &, StrokeGroup &);
    };
    static const ObjectChunk kObjectChunks[];

private:
    // A bad value inside a table entry is reported where a frame first uses the entry, so
    // the message can name the frame and object the user will look at.
    struct Deferred {
        static constexpr quint32 kNone = 0xffffffffu;
        quint32 index = kNone;
        QString what;
        void note(quint32 entry, const QString &problem)
        {
            if (index == kNone) {
                index = entry;
                what = problem;
            }
        }
    };

    bool recovering() const { return m_mode == ParseMode::Recover; }
    // A problem the reader can get past: fails in Load and Check mode, is noted (with where it
    // is) in Recover mode, where the caller then uses a default or leaves the thing out.
    void problem(Cursor &c, FileErrorCode code, const QString &what);
    // Counts `bytes` against the memory budget before they are allocated.
    void charge(Cursor &c, qint64 bytes);
    // Cursor::count, except that recovering, a count larger than what fits is cut to that.
    quint32 count(Cursor &c, std::size_t recordBytes, const char *what);

    // finbook_file_reader.cpp
    void readSections(Cursor &c);
    bool readSection(Cursor &c, std::size_t &next);
    void readSectionBody(Cursor &body, std::size_t index);
    void readDocument(Cursor &c);
    void finish(Cursor &c);
    // finbook_file_reader_tables.cpp
    void readStrokeTable(Cursor &c);
    void readStrokeEntry(Cursor &c, quint32 index);
    void readPoseTable(Cursor &c);
    // Returns the number of points, which Check mode does not store.
    quint32 readPoints(Cursor &c, std::vector<StrokePoint> &points, Deferred &deferred,
                       quint32 entry);
    // finbook_file_reader_frames.cpp
    void readFrames(Cursor &c);
    Frame readFrame(Cursor &c);
    StrokeGroup readObject(Cursor &c);
    QString readName(Cursor &c);
    void readStrokeRefs(Cursor &c, StrokeGroup &g);
    void readObjectChunks(Cursor &c, StrokeGroup &group);
    void readPinsChunk(Cursor &c, StrokeGroup &g);
    void readCageChunk(Cursor &c, StrokeGroup &g);
    void readSkeletonChunk(Cursor &c, StrokeGroup &g);
    void readJoinChunk(Cursor &c, StrokeGroup &g);
    void readPoseChunk(Cursor &c, StrokeGroup &g);
    void readFillsChunk(Cursor &c, StrokeGroup &g);      // fill/fill_chunk.cpp
    void readFillPlacesChunk(Cursor &c, StrokeGroup &g); // fill/fill_chunk.cpp
    // A fill region's stroke ids (fill/fill_chunk.cpp): sorted, unique, ids a stroke can have.
    void readFillStrokeIds(Cursor &c, std::vector<Id> &ids, const char *what);
    void readShadingChunk(Cursor &c, StrokeGroup &g); // shade/shade_chunk.cpp
    void readLightSection(Cursor &c);                 // shade/shade_chunk.cpp
    void readPaletteSection(Cursor &c);               // finbook_file_reader.cpp
    void readReferenceSection(Cursor &c);             // reference/reference_section.cpp
    void readReferenceSequenceSection(Cursor &c);     // reference/reference_section.cpp
    std::vector<Pin> readPins(Cursor &c);
    CageRig readCage(Cursor &c);
    SkeletonRig readSkeleton(Cursor &c);                // skeleton/skeleton_chunk.cpp
    void readLimbBasesChunk(Cursor &c, StrokeGroup &g); // skeleton/skeleton_chunk.cpp
    DeformedStrokesPtr readPoseRef(Cursor &c, const StrokeGroup &group);
    void claimId(Cursor &c, Id id, const QString &owner);
    // sound/sound_section.cpp: one "SOND" section, a clip of the soundtrack.
    void readSoundSection(Cursor &body);
    void readSoundClip(Cursor &c);
    // camera/camera_section.cpp: the "CAMR" section, the camera's keys.
    void readCameraSection(Cursor &body);
    bool m_sawCamera = false;
    // scene/layer_section.cpp: the "LAYR" section, the layers.
    void readLayersSection(Cursor &body);
    bool m_sawLayers = false;
    // swap/swap_section.cpp: the "SWAP" section, the swap sets and their links.
    void readSwapSection(Cursor &body);
    bool m_sawSwap = false;
    // Ids a linked object shares with its drawing, once per linked object (not clashes).
    std::vector<Id> m_sharedIds;
    // picture/picture_section.cpp: the "PICT" section and the "PICO" object chunk, and putting
    // the two together once both are read.
    void readPictureSection(Cursor &c);
    void readPictureChunk(Cursor &c, StrokeGroup &g);
    void resolvePictures(Cursor &c);
    struct PictureEntry {
        PictureDataPtr data; // null: left out (recovering)
        PictureMeshPtr mesh;
    };
    struct PendingPicture {
        std::shared_ptr<ObjectPicture> picture; // the object's, filled in by resolvePictures
        quint32 index = 0;
        std::vector<QPointF> posed;
    };
    std::vector<PictureEntry> m_pictureTable;
    std::vector<PendingPicture> m_pendingPictures;
    bool m_sawPictures = false;

    // finbook_file_recover.cpp
    bool findNextSection(Cursor &c, std::size_t next);
    void renumberClashingIds();
    Id freshId();

    ParseMode m_mode;
    qint64 m_budget;
    qint64 m_charged = 0;
    Where m_where;
    quint32 m_version = 0;
    LoadedDocument m_doc;
    std::vector<StrokeDataPtr> m_strokeData;
    std::vector<DeformedStrokesPtr> m_poses;
    std::vector<quint32> m_strokeDataSizes;        // points per stroke-data entry
    std::vector<std::vector<quint32>> m_poseSizes; // points per stroke of each pose
    std::vector<quint32> m_strokeRefs; // stroke-data index of each stroke of the current object
    Deferred m_badStrokeData;
    Deferred m_badPose;
    // Every id in file order; duplicates are found by sorting at the end (8 bytes an id where
    // a hash set costs 48), and then located by reading the file again with m_huntedId set.
    std::vector<Id> m_ids;
    Id m_huntedId = kNoId;
    bool m_huntedSeen = false;
    Id m_maxId = kNoId;
    bool m_idsClash = false; // Recover mode: some ids must be given anew
    // freshId once the ids reach kMaxId: every id the document holds or refers to, and the
    // last id given from below.
    std::unordered_set<Id> m_usedIds;
    bool m_usedGathered = false;
    Id m_lowFree = kNoId;
    QStringList m_problems;
};

// "STRK", or 0x00ff1234 for tags that are not text.
QString tagName(quint32 t);
// Unknown tags: skipped when ancillary, refused as made by a newer Finbook when critical.
void skipUnknown(Cursor &c, quint32 t, const char *kind);

} // namespace finbook::model::file_format
