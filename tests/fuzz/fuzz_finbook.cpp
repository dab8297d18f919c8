// libFuzzer target: the .finbook reader (strict and "open anyway") and the frame renderer.
//
// Invariants checked for every input, besides "no crash, no leak, no sanitizer report":
// whatever loads saves and loads again; whatever "open anyway" gives back is a valid document.
// Rendering covers paintFrame's clipping and paintList's folding at the canvas scale, capped
// at 512 pixels a side so one input stays cheap (the export of a huge canvas is banded and
// measured in app/tst_limits). Run with -rss_limit_mb and -timeout so cost bombs are findings.
#include "../../model/src/io/crc32c.h"

#include <finbook/model/finbook_file.h>
#include <finbook/model/render.h>

#include <QCoreApplication>
#include <QtEndian>

#include <cstdio>
#include <cstdlib>

namespace {
using namespace finbook::model;

void check(bool ok, const char *what)
{
    if (!ok) {
        std::fprintf(stderr, "finbook-fuzz invariant broken: %s\n", what);
        std::abort();
    }
}

// The input with every section checksum made right, so mutations inside a section reach the
// strict reader's checks instead of stopping at the checksum (format 2 on).
QByteArray withChecksums(QByteArray bytes)
{
    if (bytes.size() < 12 || qFromLittleEndian<quint32>(bytes.constData() + 8) < 2)
        return bytes;
    qsizetype at = 12;
    while (at + 16 <= bytes.size()) {
        const quint64 length = qFromLittleEndian<quint64>(bytes.constData() + at + 4);
        if (length > quint64(bytes.size() - at - 16))
            break;
        const qsizetype end = at + 12 + qsizetype(length);
        qToLittleEndian<quint32>(io::crc32c(0, bytes.constData() + at, std::size_t(end - at)),
                                 bytes.data() + end);
        at = end + 4;
    }
    return bytes;
}

void renderSome(const LoadedDocument &doc)
{
    const QSize canvas = doc.settings.canvasSize;
    const QSize size = canvas.scaled(QSize(512, 512), Qt::KeepAspectRatio).expandedTo({1, 1});
    const std::size_t frames = std::min<std::size_t>(doc.frames.size(), 3);
    for (std::size_t f = 0; f < frames; ++f) {
        const QImage image = renderFrame(doc.frames[f], doc.settings, size);
        check(image.size() == size, "renderFrame gives its size");
        RenderOptions onion;
        onion.tint = QColor(255, 0, 0);
        onion.opacity = 0.4;
        onion.showHidden = true;
        renderFrameBand(doc.frames[f], doc.settings, size, size.height() / 3, 17, onion);
    }
}

void roundTrip(LoadedDocument &doc, const char *what)
{
    Document d;
    d.reset(std::move(doc.frames), doc.settings, doc.nextId);
    const QByteArray again = serializeFinbook(d);
    auto reread = readFinbook(again);
    check(bool(reread), what);
    Document e;
    e.reset(std::move(reread->frames), reread->settings, reread->nextId);
    check(serializeFinbook(e) == again, "save -> open -> save is byte-identical");
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static QCoreApplication app(*argc, *argv); // tr() and QImage want one
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes =
        QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size));
    for (const QByteArray &input : {bytes, withChecksums(bytes)}) {
        if (auto loaded = readFinbook(input)) {
            renderSome(*loaded);
            roundTrip(*loaded, "a loaded document saves and loads again");
        }
    }
    QStringList problems;
    if (auto recovered = recoverFinbook(bytes, &problems)) {
        renderSome(*recovered);
        roundTrip(*recovered, "a recovered document saves and loads again");
    }
    readAncillarySection(bytes, "rcvy");
    return 0;
}
