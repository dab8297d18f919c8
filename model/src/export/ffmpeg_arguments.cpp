#include "ffmpeg_arguments.h"

#include "export_sound.h"
#include "export_text.h"

#include <cmath>

namespace finbook::model {

namespace {
// Linux refuses a single argument longer than 128 KiB; stay well below.
constexpr qsizetype kMaxExpression = 100000;

QStringList inputArguments(const ExportPlan &plan)
{
    // -xerror: without it ffmpeg 5.1 reports a failed write (a full disk) and still exits
    // with 0, leaving a truncated file.
    return {QStringLiteral("-hide_banner"),
            QStringLiteral("-nostats"),
            QStringLiteral("-loglevel"),
            QStringLiteral("error"),
            QStringLiteral("-xerror"),
            QStringLiteral("-f"),
            QStringLiteral("rawvideo"),
            QStringLiteral("-pix_fmt"),
            QStringLiteral("bgra"), // QImage::Format_ARGB32 in little-endian memory
            QStringLiteral("-video_size"),
            QStringLiteral("%1x%2").arg(plan.size.width()).arg(plan.size.height()),
            QStringLiteral("-framerate"),
            QString::number(plan.fps),
            QStringLiteral("-i"),
            QStringLiteral("pipe:0")};
}

// Two runs over the same frames, so that memory does not grow with their number: one
// filter graph splitting the stream into palettegen and paletteuse would hold every frame
// until palettegen has seen the last one (2.4 GB for 2,000 frames at 640×480). The first run
// only counts colours into the palette (a PNG); the second maps each frame to it as it comes.
FfmpegJob gifJob(const ExportPlan &plan, const QString &palette)
{
    FfmpegJob job;
    job.what = Export::tr("GIF");
    const QString timestamps = holdTimestamps(plan.holds);
    job.perTick = timestamps.isEmpty();
    job.paletteArguments << QStringLiteral("-vf")
                         << QStringLiteral("palettegen=stats_mode=full:reserve_transparent=%1")
                                .arg(plan.transparent ? 1 : 0)
                         << QStringLiteral("-update") << QStringLiteral("1")
                         << QStringLiteral("-c:v") << QStringLiteral("png") << QStringLiteral("-f")
                         << QStringLiteral("image2") << QStringLiteral("-y")
                         << QStringLiteral("file:") + palette;
    const QString setpts =
        job.perTick ? QString() : QStringLiteral("setpts=(%1)/(FR*TB)").arg(timestamps);
    // The frames are input 0 (from inputArguments), the palette input 1.
    const QString graph =
        (setpts.isEmpty() ? QStringLiteral("[0:v]")
                          : QStringLiteral("[0:v]%1[v];[v]").arg(setpts)) +
        QStringLiteral("[1:v]paletteuse=dither=sierra2_4a:diff_mode=rectangle:alpha_threshold=128");
    // GIF delays are centiseconds; the last drawing's hold is not known to ffmpeg otherwise.
    const int lastTicks = job.perTick ? 1 : plan.holds.back();
    const int finalDelay = int(std::lround(lastTicks * 100.0 / plan.fps));
    job.arguments << QStringLiteral("-f") << QStringLiteral("png_pipe") << QStringLiteral("-i")
                  << QStringLiteral("file:") + palette << QStringLiteral("-filter_complex") << graph
                  << QStringLiteral("-fps_mode") << QStringLiteral("passthrough")
                  << QStringLiteral("-loop")
                  << (plan.loop ? QStringLiteral("0") : QStringLiteral("-1"))
                  << QStringLiteral("-final_delay") << QString::number(finalDelay)
                  << QStringLiteral("-f") << QStringLiteral("gif");
    return job;
}

FfmpegJob mp4Job()
{
    FfmpegJob job;
    job.what = Export::tr("MP4 video");
    // BT.709 in the stream and in its tags, so browsers and phones show the same colours.
    job.arguments << QStringLiteral("-vf")
                  << QStringLiteral("scale=out_color_matrix=bt709:out_range=tv,format=yuv420p")
                  << QStringLiteral("-c:v") << QStringLiteral("libx264")
                  << QStringLiteral("-preset") << QStringLiteral("medium") << QStringLiteral("-crf")
                  << QStringLiteral("18") << QStringLiteral("-tune") << QStringLiteral("animation")
                  << QStringLiteral("-color_primaries") << QStringLiteral("bt709")
                  << QStringLiteral("-color_trc") << QStringLiteral("bt709")
                  << QStringLiteral("-colorspace") << QStringLiteral("bt709")
                  << QStringLiteral("-movflags") << QStringLiteral("+faststart")
                  << QStringLiteral("-f") << QStringLiteral("mp4");
    return job;
}

FfmpegJob webmJob(const ExportPlan &plan)
{
    FfmpegJob job;
    job.what = Export::tr("WebM video");
    job.arguments << QStringLiteral("-c:v") << QStringLiteral("libvpx-vp9")
                  << QStringLiteral("-pix_fmt")
                  << (plan.transparent ? QStringLiteral("yuva420p") : QStringLiteral("yuv420p"))
                  << QStringLiteral("-b:v") << QStringLiteral("0") << QStringLiteral("-crf")
                  << QStringLiteral("32") << QStringLiteral("-deadline") << QStringLiteral("good")
                  << QStringLiteral("-cpu-used") << QStringLiteral("4") << QStringLiteral("-row-mt")
                  << QStringLiteral("1") << QStringLiteral("-f") << QStringLiteral("webm");
    return job;
}

FfmpegJob apngJob(const ExportPlan &plan)
{
    FfmpegJob job;
    job.what = Export::tr("animated PNG");
    job.arguments << QStringLiteral("-c:v") << QStringLiteral("apng") << QStringLiteral("-pix_fmt")
                  << (plan.transparent ? QStringLiteral("rgba") : QStringLiteral("rgb24"))
                  << QStringLiteral("-plays")
                  << (plan.loop ? QStringLiteral("0") : QStringLiteral("1")) << QStringLiteral("-f")
                  << QStringLiteral("apng");
    return job;
}
} // namespace

QString holdTimestamps(const std::vector<int> &holds)
{
    QString expression = QStringLiteral("N");
    for (std::size_t i = 0; i + 1 < holds.size(); ++i) {
        if (holds[i] <= 1)
            continue;
        // Drawings after i start holds[i] - 1 ticks later. "\," keeps the comma inside the
        // filter graph.
        expression += QStringLiteral("+%1*gt(N\\,%2)").arg(holds[i] - 1).arg(i);
        if (expression.size() > kMaxExpression)
            return {};
    }
    return expression;
}

FfmpegJob ffmpegJob(ExportFormat format, const ExportPlan &plan, const QString &output,
                    const QString &palette, const QString &soundWav)
{
    FfmpegJob job;
    switch (format) {
    case ExportFormat::Gif:
        job = gifJob(plan, palette);
        break;
    case ExportFormat::Mp4:
        job = mp4Job();
        break;
    case ExportFormat::WebM:
        job = webmJob(plan);
        break;
    default:
        job = apngJob(plan);
        break;
    }
    if (!soundWav.isEmpty() && (format == ExportFormat::Mp4 || format == ExportFormat::WebM))
        job.arguments = inputArguments(plan) + soundInputArguments(soundWav) +
                        soundOutputArguments(format) + job.arguments;
    else
        job.arguments = inputArguments(plan) + job.arguments;
    if (!job.paletteArguments.isEmpty())
        job.paletteArguments = inputArguments(plan) + job.paletteArguments;
    job.arguments << QStringLiteral("-y") << output;
    return job;
}

} // namespace finbook::model
