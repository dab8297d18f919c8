// Reading an object's "FILL" chunk (the layout is in finbook_file_format.h). Counts are checked
// against the bytes left before anything is allocated, seeds must be finite, and a fill's
// stroke ids come sorted and unique (the writer's canonical form). The ids need not name
// strokes that still exist: a fill remembers the strokes that bounded its region when it was
// made, and some of them may have been erased since; but they are ids a stroke could have.
#include "../finbook_file_reader.h"

#include <algorithm>
#include <cmath>

namespace finbook::model::file_format {

void Reader::readFillStrokeIds(Cursor &c, std::vector<Id> &ids, const char *what)
{
    const quint32 n = c.count(8, what);
    charge(c, qint64(n) * qint64(sizeof(Id)));
    ids.resize(n);
    for (Id &id : ids)
        id = c.u64(what);
    // Ids no stroke can have: refused (recovering, dropped). The others count towards the
    // largest id, as the writer counts them, so new strokes never take them.
    const auto invalid = [](Id id) { return id == kNoId || id > kMaxId; };
    for (Id id : ids) {
        if (invalid(id))
            problem(
                c, FileErrorCode::BadValue,
                FinbookFile::tr("a fill names the stroke id %1, which no stroke can have").arg(id));
        else
            m_maxId = std::max(m_maxId, id);
    }
    ids.erase(std::remove_if(ids.begin(), ids.end(), invalid), ids.end());
    if (std::adjacent_find(ids.begin(), ids.end(), std::greater_equal<Id>()) != ids.end())
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("a fill's stroke ids are not in order"));
}

namespace {
QPointF seedPoint(Cursor &c, const char *what)
{
    const double x = c.f64(what);
    const double y = c.f64(what);
    if (!std::isfinite(x) || !std::isfinite(y))
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("a fill's seed is not a number"));
    return QPointF(x, y);
}
} // namespace

void Reader::readFillsChunk(Cursor &c, StrokeGroup &g)
{
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the fill list");
    const quint32 n = c.count(kFillFixedBytes, what);
    if (n > quint32(kMaxFillsPerObject))
        c.fail(FileErrorCode::TooLarge, FinbookFile::tr("the object claims %1 fills, more than %2")
                                            .arg(n)
                                            .arg(kMaxFillsPerObject));
    charge(c, qint64(n) * qint64(sizeof(Fill)));
    std::vector<Fill> fills(n);
    for (Fill &f : fills) {
        f.color = c.u32(what);
        f.seed = seedPoint(c, what);
        readFillStrokeIds(c, f.strokes, what);
    }
    g.fills = std::move(fills);
}

// Each fill's further regions (Fill::more), one entry per fill of the FILL chunk before it.
// Together with the fills, no more regions than kMaxFillsPerObject.
void Reader::readFillPlacesChunk(Cursor &c, StrokeGroup &g)
{
    const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the fill regions");
    const quint32 n = c.count(4, what);
    if (n != g.fills.size())
        c.fail(FileErrorCode::BadValue, FinbookFile::tr("the object gives regions of %1 fills but "
                                                        "has %2")
                                            .arg(n)
                                            .arg(g.fills.size()));
    std::size_t regions = g.fills.size();
    for (Fill &f : g.fills) {
        const quint32 places = c.count(8 + 8 + 4, what);
        regions += places;
        if (regions > std::size_t(kMaxFillsPerObject))
            c.fail(FileErrorCode::TooLarge,
                   FinbookFile::tr("the object's fills claim more than %1 regions")
                       .arg(kMaxFillsPerObject));
        charge(c, qint64(places) * qint64(sizeof(FillPlace)));
        f.more.resize(places);
        for (FillPlace &p : f.more) {
            p.seed = seedPoint(c, what);
            readFillStrokeIds(c, p.strokes, what);
        }
    }
}

} // namespace finbook::model::file_format
