// Every real drawing (through its silhouette) and every real shape (its contours as given) in
// shared/data gets a skeleton: valid, finite, bones inside the shape, within the vertex
// budget, and refinement at the slider maxima keeps those promises.
#include "skeleton_test_support.h"

#include <finbook/geometry/silhouette.h>
#include <finbook/geometry/skeleton/raw_skeleton.h>
#include <finbook/geometry/skeleton/skeleton.h>
#include <finbook/geometry/skeleton/skeleton_refine.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

QString dataDir()
{
    const QByteArray env = qgetenv("FINBOOK_DATA_DIR");
    return env.isEmpty() ? QStringLiteral(FINBOOK_DATA_DIR) : QString::fromLocal8Bit(env);
}

QStringList dataFiles(const QString &folder)
{
    const QDir dir(dataDir() + QLatin1Char('/') + folder);
    QStringList files;
    for (const QString &name : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        files << dir.filePath(name);
    return files;
}

QJsonObject readJson(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).object();
}

Region shapeOf(const QString &path)
{
    const QJsonObject json = readJson(path);
    if (json.contains(QStringLiteral("strokes"))) {
        std::vector<StrokeInput> strokes;
        for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray())
            strokes.push_back({toMatrix(stroke.toArray()), 3.0});
        const auto region = silhouette(strokes);
        return region ? *region : Region{};
    }
    const QJsonArray contours = json.value(QStringLiteral("contours")).toArray();
    Polygon polygon;
    for (qsizetype i = 0; i < contours.size(); ++i)
        (i == 0 ? polygon.outer : polygon.holes.emplace_back()) = toMatrix(contours[i].toArray());
    return {polygon};
}

// pieces: the outline the skeleton was built from (raw.contour), whose polygons the animator
// rig joins (the erosion can split a drawing where parts only touch).
void checkOn(const Skeleton &s, const Region &shape, const Region &pieces, const char *what)
{
    QVERIFY2(isValidSkeleton(s), what);
    QVERIFY2(s.jointCount() >= 1, what);
    // Bones that join separate pieces cross the gap between them: one per extra piece at most.
    int joining = 0;
    const double inside = bonesInsidePieces(s, shape, pieces, joining);
    QVERIFY2(joining <= std::max(0, int(pieces.size()) - 1), what);
    QVERIFY2(
        inside >= 0.99,
        qPrintable(
            QStringLiteral("%1: %2 of the bones inside").arg(QLatin1String(what)).arg(inside)));
}

} // namespace

class TestSkeletonRealData : public QObject {
    Q_OBJECT
private slots:
    void files_data();
    void files();
};

void TestSkeletonRealData::files_data()
{
    QTest::addColumn<QString>("path");
    const QStringList files =
        dataFiles(QStringLiteral("sketches")) + dataFiles(QStringLiteral("silhouettes"));
    if (files.isEmpty())
        QSKIP("shared/data is not available (set FINBOOK_DATA_DIR)");
    for (const QString &path : files)
        QTest::newRow(qPrintable(QFileInfo(path).baseName())) << path;
}

void TestSkeletonRealData::files()
{
    QFETCH(QString, path);
    const Region shape = shapeOf(path);
    QVERIFY(!shape.empty());
    const SkeletonOptions options;
    const auto raw = rawSkeleton(shape, options);
    QVERIFY2(raw.hasValue(), raw.hasValue() ? "" : raw.error().message.c_str());
    QVERIFY(!raw->degenerate);
    QVERIFY(raw->nodes.allFinite() && raw->radius.allFinite() && raw->clearance.allFinite());
    for (const Polygon &polygon : raw->contour)
        QVERIFY(regionVertexCount(Region{polygon}) <= options.maxVertices);
    QCOMPARE(raw->edges.rows(), raw->nodes.rows() - Eigen::Index(raw->contour.size()));

    const auto s = refineSkeleton(*raw);
    QVERIFY(s.hasValue());
    checkOn(*s, shape, raw->contour, "defaults");
    qInfo("%s: %ld outline vertices, %d joints, %d bones", qPrintable(QFileInfo(path).baseName()),
          raw->polygonVertices, s->jointCount(), boneCount(*s));

    // The slider maxima: fewer bones, still valid and inside.
    const RefineRanges ranges = refineRanges(*raw);
    QVERIFY(ranges.boneTolerance > 0 && ranges.mergeDistance > 0 && ranges.pruneLength > 0 &&
            ranges.collapseLength > 0);
    RefineOptions most;
    most.mergeDistance = ranges.mergeDistance;
    most.pruneLength = ranges.pruneLength;
    most.collapseLength = ranges.collapseLength;
    const auto simplest = refineSkeleton(*raw, most);

    QVERIFY(simplest.hasValue());
    checkOn(*simplest, shape, raw->contour, "slider maxima");
    QVERIFY(boneCount(*simplest) <= boneCount(*s));
    RefineOptions detailed;
    detailed.boneTolerance = 0.0;
    const auto finest = refineSkeleton(*raw, detailed);
    QVERIFY(finest.hasValue());
    checkOn(*finest, shape, raw->contour, "tolerance 0");
    QVERIFY(boneCount(*finest) >= boneCount(*s));
}

QTEST_APPLESS_MAIN(TestSkeletonRealData)
#include "tst_skeleton_real_data.moc"
