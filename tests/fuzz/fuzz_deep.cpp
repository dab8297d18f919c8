// libFuzzer target, structure-aware: the input does not hold a file, it describes one. Its
// first bytes choose a deep or wide structure (deep_structures.h: join chains and trees, long
// bone chains, many parts on one skeleton, long holds, repeated strokes, many layers of cels
// with properties at and past their limits) and its size (up to
// 131,072 objects, joints, frames or references: megabytes, far beyond libFuzzer's 64 KiB
// inputs); the rest are byte edits applied to the generated file. Each result goes through
// every reader and check of finbook-fuzz (fuzz_checks.h).
//
//   input := u8 shape  u8 sizeExponent  u16 sizeMantissa  u16 parts  u8 flags  u32 seed
//            (u32 offset  u8 xor)*          flags: 1 posed, 2 reversed, 4 star, 8 fix checksums
//
// A shape byte with its top bit set asks for embedded media instead (issue 47): a document
// whose sound clips are WAVs with the input's header fields (sample rate, channels, bits, the
// data size it announces, how many clips) and whose reference is an SVG of <use> nested as
// deep and wide as the input says; decoding them (fuzz_checks.h) must stay within the limits.
//
//   media := u8 shape|0x80  u32 rate  u8 channels  u8 bits  u32 announced  u8 clips
//            u8 useLevels  u8 useFanout  u16 samples  [u16 cameraKeys  u8 cameraSeed]
//
// The camera (issue 46) rides along: up to 65,535 keys of every easing, their values spread by
// the seed over the whole allowed range (zooms from a twentieth to fifty, turns of a hundred
// revolutions, Bézier handles that overshoot).
//
// Run: build/fuzz/bin/finbook-fuzz-deep -rss_limit_mb=4096 -timeout=300 -max_len=256 CORPUS
#include "../model/deep_structures.h"
#include "fuzz_checks.h"

#include <finbook/model/reference/reference_layer.h>
#include <finbook/model/sound/sound_commands.h>

#include <QCoreApplication>
#include <QtEndian>

#include <cmath>

