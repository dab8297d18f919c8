// PNG frames of an export, rendered and compressed band by band (io/png_stream.h).
#include "../io/png_stream.h"
#include "export_formats.h"

#include <new>

namespace finbook::model {

QByteArray ExportContext::png(std::size_t planIndex) const
{
    const QSize size = plan.size;
    const int rows = exportBandRows(plan);
    if (rows < 1)
        return {};
    QByteArray bytes;
    try {
        io::PngStream stream(size.width(), size.height(), &bytes);
        for (int top = 0; top < size.height(); top += rows) {
            const QImage band = renderBand(planIndex, top, std::min(rows, size.height() - top));
            if (band.isNull() || !stream.addRows(band))
                return {};
        }
        if (!stream.finish())
            return {};
    } catch (const std::bad_alloc &) {
        return {};
    }
    return bytes;
}

} // namespace finbook::model
