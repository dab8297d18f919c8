// libFuzzer target, structure-aware: the input does not hold a file, it describes one. Its
// first bytes choose a deep or wide structure (deep_structures.h: join chains and trees, long
// bone chains, many parts on one skeleton, long holds, repeated strokes) and its size (up to
// 131,072 objects, joints, frames or references: megabytes, far beyond libFuzzer's 64 KiB
// inputs); the rest are byte edits applied to the generated file. Each result goes through
// every reader and check of finbook-fuzz (fuzz_checks.h).
//
//   input := u8 shape  u8 sizeExponent  u16 sizeMantissa  u16 parts  u8 flags  u32 seed
//            (u32 offset  u8 xor)*          flags: 1 posed, 2 reversed, 4 star, 8 fix checksums
//
// Run: build/fuzz/bin/finbook-fuzz-deep -rss_limit_mb=4096 -timeout=300 -max_len=256 CORPUS
#include "../model/deep_structures.h"
#include "fuzz_checks.h"

#include <QCoreApplication>
#include <QtEndian>

namespace {
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
    if (p.shape == deep_build::Shape::Holds)
        p.n = std::min(p.n, 4096); // each frame is an object with a stroke: keep a run short
    return p;
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static QCoreApplication app(*argc, *argv); // tr() and QImage want one
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
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
