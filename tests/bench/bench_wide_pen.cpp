// finbook-bench wide-pen: one frame of a wide pen scribbling over the canvas (issue 25, item 6),
// rendered as `finbook export` renders it; time and peak memory per case. Peak memory only
// grows within a process, so run one case per process (--case NAME) for a per-case figure.
// With --write FOLDER every case's file is left there (--case none: only written), to time the real
// `finbook export` on them.
#include "../model/file_builder.h"
#include "bench.h"

#include <finbook/model/finbook_file.h>
#include <finbook/model/render.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>

namespace {
namespace fb = file_build;

struct Case {
    const char *name;
    float width;
    int points;
    int canvasWidth, canvasHeight;
    double scale; // rendered at canvas × scale, as `export --scale`
};

// Random points spread over the canvas: a long, self-crossing stroke.
QByteArray scribbleFile(const Case &c)
{
    std::vector<fb::Point> scribble;
    quint32 seed = 12345;
    const auto next = [&seed](int range) {
        seed = seed * 1664525u + 1013904223u;
        return float((seed >> 8) % quint32(range));
    };
    for (int i = 0; i < c.points; ++i) {
        const float x = next(c.canvasWidth);
        scribble.push_back({x, next(c.canvasHeight)});
    }
    return fb::fileV1(fb::document(quint32(c.canvasWidth), quint32(c.canvasHeight)),
                      fb::strokeTable({{c.width, scribble}}), fb::emptyTable(),
                      fb::frameList({fb::frame(1, {fb::object(2, {{3, 0}})})}));
}

int widePen(const QStringList &args)
{
    QString folder, only;
    for (qsizetype i = 0; i + 1 < args.size(); i += 2) {
        if (args[i] == QLatin1String("--write"))
            folder = args[i + 1];
        else if (args[i] == QLatin1String("--case"))
            only = args[i + 1];
        else
            return 2;
    }
    if (args.size() % 2)
        return 2;
    const std::vector<Case> cases{
        {"pen200_points20000_1920x1080", 200, 20000, 1920, 1080, 1.0},
        {"pen200_points2000_640x360", 200, 2000, 640, 360, 1.0},
        {"pen2000_points2000_640x360", 2000, 2000, 640, 360, 1.0},
        {"pen16384_points2000_640x360", finbook::model::kMaxStrokeWidth, 2000, 640, 360, 1.0},
        {"pen2000_points400_640x360_scale4", 2000, 400, 640, 360, 4.0},
        {"pen2000_points20000_1920x1080", 2000, 20000, 1920, 1080, 1.0},
        {"pen200_points200000_1920x1080", 200, 200000, 1920, 1080, 1.0},
        {"pen40_points20000_1920x1080", 40, 20000, 1920, 1080, 1.0},
        {"pen10_points20000_1920x1080", 10, 20000, 1920, 1080, 1.0},
        {"pen60_points20000_1920x1080", 60, 20000, 1920, 1080, 1.0},
    };
    for (const Case &c : cases) {
        const QByteArray bytes = scribbleFile(c);
        if (!folder.isEmpty()) {
            QFile out(
                QDir(folder).filePath(QString::fromLatin1(c.name) + QStringLiteral(".finbook")));
            if (!out.open(QIODevice::WriteOnly) || out.write(bytes) != bytes.size())
                return 1;
        }
        if (!only.isEmpty() && only != QLatin1String(c.name))
            continue;
        const auto loaded = finbook::model::readFinbook(bytes);
        if (!loaded)
            return 1;
        const QSize size(int(c.canvasWidth * c.scale), int(c.canvasHeight * c.scale));
        QElapsedTimer clock;
        clock.start();
        const QImage image =
            finbook::model::renderFrame(loaded->frames.front(), loaded->settings, size);
        const double seconds = double(clock.nsecsElapsed()) / 1e9;
        const QJsonObject line{
            {QStringLiteral("bench"), QStringLiteral("wide-pen")},
            {QStringLiteral("case"), QString::fromLatin1(c.name)},
            {QStringLiteral("bytes"), double(bytes.size())},
            {QStringLiteral("pixels"), double(size.width()) * size.height()},
            {QStringLiteral("seconds"), seconds},
            {QStringLiteral("centre_grey"), qGray(image.pixel(image.rect().center()))},
            {QStringLiteral("peak_rss_mib"), double(finbook::bench::peakResidentBytes() >> 20)}};
        std::printf("%s\n", QJsonDocument(line).toJson(QJsonDocument::Compact).constData());
        std::fflush(stdout);
    }
    return 0;
}
} // namespace

FINBOOK_BENCH("wide-pen", "[--case NAME] [--write FOLDER]: one frame of a wide pen scribbling",
              widePen);
