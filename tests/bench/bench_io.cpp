// finbook-bench io: save and open a large document (by default 500 frames × 10 objects ×
// 2,000 distinct points = 10M points) and report medians, file size and peak memory.
#include "bench.h"

#include <finbook/model/finbook_file.h>

#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>

namespace {
using namespace finbook::model;

struct IoOptions {
    int frames = 500;
    int objects = 10;
    int points = 2000; // per object
    int runs = 5;
};

bool parseOptions(const QStringList &args, IoOptions &o)
{
    for (int i = 0; i + 1 < args.size(); i += 2) {
        bool ok = false;
        const int value = args[i + 1].toInt(&ok);
        if (!ok || value < 1)
            return false;
        if (args[i] == QLatin1String("--frames"))
            o.frames = value;
        else if (args[i] == QLatin1String("--objects"))
            o.objects = value;
        else if (args[i] == QLatin1String("--points"))
            o.points = value;
        else if (args[i] == QLatin1String("--runs"))
            o.runs = value;
        else
            return false;
    }
    return args.size() % 2 == 0;
}

// Each object: a handful of strokes summing to `points`, every point distinct (nothing
// shared), pressure off the 1/65535 grid as a real pen gives it.
StrokeGroup makeObject(Document &doc, int frame, int object, int points)
{
    StrokeGroup g;
    g.id = doc.allocateId();
    g.name = QStringLiteral("object %1").arg(object + 1);
    constexpr int kStrokes = 4;
    for (int s = 0; s < kStrokes; ++s) {
        auto data = std::make_shared<StrokeData>();
        const int n = points / kStrokes + (s < points % kStrokes ? 1 : 0);
        data->points.reserve(std::size_t(n));
        for (int i = 0; i < n; ++i) {
            const float t = float(i) * 0.01f + float(frame) * 0.1f + float(object + s);
            data->points.push_back({640.0f + 300.0f * std::cos(t), 360.0f + 200.0f * std::sin(t),
                                    0.5f + 0.5f * std::sin(t * 7.0f)});
        }
        g.strokes.push_back({doc.allocateId(), std::move(data)});
    }
    return g;
}

void buildDocument(Document &doc, const IoOptions &o)
{
    std::vector<Frame> frames(std::size_t(o.frames));
    for (int f = 0; f < o.frames; ++f) {
        frames[std::size_t(f)].id = doc.allocateId();
        for (int g = 0; g < o.objects; ++g)
            frames[std::size_t(f)].groups.push_back(makeObject(doc, f, g, o.points));
    }
    const Id next = doc.nextId();
    doc.reset(std::move(frames), DocumentSettings{}, next);
}

int benchIo(const QStringList &args)
{
    IoOptions o;
    if (!parseOptions(args, o)) {
        std::fprintf(stderr, "usage: finbook-bench io [--frames 500] [--objects 10] "
                             "[--points 2000] [--runs 5]\n");
        return 2;
    }
    Document doc;
    buildDocument(doc, o);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("io.finbook"));
    std::vector<double> saveMs, openMs;
    for (int run = 0; run < o.runs; ++run) {
        QElapsedTimer timer;
        timer.start();
        if (const auto error = saveFinbook(doc, path)) {
            std::fprintf(stderr, "%s\n", qPrintable(error->message));
            return 1;
        }
        saveMs.push_back(double(timer.nsecsElapsed()) / 1e6);
        Document opened;
        timer.restart();
        if (const auto error = openFinbook(opened, path)) {
            std::fprintf(stderr, "%s\n", qPrintable(error->message));
            return 1;
        }
        openMs.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    const qint64 bytes = QFileInfo(path).size();
    const qint64 points = doc.pointCount();
    QJsonObject out;
    out[QStringLiteral("bench")] = QStringLiteral("io");
    out[QStringLiteral("points")] = points;
    out[QStringLiteral("save_ms_median")] = std::round(finbook::bench::median(saveMs) * 10) / 10;
    out[QStringLiteral("open_ms_median")] = std::round(finbook::bench::median(openMs) * 10) / 10;
    out[QStringLiteral("peak_rss_mb")] =
        std::round(double(finbook::bench::peakResidentBytes()) / (1 << 20) * 10) / 10;
    out[QStringLiteral("file_bytes")] = bytes;
    out[QStringLiteral("bytes_per_point")] =
        std::round(double(bytes) / double(std::max<qint64>(points, 1)) * 1000) / 1000;
    std::printf("%s\n", QJsonDocument(out).toJson(QJsonDocument::Compact).constData());
    return 0;
}
} // namespace

FINBOOK_BENCH("io", "[--frames 500] [--objects 10] [--points 2000] [--runs 5]", benchIo);
