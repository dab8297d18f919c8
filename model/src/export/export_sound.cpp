#include "export_sound.h"

#include "export_text.h"

#include <finbook/model/sound/sound_mix.h>

#include <QCoreApplication>
#include <QIODevice>

#include <algorithm>
#include <tuple>

namespace finbook::model {

namespace {
qint64 firstTick(const ExportSource &source, const ExportPlan &plan)
{
    if (plan.frames.empty())
        return 0;
    qint64 tick = 0;
    const int first = std::min(plan.frames.front(), int(source.frames.size()));
    for (int i = 0; i < first; ++i)
        tick += std::max(1, source.frames[std::size_t(i)].hold);
    return tick;
}

// Samples: where the range starts in the soundtrack (document time) and how long the video is
// (export time: plan.fps may differ from the document's rate).
std::pair<qint64, qint64> sampleRange(const ExportSource &source, const ExportPlan &plan)
{
    const qint64 from = sampleOfTick(double(firstTick(source, plan)), source.settings.fps);
    const qint64 count = sampleOfTick(double(plan.ticks), plan.fps);
    return {from, count};
}
} // namespace

bool exportHasSound(const ExportSource &source, const ExportOptions &options)
{
    if (options.format != ExportFormat::Mp4 && options.format != ExportFormat::WebM)
        return false;
    return std::any_of(source.sound.begin(), source.sound.end(),
                       [](const SoundClip &c) { return !c.muted && c.volume > 0.0; });
}

bool flipbookHasSound(const ExportSource &source)
{
    return std::any_of(source.sound.begin(), source.sound.end(),
                       [](const SoundClip &c) { return !c.muted && c.volume > 0.0; });
}

ExportSoundtrack::ExportSoundtrack(const ExportSource &source, const ExportOptions &options,
                                   const ExportPlan &plan)
    : m_source(source)
{
    m_carries = options.format == ExportFormat::Html ? flipbookHasSound(source)
                                                     : exportHasSound(source, options);
    if (!m_carries)
        return;
    std::tie(m_from, m_count) = sampleRange(source, plan);
    m_count = std::max<qint64>(0, m_count);
    qint64 bytes = 0;
    for (const SoundClip &clip : source.sound)
        bytes += clip.bytes.size();
    SoundBudget budget(bytes);
    for (const SoundClip &clip : source.sound) {
        if (clip.muted || clip.volume <= 0.0)
            continue;
        // Only clips reaching into the range need decoding, and only up to its end.
        const qint64 begin = sampleOfTick(double(clip.start), source.settings.fps);
        if (begin >= m_from + m_count)
            continue;
        auto decoded = decodeSound(clip.bytes, nullptr,
                                   budget.limitsFor(clip.bytes.size(), m_from + m_count - begin));
        if (!decoded) {
            m_problems
                << Export::tr("The sound \"%1\" is left out: %2").arg(clip.name, decoded.error());
            continue;
        }
        budget.spend(decoded->frames());
        m_sounds.emplace(clip.id, std::make_shared<const DecodedSound>(std::move(*decoded)));
    }
}

template <typename Block> bool ExportSoundtrack::forEachBlock(Block &&block) const
{
    const SoundLookup lookup = [this](Id id) {
        const auto it = m_sounds.find(id);
        return it == m_sounds.end() ? nullptr : it->second;
    };
    std::vector<float> mix;
    for (qint64 at = 0; at < m_count; at += kSoundRate) {
        const qint64 n = std::min<qint64>(kSoundRate, m_count - at);
        mix.assign(std::size_t(n) * kSoundChannels, 0.0f);
        mixSoundtrack(m_source.sound, lookup, m_source.settings.fps, m_from + at, n, mix.data());
        if (!block(mix))
            return false;
    }
    return true;
}

bool ExportSoundtrack::writeWav(QIODevice &device) const
{
    const QByteArray header = wavHeader(m_count * kSoundChannels, kSoundRate, kSoundChannels);
    if (device.write(header) != header.size())
        return false;
    return forEachBlock([&device](const std::vector<float> &mix) {
        const QByteArray pcm = pcmBytes(mix);
        return device.write(pcm) == pcm.size();
    });
}

QByteArray ExportSoundtrack::flipbookWav() const
{
    const qint64 samples = m_count / 2; // mono at half the rate
    QByteArray wav = wavHeader(samples, kSoundRate / 2, 1);
    wav.reserve(wav.size() + samples * 2);
    std::vector<float> small;
    forEachBlock([&](const std::vector<float> &mix) {
        small.resize(mix.size() / 4);
        for (std::size_t i = 0; i < small.size(); ++i)
            small[i] = 0.25f * (mix[4 * i] + mix[4 * i + 1] + mix[4 * i + 2] + mix[4 * i + 3]);
        wav += pcmBytes(small);
        return true;
    });
    // Odd block lengths drop a sample here and there: the header says what is there.
    wav.resize(std::min<qsizetype>(wav.size(), 44 + samples * 2));
    wav.append(QByteArray(44 + samples * 2 - wav.size(), '\0'));
    return wav;
}

QStringList soundInputArguments(const QString &wavPath)
{
    return {QStringLiteral("-f"), QStringLiteral("wav"), QStringLiteral("-i"),
            QStringLiteral("file:") + wavPath};
}

QStringList soundOutputArguments(ExportFormat format)
{
    QStringList args{QStringLiteral("-map"), QStringLiteral("0:v"), QStringLiteral("-map"),
                     QStringLiteral("1:a")};
    if (format == ExportFormat::WebM)
        args << QStringLiteral("-c:a") << QStringLiteral("libopus") << QStringLiteral("-b:a")
             << QStringLiteral("128k");
    else
        args << QStringLiteral("-c:a") << QStringLiteral("aac") << QStringLiteral("-b:a")
             << QStringLiteral("192k");
    return args;
}

} // namespace finbook::model
