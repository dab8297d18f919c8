// A PNG encoder fed band by band (private to the model): a frame of any size is written
// without ever holding all its pixels, only a band and the compressed bytes.
#pragma once

#include <QByteArray>
#include <QImage>

#include <zlib.h>

namespace finbook::model::io {

class PngStream {
public:
    // Starts an 8-bit RGBA PNG of width × height in `out` (cleared). Needs both sides >= 1.
    PngStream(int width, int height, QByteArray *out);
    ~PngStream();
    PngStream(const PngStream &) = delete;
    PngStream &operator=(const PngStream &) = delete;

    // Appends the rows of `band` (any format, `width` wide), top to bottom. False when zlib
    // fails or more rows come than the height announced.
    bool addRows(const QImage &band);
    // Ends the image; false unless exactly `height` rows came and zlib finished cleanly.
    bool finish();

private:
    bool deflateChunk(int flush);
    void chunk(const char type[4], const char *data, qsizetype size);

    z_stream m_zip{};
    bool m_zipOpen = false;
    int m_width;
    int m_height;
    int m_rows = 0;
    QByteArray *m_out;
    QByteArray m_row;        // filter byte + RGBA of one row
    QByteArray m_compressed; // IDAT payload being filled
};

} // namespace finbook::model::io
