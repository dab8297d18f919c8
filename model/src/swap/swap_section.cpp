// Reading the "SWAP" section: the swap sets and which object shows which drawing (layout in
// finbook_file_format.h). Counts are checked against the section's bytes before anything is
// allocated. A link to an object, set or drawing that is not there is a damaged file; opening
// anyway, the section is left out and every object keeps the drawing it showed.
#include "../finbook_file_reader.h"

#include <algorithm>

namespace finbook::model::file_format {

void Reader::readSwapSection(Cursor &body)
{
    m_where = Where();
    m_where.section = FinbookFile::tr("the swap sets");
    try {
        const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the swap sets");
        const quint32 n = count(body, kSwapSetFixedBytes, what);
        if (n > quint32(kMaxSwapSets))
            body.fail(
                FileErrorCode::TooLarge,
                FinbookFile::tr("the file has %1 swap sets (at most %2)").arg(n).arg(kMaxSwapSets));
        charge(body, qint64(n) * qint64(sizeof(SwapSet)));
        std::vector<SwapSet> sets;
        sets.reserve(n);
        for (quint32 i = 0; i < n; ++i) {
            SwapSet set;
            set.id = Id(body.u64(what));
            claimId(body, set.id, FinbookFile::tr("swap set %1").arg(i + 1));
            set.name = readName(body);
            const quint32 drawings = count(body, 4 + kObjectFixedBytes, what);
            if (drawings == 0 || drawings > quint32(kMaxSwapDrawings))
                body.fail(FileErrorCode::BadValue,
                          FinbookFile::tr("swap set %1 has %2 drawings (1 to %3)")
                              .arg(i + 1)
                              .arg(drawings)
                              .arg(kMaxSwapDrawings));
            charge(body, qint64(drawings) * qint64(sizeof(StrokeGroup)));
            for (quint32 k = 0; k < drawings; ++k) {
                Cursor record = body.record(body.u32(what), what);
                StrokeGroup g = readObject(record);
                if (g.deformed)
                    body.fail(
                        FileErrorCode::BadValue,
                        FinbookFile::tr("a drawing of swap set %1 carries a pose").arg(i + 1));
                set.drawings.push_back(SwapDrawing{g.id, g.name, std::move(g.strokes),
                                                   std::move(g.fills), g.meshDensity,
                                                   std::move(g.rig)});
            }
            sets.push_back(std::move(set));
        }
        m_where = Where();
        m_where.section = FinbookFile::tr("the swap sets");
        const quint32 links = count(body, kSwapLinkBytes, what);
        std::vector<std::pair<Id, SwapLink>> linked;
        linked.reserve(links);
        for (quint32 i = 0; i < links; ++i) {
            const Id object = Id(body.u64(what));
            SwapLink link;
            link.set = Id(body.u64(what));
            link.drawing = Id(body.u64(what));
            const auto set = std::find_if(sets.begin(), sets.end(),
                                          [&](const SwapSet &s) { return s.id == link.set; });
            if (set == sets.end() || !set->drawing(link.drawing))
                body.fail(FileErrorCode::BadValue,
                          FinbookFile::tr("object %1 shows a drawing the swap sets do not hold")
                              .arg(object));
            linked.emplace_back(object, link);
        }
        body.expectEnd(what);
        std::sort(linked.begin(), linked.end(),
                  [](const auto &a, const auto &b) { return a.first < b.first; });
        std::vector<StrokeGroup *> objects;
        for (Frame &f : m_doc.frames)
            for (StrokeGroup &g : f.groups) {
                const auto it =
                    std::lower_bound(linked.begin(), linked.end(), g.id,
                                     [](const auto &entry, Id id) { return entry.first < id; });
                if (it != linked.end() && it->first == g.id)
                    objects.push_back(&g);
            }
        if (objects.size() != linked.size())
            body.fail(FileErrorCode::BadValue,
                      FinbookFile::tr("the swap sets link objects the frames do not hold"));
        // A frame shows a set on one object at most: two would hold the same strokes.
        for (const Frame &f : m_doc.frames) {
            std::vector<Id> setsHere;
            for (const StrokeGroup &g : f.groups) {
                const auto it =
                    std::lower_bound(linked.begin(), linked.end(), g.id,
                                     [](const auto &entry, Id id) { return entry.first < id; });
                if (it == linked.end() || it->first != g.id)
                    continue;
                if (std::find(setsHere.begin(), setsHere.end(), it->second.set) != setsHere.end())
                    body.fail(FileErrorCode::BadValue,
                              FinbookFile::tr("a frame shows a swap set on two objects"));
                setsHere.push_back(it->second.set);
            }
        }
        for (StrokeGroup *g : objects) {
            g->swap =
                std::lower_bound(linked.begin(), linked.end(), g->id, [](const auto &entry, Id id) {
                    return entry.first < id;
                })->second;
            // Its stroke ids are its drawing's, claimed there: not a clash.
            for (const Stroke &s : g->strokes)
                m_sharedIds.push_back(s.id);
        }
        if (m_mode != ParseMode::Check)
            m_doc.swapSets = std::move(sets);
    } catch (const ReadFailure &failure) {
        if (!recovering())
            throw;
        m_problems << FinbookFile::tr("%1; the swap sets are left out").arg(failure.what);
    }
}

} // namespace finbook::model::file_format
