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

QByteArray exportSoundtrackWav(const ExportSource &source, const ExportPlan &plan)
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
    return mixToWav(source.sound, lookup, source.settings.fps, from, count);
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
