#include "ffmpeg_arguments.h"

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

FfmpegJob gifJob(const ExportPlan &plan)
{
    FfmpegJob job;
    job.what = Export::tr("GIF");
    const QString timestamps = holdTimestamps(plan.holds);
    job.perTick = timestamps.isEmpty();
    const QString setpts =
        job.perTick ? QString() : QStringLiteral("setpts=(%1)/(FR*TB),").arg(timestamps);
    // One pass: split keeps the frames while palettegen sees them all, then paletteuse maps
    // each to the shared 256 (255 + transparent) colours.
    const QString graph =
        QStringLiteral("[0:v]%1split[a][b];[a]palettegen=stats_mode=full:reserve_transparent=%2[p];"
                       "[b][p]paletteuse=dither=sierra2_4a:diff_mode=rectangle:alpha_threshold=128")
            .arg(setpts)
            .arg(plan.transparent ? 1 : 0);
    // GIF delays are centiseconds; the last drawing's hold is not known to ffmpeg otherwise.
    const int lastTicks = job.perTick ? 1 : plan.holds.back();
    const int finalDelay = int(std::lround(lastTicks * 100.0 / plan.fps));
    job.arguments << QStringLiteral("-filter_complex") << graph << QStringLiteral("-fps_mode")
                  << QStringLiteral("passthrough") << QStringLiteral("-loop")
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

FfmpegJob ffmpegJob(ExportFormat format, const ExportPlan &plan, const QString &output)
{
    FfmpegJob job;
    switch (format) {
    case ExportFormat::Gif:
        job = gifJob(plan);
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
    job.arguments = inputArguments(plan) + job.arguments;
    job.arguments << QStringLiteral("-y") << output;
    return job;
}

} // namespace finbook::model
