// `finbook-bench import FILE OUT.finbook`: a Quick, Draw! sketch or a silhouette file (the two
// formats of ../shared/data/README.md) as a one-object Finbook document, for looking at real
// drawings in the editor (meshes, pins) and for ad-hoc measurements.
#include "bench.h"

#include <finbook/model/finbook_file.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <cstdio>

using namespace finbook::model;

namespace {

std::vector<StrokeDataPtr> strokesOf(const QJsonObject &root)
{
    // Sketches are open strokes; silhouettes are closed contours, drawn as closed strokes.
    const bool sketch = root.contains(QStringLiteral("strokes"));
    const QJsonArray lists =
        root.value(sketch ? QStringLiteral("strokes") : QStringLiteral("contours")).toArray();
    std::vector<StrokeDataPtr> strokes;
    for (const QJsonValue &list : lists) {
        auto data = std::make_shared<StrokeData>();
        data->width = 3.0f;
        for (const QJsonValue &pt : list.toArray()) {
            const QJsonArray xy = pt.toArray();
            data->points.push_back({float(xy.at(0).toDouble()), float(xy.at(1).toDouble()), 1.0f});
        }
        if (!sketch && !data->points.empty())
            data->points.push_back(data->points.front());
        if (!data->points.empty())
            strokes.push_back(std::move(data));
    }
    return strokes;
}

int benchImport(const QStringList &args)
{
    if (args.size() != 2) {
        std::fprintf(stderr, "usage: finbook-bench import FILE OUT.finbook\n");
        return 2;
    }
    QFile in(args[0]);
    if (!in.open(QIODevice::ReadOnly)) {
        std::fprintf(stderr, "cannot read %s\n", qPrintable(args[0]));
        return 2;
    }
    const QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
    std::vector<StrokeDataPtr> strokes = strokesOf(root);
    if (strokes.empty()) {
        std::fprintf(stderr, "%s has no strokes or contours\n", qPrintable(args[0]));
        return 2;
    }
    // Fit the drawing into a 1280×720 canvas with a margin, keeping its proportions.
    float minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    for (const auto &s : strokes)
        for (const StrokePoint &p : s->points) {
            minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
            minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
        }
    const float scale =
        std::min(1100.0f / std::max(1.0f, maxX - minX), 600.0f / std::max(1.0f, maxY - minY));
    Document doc;
    Frame frame;
    frame.id = doc.allocateId();
    StrokeGroup group;
    group.id = doc.allocateId();
    group.name = root.value(QStringLiteral("category")).toString(QStringLiteral("drawing"));
    for (const auto &s : strokes) {
        auto placed = std::make_shared<StrokeData>(*s);
        for (StrokePoint &p : placed->points) {
            p.x = 640.0f + (p.x - (minX + maxX) / 2) * scale;
            p.y = 360.0f + (p.y - (minY + maxY) / 2) * scale;
        }
        group.strokes.push_back({doc.allocateId(), std::move(placed)});
    }
    frame.groups.push_back(std::move(group));
    doc.reset({std::move(frame)}, DocumentSettings{}, doc.nextId());
    if (const auto error = saveFinbook(doc, args[1])) {
        std::fprintf(stderr, "%s\n", qPrintable(error->message));
        return 1;
    }
    std::printf("{\"bench\":\"import\",\"file\":\"%s\",\"strokes\":%zu,\"scale\":%.3f}\n",
                qPrintable(args[0]), strokes.size(), double(scale));
    return 0;
}

} // namespace

FINBOOK_BENCH("import", "FILE OUT.finbook", benchImport);
