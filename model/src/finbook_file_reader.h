// The .finbook parser behind readFinbook (private to the model). The tables (shared stroke
// data and poses) are parsed in finbook_file_reader_tables.cpp, the rest in
// finbook_file_reader.cpp.
#pragma once

#include "finbook_file_cursor.h"

#include <unordered_set>

namespace finbook::model::file_format {

class Reader {
public:
    explicit Reader(ParseMode mode)
        : m_mode(mode)
    {}
    // Parses a whole file; throws ReadFailure.
    LoadedDocument read(const QByteArray &bytes);

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

    quint32 readHeader(Cursor &c);
    void readSections(Cursor &c);
    void readDocument(Cursor &c);
    void readStrokeTable(Cursor &c);
    void readPoseTable(Cursor &c);
    // Returns the number of points, which Check mode does not store.
    quint32 readPoints(Cursor &c, std::vector<StrokePoint> &points, Deferred &deferred,
                       quint32 entry);
    void readFrames(Cursor &c);
    Frame readFrame(Cursor &c);
    StrokeGroup readObject(Cursor &c);
    void readObjectChunks(Cursor &c, StrokeGroup &group);
    std::vector<Pin> readPins(Cursor &c);
    DeformedStrokesPtr readPoseRef(Cursor &c, const StrokeGroup &group);
    void skipUnknownChunk(Cursor &c, quint32 chunkTag);
    void claimId(Cursor &c, Id id, const QString &owner);
    void finish(Cursor &c);

    ParseMode m_mode;
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
    std::unordered_set<Id> m_ids;
    Id m_maxId = kNoId;
};

// "STRK", or 0x00ff1234 for tags that are not text.
QString tagName(quint32 t);
// Unknown tags: skipped when ancillary, refused as made by a newer Finbook when critical.
void skipUnknown(Cursor &c, quint32 t, const char *kind);

} // namespace finbook::model::file_format
