// Every real drawing and shape in shared/data must mesh: no crash, no NaN, the mesh promises
// hold and every stroke point is embedded inside.
#include "geometry_test_support.h"

#include <finbook/geometry/embedding.h>
#include <finbook/geometry/mesh_quality.h>
#include <finbook/geometry/object_mesh.h>
#include <finbook/geometry/polyline.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace finbook::geometry;

namespace {

using namespace finbook::test;

QString dataDir()
{
    const QByteArray env = qgetenv("FINBOOK_DATA_DIR");
    return env.isEmpty() ? QStringLiteral(FINBOOK_DATA_DIR) : QString::fromLocal8Bit(env);
}

QJsonObject readJson(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).object();
}

QStringList dataFiles(const QString &folder)
{
    const QDir dir(dataDir() + QLatin1Char('/') + folder);
    QStringList files;
    for (const QString &name : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        files << dir.filePath(name);
    return files;
}

// The ObjectMesh promises, checked on any mesh.
void checkMesh(const ObjectMesh &m, double minAngle)
{
    QVERIFY(m.V.rows() > 0 && m.F.rows() > 0);
    QVERIFY(m.V.allFinite());
    QVERIFY(triangleSignedAreas(m.V, m.F).minCoeff() > 0.0);
    QVERIFY(m.F.minCoeff() >= 0 && m.F.maxCoeff() < m.V.rows());
    std::vector<bool> used(std::size_t(m.V.rows()), false);
    for (Eigen::Index i = 0; i < m.F.size(); ++i)
        used[std::size_t(m.F.data()[i])] = true;
    QVERIFY(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
    QCOMPARE(qsizetype(m.mesh.n_vertices()), qsizetype(m.V.rows()));
    QCOMPARE(qsizetype(m.mesh.n_faces()), qsizetype(m.F.rows()));
    QVERIFY2(minAngleDegrees(m.V, m.F) >= minAngle,
             qPrintable(QString::number(minAngleDegrees(m.V, m.F))));
    const double meshArea = triangleSignedAreas(m.V, m.F).sum();
    const double outlineArea = regionArea(m.region);
    QVERIFY(std::abs(meshArea - outlineArea) <= 1e-6 * outlineArea);
}

} // namespace

class TestRealData : public QObject {
    Q_OBJECT
private slots:
    void sketches_data();
    void sketches();
    void silhouettes_data();
    void silhouettes();
    void silhouettesAsStrokes_data() { silhouettes_data(); }
    void silhouettesAsStrokes();
};

void TestRealData::sketches_data()
{
    QTest::addColumn<QString>("path");
    const QStringList files = dataFiles(QStringLiteral("sketches"));
    if (files.isEmpty())
        QSKIP("shared/data/sketches is not available (set FINBOOK_DATA_DIR)");
    for (const QString &path : files)
        QTest::newRow(qPrintable(QFileInfo(path).baseName())) << path;
}

void TestRealData::sketches()
{
    QFETCH(QString, path);
    const QJsonObject json = readJson(path);
    std::vector<StrokeInput> strokes;
    long pointCount = 0;
    for (const QJsonValue &stroke : json.value(QStringLiteral("strokes")).toArray()) {
        strokes.push_back({toMatrix(stroke.toArray()), 3.0});
        pointCount += strokes.back().points.rows();
    }
    QVERIFY(!strokes.empty());
    const auto mesh = buildObjectMesh(strokes);
    QVERIFY2(mesh.hasValue(), mesh.hasValue() ? "" : mesh.error().message.c_str());
    checkMesh(*mesh, 20.0);
    qInfo("%s: %ld vertices, %ld triangles, min angle %.1f", qPrintable(QFileInfo(path).baseName()),
          long(mesh->V.rows()), long(mesh->F.rows()), minAngleDegrees(mesh->V, mesh->F));

    // Every stroke point lies inside the mesh and comes back exactly from its embedding.
    Eigen::MatrixX2d points(pointCount, 2);
    Eigen::Index row = 0;
    for (const StrokeInput &s : strokes) {
        points.middleRows(row, s.points.rows()) = s.points;
        row += s.points.rows();
    }
    const Embedding e = embed(*mesh, points);
    QCOMPARE(e.snapped, 0);
    const double size = (points.colwise().maxCoeff() - points.colwise().minCoeff()).maxCoeff();
    const Eigen::MatrixX2d back = applyEmbedding(e, mesh->V, mesh->F);
    QVERIFY((back - points).cwiseAbs().maxCoeff() <= 1e-9 * size);
}

void TestRealData::silhouettes_data()
{
    QTest::addColumn<QString>("path");
    const QStringList files = dataFiles(QStringLiteral("silhouettes"));
    if (files.isEmpty())
        QSKIP("shared/data/silhouettes is not available (set FINBOOK_DATA_DIR)");
    for (const QString &path : files)
        QTest::newRow(qPrintable(QFileInfo(path).baseName())) << path;
}

void TestRealData::silhouettes()
{
    QFETCH(QString, path);
    const QJsonArray contours = readJson(path).value(QStringLiteral("contours")).toArray();
    QVERIFY(!contours.isEmpty());
    Polygon polygon;
    polygon.outer = toMatrix(contours[0].toArray());
    for (qsizetype i = 1; i < contours.size(); ++i)
        polygon.holes.push_back(toMatrix(contours[i].toArray()));
    const auto mesh = buildObjectMesh(Region{polygon});
    QVERIFY2(mesh.hasValue(), mesh.hasValue() ? "" : mesh.error().message.c_str());
    checkMesh(*mesh, 20.0);
    qInfo("%s: %ld vertices, %ld triangles, min angle %.1f, %zu polygons, %zu holes",
          qPrintable(QFileInfo(path).baseName()), long(mesh->V.rows()), long(mesh->F.rows()),
          minAngleDegrees(mesh->V, mesh->F), mesh->region.size(),
          mesh->region.empty() ? size_t(0) : mesh->region[0].holes.size());
    // The mesh covers the shape: area within 3% (corner rounding trims spikes and pixel steps).
    double inputArea = std::abs(signedArea(polygon.outer));
    for (const Eigen::MatrixX2d &hole : polygon.holes)
        inputArea -= std::abs(signedArea(hole));
    const double meshArea = triangleSignedAreas(mesh->V, mesh->F).sum();
    QVERIFY2(std::abs(meshArea - inputArea) <= 0.03 * inputArea,
             qPrintable(QStringLiteral("%1 vs %2").arg(meshArea).arg(inputArea)));
}

void TestRealData::silhouettesAsStrokes()
{
    // The same outlines traced as closed pen strokes: the silhouette fills them, so the mesh
    // covers the shape (holes included) and every traced point is embedded without snapping.
    QFETCH(QString, path);
    const QJsonArray contours = readJson(path).value(QStringLiteral("contours")).toArray();
    std::vector<StrokeInput> strokes;
    for (const QJsonValue &contour : contours) {
        Eigen::MatrixX2d ring = toMatrix(contour.toArray());
        ring.conservativeResize(ring.rows() + 1, 2);
        ring.row(ring.rows() - 1) = ring.row(0);
        strokes.push_back({ring, 3.0});
    }
    const auto mesh = buildObjectMesh(strokes);
    QVERIFY2(mesh.hasValue(), mesh.hasValue() ? "" : mesh.error().message.c_str());
    checkMesh(*mesh, 20.0);
    const double meshArea = triangleSignedAreas(mesh->V, mesh->F).sum();
    QVERIFY(meshArea >= std::abs(signedArea(strokes[0].points)));
    const Embedding e = embed(*mesh, strokes[0].points);
    QCOMPARE(e.snapped, 0);
}

QTEST_APPLESS_MAIN(TestRealData)
#include "tst_real_data.moc"
