// Reading an object's "FILL" chunk (the layout is in finbook_file_format.h). Counts are checked
// against the bytes left before anything is allocated, seeds must be finite, and a fill's
// stroke ids come sorted and unique (the writer's canonical form). The ids need not name
// strokes that still exist: a fill remembers the strokes that bounded its region when it was
// made, and some of them may have been erased since; but they are ids a stroke could have.
#include "../finbook_file_reader.h"

#include <algorithm>
#include <cmath>

namespace finbook::model::file_format {

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
        const double x = c.f64(what);
        const double y = c.f64(what);
        if (!std::isfinite(x) || !std::isfinite(y))
            c.fail(FileErrorCode::BadValue, FinbookFile::tr("a fill's seed is not a number"));
        f.seed = QPointF(x, y);
        const quint32 ids = c.count(8, what);
        charge(c, qint64(ids) * qint64(sizeof(Id)));
        f.strokes.resize(ids);
        for (Id &id : f.strokes)
            id = c.u64(what);
        // Ids no stroke can have: refused (recovering, dropped). The others count towards
        // the largest id, as the writer counts them, so new strokes never take them.
        const auto invalid = [](Id id) { return id == kNoId || id > kMaxId; };
        for (Id id : f.strokes) {
            if (invalid(id))
                problem(c, FileErrorCode::BadValue,
                        FinbookFile::tr("a fill names the stroke id %1, which no stroke can have")
                            .arg(id));
            else
                m_maxId = std::max(m_maxId, id);
        }
        f.strokes.erase(std::remove_if(f.strokes.begin(), f.strokes.end(), invalid),
                        f.strokes.end());
        if (std::adjacent_find(f.strokes.begin(), f.strokes.end(), std::greater_equal<Id>()) !=
            f.strokes.end())
            c.fail(FileErrorCode::BadValue,
                   FinbookFile::tr("a fill's stroke ids are not in order"));
    }
    g.fills = std::move(fills);
}

} // namespace finbook::model::file_format
