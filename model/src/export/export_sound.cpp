#include "export_sound.h"

#include <finbook/model/sound/sound_mix.h>

#include <algorithm>
#include <unordered_map>

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

namespace {
std::vector<float> rangeMix(const ExportSource &source, const ExportPlan &plan);
} // namespace

QByteArray exportSoundtrackWav(const ExportSource &source, const ExportPlan &plan)
{
    return wavBytes(rangeMix(source, plan), kSoundRate, kSoundChannels);
}

QByteArray flipbookSoundtrackWav(const ExportSource &source, const ExportPlan &plan)
{
    const std::vector<float> mix = rangeMix(source, plan);
    std::vector<float> small(mix.size() / 4);
    for (std::size_t i = 0; i < small.size(); ++i)
        small[i] = 0.25f * (mix[4 * i] + mix[4 * i + 1] + mix[4 * i + 2] + mix[4 * i + 3]);
    return wavBytes(small, kSoundRate / 2, 1);
}

namespace {
std::vector<float> rangeMix(const ExportSource &source, const ExportPlan &plan)
{
    const auto [from, count] = sampleRange(source, plan);
    std::unordered_map<Id, DecodedSoundPtr> sounds;
    for (const SoundClip &clip : source.sound) {
        if (clip.muted || clip.volume <= 0.0)
            continue;
        // Only clips reaching into the range need decoding.
        if (sampleOfTick(double(clip.start), source.settings.fps) >= from + count)
            continue;
        if (auto decoded = decodeSound(clip.bytes))
            sounds.emplace(clip.id, std::make_shared<const DecodedSound>(std::move(*decoded)));
    }
    const SoundLookup lookup = [&sounds](Id id) {
        const auto it = sounds.find(id);
        return it == sounds.end() ? nullptr : it->second;
    };
    std::vector<float> mix(std::size_t(std::max<qint64>(0, count)) * kSoundChannels, 0.0f);
    mixSoundtrack(source.sound, lookup, source.settings.fps, from, count, mix.data());
    return mix;
}
} // namespace

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
