// What only "open anyway" does: find the next section that reads after damage, and give new
// ids to what lost its own. Also reading one ancillary section without parsing the rest.
#include "finbook_file_ids.h"
#include "finbook_file_reader.h"
#include "io/crc32c.h"

#include <algorithm>
#include <unordered_set>
#include <utility>

namespace finbook::model {

namespace file_format {

namespace {
constexpr quint32 kSectionTags[] = {kTagDocument, kTagStrokes, kTagPoses, kTagFrames,   kTagSound,
                                    kTagCamera,   kTagLayers,  kTagSwap,  kTagPictures, kTagEnd};

// Whether a section that reads starts at `p`: a tag from `tags`, a length that fits and, from
// format 2 on, a checksum that matches.
bool sectionStartsAt(const char *p, const char *end, bool hasCrc, const quint32 *tags,
                     std::size_t tagCount)
{
    if (std::size_t(end - p) < kSectionHeaderBytes + (hasCrc ? kSectionCrcBytes : 0))
        return false;
    const quint32 t = qFromLittleEndian<quint32>(p);
    if (std::find(tags, tags + tagCount, t) == tags + tagCount)
        return false;
    const quint64 length = qFromLittleEndian<quint64>(p + 4);
    const std::size_t room =
        std::size_t(end - p) - kSectionHeaderBytes - (hasCrc ? kSectionCrcBytes : 0);
    if (length > room)
        return false;
    if (!hasCrc)
        return true;
    const std::size_t covered = kSectionHeaderBytes + std::size_t(length);
    return qFromLittleEndian<quint32>(p + covered) == io::crc32c(0, p, covered);
}
} // namespace

bool Reader::findNextSection(Cursor &c, std::size_t next)
{
    const bool hasCrc = m_version >= kFirstVersionWithCrc;
    const quint32 *tags = kSectionTags + std::min<std::size_t>(next, 4);
    const std::size_t tagCount = std::size(kSectionTags) - std::min<std::size_t>(next, 4);
    const char *from = c.position();
    for (const char *p = from + 1; p < c.end(); ++p) {
        if (!sectionStartsAt(p, c.end(), hasCrc, tags, tagCount))
            continue;
        problem(c, FileErrorCode::Damaged,
                FinbookFile::tr("%1 damaged bytes could not be read; reading goes on with section "
                                "%2")
                    .arg(p - from)
                    .arg(tagName(qFromLittleEndian<quint32>(p))));
        c.skipTo(p);
        return true;
    }
    problem(c, FileErrorCode::Damaged,
            FinbookFile::tr("the last %1 bytes of the file are damaged and could not be read")
                .arg(c.end() - from));
    return false;
}

// A new id, within kMaxId, that no id of the document uses or refers to: above the largest while
// there is room, else the lowest free one (a damaged file may hold an id at the very top).
Id Reader::freshId()
{
    if (m_maxId < kMaxId)
        return ++m_maxId;
    if (!std::exchange(m_usedGathered, true))
        m_usedIds = idsIn(m_doc);
    return lowestFreeId(m_usedIds, m_lowFree);
}

// Ids that were missing, too large or used twice: each one after the first gets a new id above
// every good one (freshId), in file order, so the document is valid again. The swap sets come
// first: an object showing one of their drawings is linked to it by the set's and the drawing's ids
// and holds the drawing's stroke ids, so those follow the drawing rather than count as a clash.
void Reader::renumberClashingIds()
{
    std::unordered_set<Id> seen;
    int renumbered = 0;
    const auto fix = [&](Id &id) {
        if (id != kNoId && id <= kMaxId && seen.insert(id).second)
            return;
        id = freshId();
        seen.insert(id);
        ++renumbered;
    };
    std::vector<StrokeGroup *> linked;
    for (Frame &f : m_doc.frames)
        for (StrokeGroup &g : f.groups)
            if (g.swap.linked())
                linked.push_back(&g);
    // Each link was resolved, on reading, to the first set and drawing bearing its ids.
    std::vector<bool> rewired(linked.size(), false);
    for (SwapSet &set : m_doc.swapSets) {
        const Id oldSet = set.id;
        fix(set.id);
        for (SwapDrawing &d : set.drawings) {
            const Id oldDrawing = d.id;
            fix(d.id);
            for (Stroke &s : d.strokes)
                fix(s.id);
            for (Pin &p : d.rig.pins)
                fix(p.id);
            for (std::size_t k = 0; k < linked.size(); ++k) {
                StrokeGroup &g = *linked[k];
                if (rewired[k] || g.swap.set != oldSet || g.swap.drawing != oldDrawing)
                    continue;
                rewired[k] = true;
                g.swap = SwapLink{set.id, d.id};
                if (g.strokes.size() == d.strokes.size())
                    for (std::size_t i = 0; i < d.strokes.size(); ++i)
                        g.strokes[i].id = d.strokes[i].id;
                else // not the drawing's strokes: ids of their own
                    for (Stroke &s : g.strokes)
                        fix(s.id);
            }
        }
    }
    for (std::size_t k = 0; k < linked.size(); ++k)
        if (!rewired[k]) // a link no set answers (the reader refuses it): it stands alone
            linked[k]->swap = SwapLink{};
    for (Frame &f : m_doc.frames) {
        fix(f.id);
        for (StrokeGroup &g : f.groups) {
            fix(g.id);
            if (!g.swap.linked())
                for (Stroke &s : g.strokes)
                    fix(s.id);
            for (Pin &p : g.rig.pins)
                fix(p.id);
        }
    }
    for (SoundClip &clip : m_doc.sound)
        fix(clip.id);
    if (renumbered > 0)
        m_problems << FinbookFile::tr("%n missing or repeated id(s) were replaced by new ones",
                                      nullptr, renumbered);
}

} // namespace file_format

std::optional<QByteArray> readAncillarySection(const QByteArray &bytes, const char (&name)[5])
{
    using namespace file_format;
    if (checkHeader(bytes) || bytes.size() < qsizetype(kHeaderBytes))
        return std::nullopt;
    const bool hasCrc = qFromLittleEndian<quint32>(bytes.constData() + 8) >= kFirstVersionWithCrc;
    const quint32 wanted = tag(name);
    const char *p = bytes.constData() + kHeaderBytes;
    const char *end = bytes.constData() + bytes.size();
    while (std::size_t(end - p) >= 4) {
        const quint32 current = qFromLittleEndian<quint32>(p);
        if (!sectionStartsAt(p, end, hasCrc, &current, 1))
            break;
        const quint64 length = qFromLittleEndian<quint64>(p + 4);
        if (current == wanted)
            return QByteArray(p + kSectionHeaderBytes, qsizetype(length));
        if (current == kTagEnd)
            break;
        p += kSectionHeaderBytes + length + (hasCrc ? kSectionCrcBytes : 0);
    }
    return std::nullopt;
}

} // namespace finbook::model
