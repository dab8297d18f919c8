// Checks shared by the fuzz targets (fuzz_finbook.cpp on raw bytes, fuzz_deep.cpp on generated
// deep and wide structures). Besides "no crash, no leak, no sanitizer report": whatever loads
// saves and loads again; whatever "open anyway" gives back is a valid document.
#pragma once

#include "../../model/src/io/crc32c.h"

#include <finbook/model/export/export_plan.h>
#include <finbook/model/finbook_file.h>
#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/reference/reference_media.h>
#include <finbook/model/render.h>
#include <finbook/model/sound/sound_decode.h>

#include <QtEndian>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace fuzz_checks {
using namespace finbook::model;

inline void check(bool ok, const char *what)
{
    if (!ok) {
        std::fprintf(stderr, "finbook-fuzz invariant broken: %s\n", what);
        std::abort();
    }
}

// The input with every section checksum made right, so mutations inside a section reach the
// strict reader's checks instead of stopping at the checksum (format 2 on).
inline QByteArray withChecksums(QByteArray bytes)
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

inline void renderSome(const LoadedDocument &doc)
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
    // Through the camera (issue 46): at its first and last key and halfway, a finite shot of
    // the export's size.
    if (doc.camera.isEmpty() || doc.frames.empty())
        return;
    ExportPlan plan;
    plan.size = size;
    const double first = double(doc.camera.keys.front().tick);
    const double last = double(doc.camera.keys.back().tick);
    for (double tick : {first, (first + last) / 2.0 + 0.5, last}) {
        const CameraState state = cameraAt(doc.camera, tick, QSizeF(canvas));
        check(std::isfinite(state.center.x()) && std::isfinite(state.center.y()) &&
                  std::isfinite(state.zoom) && state.zoom > 0.0 && std::isfinite(state.rotation),
              "the camera between valid keys is finite");
        check(
            renderExportFrame(doc.frames.front(), doc.settings, plan, nullptr, {}, &state).size() ==
                size,
            "a shot through the camera has the export's size");
    }
}

inline void roundTrip(LoadedDocument &doc, const char *what)
{
    Document d;
    adoptLoadedDocument(d, std::move(doc)); // the sound clips too
    const QByteArray again = serializeFinbook(d);
    auto reread = readFinbook(again);
    if (!reread)
        std::fprintf(stderr, "finbook-fuzz: the saved copy does not open: %s\n",
                     qPrintable(reread.error().message));
    check(bool(reread), what);
    Document e;
    adoptLoadedDocument(e, std::move(*reread));
    check(serializeFinbook(e) == again, "save -> open -> save is byte-identical");
}

// The embedded media as the editor and an export decode them: every clip within one soundtrack
// budget, and a few pictures of the reference. What decodes stays within the limits the
// budget promised (issue 47: a few KB of sound decoded to gigabytes).
inline void decodeMedia(const LoadedDocument &doc)
{
    qint64 bytes = 0;
    for (const SoundClip &clip : doc.sound)
        bytes += clip.bytes.size();
    SoundBudget budget(bytes);
    const auto allowed = qint64(soundSecondsAllowed(bytes, kMaxSoundtrackSeconds) * kSoundRate);
    for (const SoundClip &clip : doc.sound) {
        const SoundDecodeLimits limits = budget.limitsFor(clip.bytes.size());
        if (auto sound = decodeSound(clip.bytes, nullptr, limits)) {
            check(sound->frames() <= limits.maxFrames, "a clip decodes within its limit");
            budget.spend(sound->frames());
            check(budget.spentFrames() <= allowed, "the soundtrack decodes within its budget");
            computeWaveform(*sound);
        }
    }
    if (doc.reference.isEmpty())
        return;
    if (auto media = ReferenceMedia::open(doc.reference)) {
        const QSize size = (*media)->size();
        for (qint64 i : {qint64(0), (*media)->frameCount() / 2, (*media)->frameCount() - 1}) {
            const QImage picture = (*media)->frame(i);
            check(picture.isNull() || picture.size() == size ||
                      doc.reference.kind == ReferenceKind::Sequence,
                  "a reference's pictures have its size");
        }
    }
}

// Everything a file goes through: the strict reader (as is and with its checksums made
// right), "open anyway", the description reader.
inline void readEveryWay(const QByteArray &bytes)
{
    for (const QByteArray &input : {bytes, withChecksums(bytes)}) {
        if (auto loaded = readFinbook(input)) {
            renderSome(*loaded);
            decodeMedia(*loaded);
            roundTrip(*loaded, "a loaded document saves and loads again");
        }
    }
    QStringList problems;
    if (auto recovered = recoverFinbook(bytes, &problems)) {
        renderSome(*recovered);
        roundTrip(*recovered, "a recovered document saves and loads again");
    }
    readAncillarySection(bytes, "rcvy");
}

} // namespace fuzz_checks
