// Reading the "LAYR" section: the layers and how many of FRAM's frames each holds (layout in
// finbook_file_format.h). The count is checked against the section's bytes before anything is
// allocated. Opening anyway, a value out of range is set to its default and the counts are
// made to add up (the last layer takes the frames left over).
#include "../finbook_file_reader.h"

#include <cmath>

namespace finbook::model::file_format {

void Reader::readLayersSection(Cursor &body)
{
    m_where = Where();
    m_where.section = FinbookFile::tr("the layers");
    try {
        const char *what = QT_TRANSLATE_NOOP("FinbookFile", "the layers");
        const quint32 n = count(body, kLayerFixedBytes, what);
        if (n == 0 || n > quint32(kMaxLayers))
            body.fail(FileErrorCode::BadValue,
                      FinbookFile::tr("the file has %1 layers (1 to %2)").arg(n).arg(kMaxLayers));
        charge(body, qint64(n) * qint64(sizeof(LoadedLayer)));
        std::vector<LoadedLayer> layers;
        layers.reserve(n);
        for (quint32 i = 0; i < n; ++i) {
            m_where.layer = int(i + 1);
            LoadedLayer l;
            l.id = Id(body.u64(what));
            claimId(body, l.id, FinbookFile::tr("the layer"));
            const quint32 cels = body.u32(what);
            const quint8 flags = body.u8(what);
            l.properties.visible = !(flags & kLayerFlagHidden);
            l.properties.locked = flags & kLayerFlagLocked;
            l.properties.onionSkin = !(flags & kLayerFlagNoOnion);
            l.properties.opacity = body.f64(what);
            l.properties.depth = body.f64(what);
            l.properties.name = readName(body);
            if (!(l.properties.opacity >= 0.0 && l.properties.opacity <= 1.0)) {
                problem(body, FileErrorCode::BadValue,
                        FinbookFile::tr("its opacity is not between 0 and 1"));
                l.properties.opacity = 1.0;
            }
            if (!(l.properties.depth >= kMinLayerDepth && l.properties.depth <= kMaxLayerDepth)) {
                problem(body, FileErrorCode::BadValue,
                        FinbookFile::tr("its depth is not between %1 and %2")
                            .arg(kMinLayerDepth)
                            .arg(kMaxLayerDepth));
                l.properties.depth = 0.0;
            }
            l.cels = int(std::min<quint32>(cels, quint32(m_doc.frames.size()) + 1));
            layers.push_back(std::move(l));
        }
        m_where.layer = 0;
        body.expectEnd(what);
        qint64 total = 0;
        for (const LoadedLayer &l : layers)
            total += l.cels;
        if (total != qint64(m_doc.frames.size())) {
            problem(body, FileErrorCode::BadValue,
                    FinbookFile::tr("the layers hold %1 frames, but the file has %2")
                        .arg(total)
                        .arg(m_doc.frames.size()));
            // Opening anyway: the frames are dealt out in order, the last layer takes the rest.
            qint64 left = qint64(m_doc.frames.size());
            for (LoadedLayer &l : layers) {
                l.cels = int(std::min<qint64>(l.cels, left));
                left -= l.cels;
            }
            layers.back().cels += int(left);
        }
        if (m_mode != ParseMode::Check)
            m_doc.layers = std::move(layers);
    } catch (const ReadFailure &failure) {
        if (!recovering())
            throw;
        m_where.layer = 0;
        m_problems << FinbookFile::tr("%1; every frame is put on one layer").arg(failure.what);
    }
}

} // namespace finbook::model::file_format
