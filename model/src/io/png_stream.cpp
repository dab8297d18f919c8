// PngStream: signature, IHDR, IDAT chunks as deflate fills them, IEND (PNG spec, ISO 15948).
#include "png_stream.h"

#include <QtEndian>

#include <cstring>

namespace finbook::model::io {

namespace {
constexpr char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
constexpr qsizetype kIdatBytes = 1 << 16;
} // namespace

PngStream::PngStream(int width, int height, QByteArray *out)
    : m_width(width)
    , m_height(height)
    , m_out(out)
{
    m_out->clear();
    m_out->append(kSignature, sizeof(kSignature));
    char header[13];
    qToBigEndian<quint32>(quint32(width), header);
    qToBigEndian<quint32>(quint32(height), header + 4);
    header[8] = 8;  // bits per channel
    header[9] = 6;  // colour type: RGBA
    header[10] = 0; // deflate
    header[11] = 0; // adaptive filtering (each row says its filter)
    header[12] = 0; // not interlaced
    chunk("IHDR", header, sizeof(header));
    m_zipOpen = deflateInit(&m_zip, Z_DEFAULT_COMPRESSION) == Z_OK;
    m_row.resize(1 + qsizetype(width) * 4);
    m_compressed.resize(kIdatBytes);
    m_zip.next_out = reinterpret_cast<Bytef *>(m_compressed.data());
    m_zip.avail_out = uInt(kIdatBytes);
}

PngStream::~PngStream()
{
    if (m_zipOpen)
        deflateEnd(&m_zip);
}

void PngStream::chunk(const char type[4], const char *data, qsizetype size)
{
    char length[4];
    qToBigEndian<quint32>(quint32(size), length);
    m_out->append(length, 4);
    const qsizetype start = m_out->size();
    m_out->append(type, 4);
    m_out->append(data, size);
    const uLong crc =
        crc32(crc32(0L, nullptr, 0), reinterpret_cast<const Bytef *>(m_out->constData() + start),
              uInt(size + 4));
    char sum[4];
    qToBigEndian<quint32>(quint32(crc), sum);
    m_out->append(sum, 4);
}

// Runs deflate over the pending input; each full output buffer becomes an IDAT chunk, and on
// Z_FINISH so does the rest.
bool PngStream::deflateChunk(int flush)
{
    for (;;) {
        const int result = deflate(&m_zip, flush);
        if (result == Z_STREAM_ERROR)
            return false;
        if (m_zip.avail_out == 0) {
            chunk("IDAT", m_compressed.constData(), kIdatBytes);
            m_zip.next_out = reinterpret_cast<Bytef *>(m_compressed.data());
            m_zip.avail_out = uInt(kIdatBytes);
            continue;
        }
        // Room left in the output: deflate took all the input (and, finishing, ended).
        if (flush != Z_FINISH)
            return true;
        if (result != Z_STREAM_END)
            return false;
        const qsizetype rest = kIdatBytes - qsizetype(m_zip.avail_out);
        if (rest > 0)
            chunk("IDAT", m_compressed.constData(), rest);
        return true;
    }
}

bool PngStream::addRows(const QImage &band)
{
    if (!m_zipOpen || band.width() != m_width || m_rows + band.height() > m_height)
        return false;
    const QImage rgba = band.convertToFormat(QImage::Format_RGBA8888);
    if (rgba.isNull())
        return false;
    for (int y = 0; y < rgba.height(); ++y) {
        m_row[0] = 0; // filter: none
        std::memcpy(m_row.data() + 1, rgba.constScanLine(y), std::size_t(m_width) * 4);
        m_zip.next_in = reinterpret_cast<Bytef *>(m_row.data());
        m_zip.avail_in = uInt(m_row.size());
        if (!deflateChunk(Z_NO_FLUSH))
            return false;
    }
    m_rows += rgba.height();
    return true;
}

bool PngStream::finish()
{
    if (!m_zipOpen || m_rows != m_height)
        return false;
    m_zip.next_in = nullptr;
    m_zip.avail_in = 0;
    if (!deflateChunk(Z_FINISH))
        return false;
    chunk("IEND", nullptr, 0);
    return true;
}

} // namespace finbook::model::io
