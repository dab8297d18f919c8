#include "ffmpeg_arguments.h"

#include "export_sound.h"
#include "export_text.h"

#include <algorithm>
#include <cmath>

namespace finbook::model {

namespace {
QStringList inputArguments(const ExportPlan &plan, const QString &concat)
{
    // -xerror: without it ffmpeg 5.1 reports a failed write (a full disk) and still exits
    // with 0, leaving a truncated file.
    QStringList arguments{QStringLiteral("-hide_banner"), QStringLiteral("-nostats"),
                          QStringLiteral("-loglevel"), QStringLiteral("error"),
                          QStringLiteral("-xerror")};
    if (!concat.isEmpty()) // drawings as files, each with its duration
        return arguments << QStringLiteral("-f") << QStringLiteral("concat")
                         << QStringLiteral("-safe") << QStringLiteral("0") << QStringLiteral("-i")
                         << QStringLiteral("file:") + concat;
    return arguments << QStringLiteral("-f") << QStringLiteral("rawvideo")
                     << QStringLiteral("-pix_fmt")
                     << QStringLiteral("bgra") // QImage::Format_ARGB32 in little-endian memory
                     << QStringLiteral("-video_size")
                     << QStringLiteral("%1x%2").arg(plan.size.width()).arg(plan.size.height())
                     << QStringLiteral("-framerate") << QString::number(plan.fps)
                     << QStringLiteral("-i") << QStringLiteral("pipe:0");
}

// Two runs over the same frames, so that memory does not grow with their number: one
// filter graph splitting the stream into palettegen and paletteuse would hold every frame
// until palettegen has seen the last one (2.4 GB for 2,000 frames at 640×480). The first run
// only counts colours into the palette (a PNG); the second maps each frame to it as it comes.
// Drawings held for different times come from `drawings`, a concat list (concatList) whose
// durations give each its hold; drawings all held one tick are piped, one per tick.
FfmpegJob gifJob(const ExportPlan &plan, const QString &palette, const QString &drawings)
{
    FfmpegJob job;
    job.what = Export::tr("GIF");
    job.perTick = drawings.isEmpty();
    job.concatList = drawings;
    job.paletteArguments << QStringLiteral("-vf")
                         << QStringLiteral("palettegen=stats_mode=full:reserve_transparent=%1")
                                .arg(plan.transparent ? 1 : 0)
                         << QStringLiteral("-update") << QStringLiteral("1")
                         << QStringLiteral("-c:v") << QStringLiteral("png") << QStringLiteral("-f")
                         << QStringLiteral("image2") << QStringLiteral("-y")
                         << QStringLiteral("file:") + palette;
    // The frames are input 0, the palette input 1.
    const QString graph = QStringLiteral(
        "[0:v][1:v]paletteuse=dither=sierra2_4a:diff_mode=rectangle:alpha_threshold=128");
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

bool holdsVary(const std::vector<int> &holds)
{
    return std::any_of(holds.begin(), holds.end(), [](int hold) { return hold > 1; });
}

QByteArray concatList(const std::vector<int> &holds, int fps,
                      const std::function<QString(std::size_t)> &file)
{
    QByteArray list = "ffconcat version 1.0\n";
    for (std::size_t i = 0; i < holds.size(); ++i) {
        // Quoted as the concat demuxer reads it: ' closes, so each one inside is '\''.
        QString name = file(i);
        name.replace(QLatin1Char('\''), QStringLiteral("'\\''"));
        list += "file '" + name.toUtf8() + "'\n";
        // Read at 1,000 frames per second, so its time base is a millisecond: at the image
        // reader's default (25) every start was rounded to 40 ms.
        list += "option framerate 1000\n";
        list += "duration " + QByteArray::number(double(holds[i]) / fps, 'f', 9) + '\n';
    }
    return list;
}

FfmpegJob ffmpegJob(ExportFormat format, const ExportPlan &plan, const QString &output,
                    const QString &palette, const QString &soundWav, const QString &drawings)
{
    FfmpegJob job;
    switch (format) {
    case ExportFormat::Gif:
        job = gifJob(plan, palette, drawings);
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
        job.arguments = inputArguments(plan, job.concatList) + soundInputArguments(soundWav) +
                        soundOutputArguments(format) + job.arguments;
    else
        job.arguments = inputArguments(plan, job.concatList) + job.arguments;
    if (!job.paletteArguments.isEmpty())
        job.paletteArguments = inputArguments(plan, job.concatList) + job.paletteArguments;
    job.arguments << QStringLiteral("-y") << output;
    return job;
}

} // namespace finbook::model