namespace {
using namespace finbook::model;

constexpr int kMaxCount = 1 << 17;
constexpr std::size_t kHeaderBytes = 11;
constexpr std::size_t kEditBytes = 5;

deep_build::Params paramsOf(const uint8_t *data)
{
    deep_build::Params p;
    p.shape = deep_build::Shape(data[0] % std::uint8_t(deep_build::Shape::Count));
    // A size spread over every scale: 2^e (e ≤ 17) plus a mantissa below it.
    const int exponent = data[1] % 18;
    const int mantissa = qFromLittleEndian<quint16>(data + 2) % (1 << exponent);
    p.n = std::min(kMaxCount, (1 << exponent) + mantissa);
    p.parts = qFromLittleEndian<quint16>(data + 4) % (kMaxCount / 8);
    p.posed = data[6] & 1;
    p.reversed = data[6] & 2;
    p.star = data[6] & 4;
    p.seed = qFromLittleEndian<quint32>(data + 7);
    // Each frame (or cel) is an object with a stroke: keep a run short. 4,096 layers is
    // still four times what a file may hold.
    if (p.shape == deep_build::Shape::Holds || p.shape == deep_build::Shape::Layers)
        p.n = std::min(p.n, 4096);
    return p;
}
constexpr std::size_t kMediaBytes = 16;

// A WAV of `samples` bytes of data whose header says what the input says.
QByteArray wavWithHeader(const uint8_t *data)
{
    const quint32 rate = qFromLittleEndian<quint32>(data + 1);
    const quint16 channels = data[5];
    const quint16 bits = data[6];
    const quint32 announced = qFromLittleEndian<quint32>(data + 7);
    const int samples = qFromLittleEndian<quint16>(data + 14);
    QByteArray wav(44 + samples, '\0');
    char *p = wav.data();
    const auto u32 = [&p](quint32 v) { qToLittleEndian<quint32>(v, p), p += 4; };
    const auto u16 = [&p](quint16 v) { qToLittleEndian<quint16>(v, p), p += 2; };
    const auto text = [&p](const char *four) { std::copy(four, four + 4, p), p += 4; };
    text("RIFF");
    u32(quint32(36 + samples));
    text("WAVE");
    text("fmt ");
    u32(16);
    u16(1);
    u16(channels);
    u32(rate);
    u32(rate * channels * std::max<quint32>(1, bits / 8));
    u16(quint16(channels * std::max(1, bits / 8)));
    u16(bits);
    text("data");
    u32(announced);
    for (int i = 0; i < samples; ++i)
        p[i] = char(i * 37);
    return wav;
}

QByteArray svgOfUses(int levels, int fanout)
{
    QByteArray svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" "
                     "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"64\" height=\"64\">"
                     "<defs><rect id=\"l0\" width=\"1\" height=\"1\"/>";
    for (int level = 1; level <= levels; ++level) {
        svg += "<g id=\"l" + QByteArray::number(level) + "\">";
        for (int i = 0; i < fanout; ++i)
            svg += "<use xlink:href=\"#l" + QByteArray::number(level - 1) + "\" x=\"" +
                   QByteArray::number(i) + "\"/>";
        svg += "</g>";
    }
    return svg + "</defs><use xlink:href=\"#l" + QByteArray::number(levels) + "\"/></svg>";
}

// `count` camera keys, values spread over the allowed ranges by `seed`.
CameraTrack cameraOf(int count, std::uint8_t seed)
{
    CameraTrack track;
    std::uint32_t x = 2166136261u ^ seed;
    const auto unit = [&x] {
        x = x * 1664525u + 1013904223u;
        return double(x >> 8) / double(1u << 24);
    };
    for (int i = 0; i < count; ++i) {
        CameraKey k;
        k.tick = qint64(i) * (1 + seed % 13);
        k.center = QPointF((unit() * 2 - 1) * kMaxCameraReach, (unit() * 2 - 1) * kMaxCameraReach);
        k.zoom = kMinCameraZoom * std::pow(kMaxCameraZoom / kMinCameraZoom, unit());
        k.rotation = (unit() * 2 - 1) * kMaxCameraTurn;
        k.easing = CameraEasing(i % kCameraEasingCount);
        k.control1 = QPointF(unit(), unit() * 3 - 1);
        k.control2 = QPointF(unit(), unit() * 3 - 1);
        if (k.tick <= kMaxCameraTick)
            track.keys.push_back(k);
    }
    return track;
}

QByteArray mediaFile(const uint8_t *data, std::size_t size)
{
    Document doc;
    if (size >= kMediaBytes + 3)
        doc.setCamera(
            cameraOf(qFromLittleEndian<quint16>(data + kMediaBytes), data[kMediaBytes + 2]));
    const QByteArray wav = wavWithHeader(data);
    const int clips = 1 + data[11] % kMaxSoundClips;
    for (int i = 0; i < clips; ++i) {
        SoundClip clip;
        clip.name = QStringLiteral("c.wav");
        clip.bytes = wav;
        doc.undoStack()->push(new AddSoundClipCommand(&doc, clip));
    }
    Reference r;
    r.kind = ReferenceKind::Image;
    r.name = QStringLiteral("uses.svg");
    r.bytes = svgOfUses(data[12] % 16, data[13] % 16);
    r.mediaSize = QSizeF(64, 64);
    doc.referenceLayer().setReference(r);
    return serializeFinbook(doc);
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static QCoreApplication app(*argc, *argv); // tr() and QImage want one
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size >= kMediaBytes && (data[0] & 0x80)) {
        fuzz_checks::readEveryWay(mediaFile(data, size));
        return 0;
    }
    if (size < kHeaderBytes)
        return 0;
    const deep_build::Params p = paramsOf(data);
    QByteArray bytes = deep_build::file(p);
    for (std::size_t at = kHeaderBytes; at + kEditBytes <= size; at += kEditBytes) {
        const quint32 offset = qFromLittleEndian<quint32>(data + at);
        bytes[qsizetype(offset % quint32(bytes.size()))] ^= char(data[at + 4]);
    }
    if (data[6] & 8)
        bytes = fuzz_checks::withChecksums(bytes);
    fuzz_checks::readEveryWay(bytes);
    return 0;
}
