// ARAP on real drawings: every Quick, Draw! sketch in ../shared/data/sketches is meshed by the
// geometry layer (buildObjectMesh, often several components) and deformed with random pins.
#include <finbook/deform/arap.h>
#include <finbook/geometry/object_mesh.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <random>

using namespace finbook::deform;

namespace {

QString dataDir()
{
    const QByteArray fromEnvironment = qgetenv("FINBOOK_DATA_DIR");
    return fromEnvironment.isEmpty() ? QStringLiteral(FINBOOK_DATA_DIR)
                                     : QString::fromLocal8Bit(fromEnvironment);
}

std::vector<finbook::geometry::StrokeInput> readStrokes(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QJsonArray strokes =
        QJsonDocument::fromJson(file.readAll()).object()["strokes"].toArray();
    std::vector<finbook::geometry::StrokeInput> out;
    for (const QJsonValue &stroke : strokes) {
        const QJsonArray points = stroke.toArray();
        finbook::geometry::StrokeInput input;
        input.points.resize(points.size(), 2);
        for (qsizetype k = 0; k < points.size(); ++k) {
            input.points(k, 0) = points[k].toArray()[0].toDouble();
            input.points(k, 1) = points[k].toArray()[1].toDouble();
        }
        input.width = 4.0;
        out.push_back(std::move(input));
    }
    return out;
}

// `count` pin entries on random vertices (repeats allowed, as a user may click twice).
Eigen::VectorXi randomPins(Eigen::Index vertices, int count, std::mt19937 &random)
{
    std::uniform_int_distribution<int> pick(0, int(vertices) - 1);
    Eigen::VectorXi b(count);
    for (int k = 0; k < count; ++k)
        b(k) = pick(random);
    return b;
}

double extent(const Eigen::MatrixX2d &V)
{
    return (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
}

} // namespace

class TestArapSketches : public QObject {
    Q_OBJECT

private slots:
    void randomPinsGiveFiniteResults_data();
    void randomPinsGiveFiniteResults();
};

void TestArapSketches::randomPinsGiveFiniteResults_data()
{
    QTest::addColumn<QString>("path");
    const QDir dir(dataDir() + QStringLiteral("/sketches"));
    // Without the data the test function skips its one empty row. A skip here, in the data
    // function of the only test, made under load LeakSanitizer report QtTest's watchdog thread
    // (152 bytes from QThread::QThread in QTest::qRun) in 8 of 60 runs; skipped in the test
    // function, in none of 60.
    if (!dir.exists())
        QTest::newRow("absent") << QString();
    for (const QFileInfo &info : dir.entryInfoList({QStringLiteral("*.json")}, QDir::Files))
        QTest::newRow(qPrintable(info.baseName())) << info.filePath();
}

void TestArapSketches::randomPinsGiveFiniteResults()
{
    QFETCH(QString, path);
    if (path.isEmpty())
        QSKIP("../shared/data/sketches is absent (see its README); nothing to test");
    const auto strokes = readStrokes(path);
    QVERIFY(!strokes.empty());
    auto mesh = finbook::geometry::buildObjectMesh(strokes);
    if (!mesh)
        QSKIP(qPrintable(QStringLiteral("the geometry layer could not mesh this sketch: ") +
                         QString::fromStdString(mesh.error().message)));
    const Eigen::MatrixX2d &V = mesh->V;
    const double size = extent(V);
    std::mt19937 random(qHash(path));
    std::uniform_real_distribution<double> shift(-0.3 * size, 0.3 * size);
    for (const int count : {0, 1, 2, 3, 5, 8, 20}) {
        const Eigen::VectorXi b = randomPins(V.rows(), count, random);
        auto data = arapPrecompute(V, mesh->F, b, ArapOptions{count % 2});
        QVERIFY2(data, data ? "" : data.error().message.c_str());
        Eigen::MatrixX2d bc(count, 2), U;
        for (int k = 0; k < count; ++k)
            bc.row(k) = V.row(b(k)) + Eigen::RowVector2d(shift(random), shift(random));
        auto solved = arapSolve(**data, bc, U);
        QVERIFY2(solved, solved ? "" : solved.error().message.c_str());
        QVERIFY(U.allFinite());
        // Every pin reaches its target (the last entry wins for a repeated vertex).
        for (int k = 0; k < count; ++k) {
            if ((b.tail(count - k - 1).array() != b(k)).all())
                QVERIFY((U.row(b(k)) - bc.row(k)).norm() <= 1e-9 * size);
        }
        // All pins on one spot: step 1 collapses each solved component, step 2 stays finite.
        bc.rowwise() = V.row(0);
        QVERIFY(arapSolve(**data, bc, U));
        QVERIFY(U.allFinite());
    }
}

QTEST_APPLESS_MAIN(TestArapSketches)
#include "tst_arap_sketches.moc"
