// Shared by the export tests: the example with holds, ffprobe, and image comparison.
#pragma once

#include <finbook/model/export/exporter.h>
#include <finbook/model/finbook_file.h>

#include <QDir>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>

#include <cmath>

namespace finbook::test {

inline QString examplePath()
{
    return QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook");
}

// The example's walk cycle: the layer with the most drawings (12), without the scene's other
// layers and its camera.
inline model::ExportSource loadExample()
{
    auto loaded = model::loadFinbook(examplePath());
    if (!loaded)
        return {};
    std::vector<model::Layer> layers = model::takeLoadedLayers(*loaded);
    auto walk = layers.begin();
    for (auto l = layers.begin(); l != layers.end(); ++l)
        if (l->cels.size() > walk->cels.size())
            walk = l;
    return model::ExportSource{std::move(walk->cels), loaded->settings, {}};
}

// The example with some drawings held: frame 3 for 3 ticks, frame 8 for 2, the last for 4.
// 12 drawings, 12 + 2 + 1 + 3 = 18 ticks.
inline model::ExportSource exampleWithHolds()
{
    model::ExportSource source = loadExample();
    if (source.frames.size() >= 12) {
        source.frames[2].hold = 3;
        source.frames[7].hold = 2;
        source.frames[11].hold = 4;
    }
    return source;
}

inline qint64 ticksOf(const model::ExportSource &source, int first, int last)
{
    qint64 ticks = 0;
    for (int i = first; i <= last; ++i)
        ticks += source.frames[std::size_t(i)].hold;
    return ticks;
}

// Files (hidden ones included) directly inside `folder`.
inline QStringList filesIn(const QString &folder)
{
    return QDir(folder).entryList(QDir::Files | QDir::Dirs | QDir::Hidden | QDir::NoDotAndDotDot,
                                  QDir::Name);
}

inline QString program(const char *name)
{
    return QStandardPaths::findExecutable(QString::fromLatin1(name));
}

// The headless browser the HTML flipbook tests open pages in; empty when none is installed.
inline QString chromium()
{
    for (const char *name : {"chromium", "chromium-browser", "google-chrome"})
        if (const QString path = program(name); !path.isEmpty())
            return path;
    return {};
}

// ffprobe's JSON for the first video stream and the container, frames counted by decoding.
inline QJsonObject probe(const QString &path, QString *error = nullptr)
{
    QProcess p;
    p.start(program("ffprobe"),
            {QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-count_frames"),
             QStringLiteral("-select_streams"), QStringLiteral("v:0"),
             QStringLiteral("-show_streams"), QStringLiteral("-show_format"), QStringLiteral("-of"),
             QStringLiteral("json"), path});
    if (!p.waitForFinished(120000) || p.exitCode() != 0) {
        if (error)
            *error = QString::fromLocal8Bit(p.readAllStandardError());
        return {};
    }
    const QJsonObject all = QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    QJsonObject stream = all[QStringLiteral("streams")].toArray().at(0).toObject();
    stream[QStringLiteral("format")] = all[QStringLiteral("format")];
    return stream;
}

// Each decoded frame's duration in seconds, in order (ffprobe -show_frames).
inline std::vector<double> frameDurations(const QString &path)
{
    QProcess p;
    p.start(program("ffprobe"),
            {QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-select_streams"),
             QStringLiteral("v:0"), QStringLiteral("-show_entries"),
             QStringLiteral("frame=pkt_duration_time"), QStringLiteral("-of"),
             QStringLiteral("json"), path});
    std::vector<double> durations;
    if (!p.waitForFinished(120000) || p.exitCode() != 0)
        return durations;
    const QJsonArray frames = QJsonDocument::fromJson(p.readAllStandardOutput())
                                  .object()[QStringLiteral("frames")]
                                  .toArray();
    for (const QJsonValue &f : frames)
        durations.push_back(
            f.toObject()[QStringLiteral("pkt_duration_time")].toString().toDouble());
    return durations;
}

// Frame `index` of a video or animation decoded by ffmpeg as an RGBA image (timestamps kept,
// so frame n is the n-th stored frame).
inline QImage decodeFrame(const QString &path, int index, const QStringList &decoder = {})
{
    QProcess p;
    p.start(program("ffmpeg"),
            decoder + QStringList{
                          QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-i"), path,
                          QStringLiteral("-vf"), QStringLiteral("select=eq(n\\,%1)").arg(index),
                          QStringLiteral("-fps_mode"), QStringLiteral("passthrough"),
                          QStringLiteral("-frames:v"), QStringLiteral("1"), QStringLiteral("-f"),
                          QStringLiteral("image2pipe"), QStringLiteral("-c:v"),
                          QStringLiteral("png"), QStringLiteral("-pix_fmt"), QStringLiteral("rgba"),
                          QStringLiteral("pipe:1")});
    if (!p.waitForFinished(120000) || p.exitCode() != 0)
        return {};
    return QImage::fromData(p.readAllStandardOutput(), "PNG");
}

struct ImageDifference {
    double meanAbs = 255;   // mean absolute difference per channel, 0..255
    double farFraction = 1; // share of pixels where some channel differs by more than 64
};

// Compares two images of the same size (premultiplied-independent: both as ARGB32).
inline ImageDifference difference(const QImage &a, const QImage &b)
{
    ImageDifference d;
    if (a.size() != b.size() || a.isNull())
        return d;
    const QImage x = a.convertToFormat(QImage::Format_ARGB32);
    const QImage y = b.convertToFormat(QImage::Format_ARGB32);
    double sum = 0;
    qint64 far = 0;
    for (int row = 0; row < x.height(); ++row) {
        const auto *p = reinterpret_cast<const QRgb *>(x.constScanLine(row));
        const auto *q = reinterpret_cast<const QRgb *>(y.constScanLine(row));
        for (int col = 0; col < x.width(); ++col) {
            const int dr = std::abs(qRed(p[col]) - qRed(q[col]));
            const int dg = std::abs(qGreen(p[col]) - qGreen(q[col]));
            const int db = std::abs(qBlue(p[col]) - qBlue(q[col]));
            const int da = std::abs(qAlpha(p[col]) - qAlpha(q[col]));
            sum += dr + dg + db + da;
            far += std::max({dr, dg, db, da}) > 64;
        }
    }
    const double pixels = double(x.width()) * x.height();
    d.meanAbs = sum / (4 * pixels);
    d.farFraction = double(far) / pixels;
    return d;
}

} // namespace finbook::test
