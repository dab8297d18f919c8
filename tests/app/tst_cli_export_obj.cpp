// `finbook export FILE OUT.obj` as a user runs it: the 3D model of one frame (the .obj and its
// .mtl, or one .glb), chosen by the suffix or --format obj, --frame N, a target in the way without
// --overwrite, and a frame with nothing that can be made 3D; each refusal one line on stderr,
// the README's exit code and nothing at the target.
#include "../model/export_support.h"
#include "cli_run.h"

#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;
using namespace cli_run;

namespace {

const QString kFinbook = QStringLiteral(FINBOOK_BINARY_DIR "/bin/finbook");

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The OBJ's object names ("o" lines).
QStringList objects(const QString &path)
{
    QStringList names;
    for (const QByteArray &line : readAll(path).split('\n'))
        if (line.startsWith("o "))
            names << QString::fromUtf8(line.mid(2));
    return names;
}

model::StrokeDataPtr stroke(std::vector<model::StrokePoint> points)
{
    auto data = std::make_shared<model::StrokeData>();
    data->points = std::move(points);
    return data;
}

// The example's first two drawings, then a drawing of a single dot and a straight line (frame
// 3), then a closed triangle "Ring" beside a line "Lone" (frame 4).
QString saveDocument(const QString &path)
{
    model::ExportSource source = loadExample();
    if (source.frames.size() < 2)
        return {};
    source.frames.resize(2);
    model::Id id = 900000;
    const auto object = [&id](const QString &name, std::vector<model::StrokePoint> points) {
        model::StrokeGroup group;
        group.id = ++id;
        group.name = name;
        group.strokes.push_back({++id, stroke(std::move(points))});
        return group;
    };
    const std::vector<model::StrokePoint> line{{100, 100, 1}, {250, 100, 1}, {400, 100, 1}};
    model::Frame dots;
    dots.id = ++id;
    dots.groups.push_back(object(QStringLiteral("Dot"), {{300, 300, 1}}));
    dots.groups.push_back(object(QStringLiteral("Lone"), line));
    source.frames.push_back(dots);
    model::Frame ring;
    ring.id = ++id;
    std::vector<model::StrokePoint> triangle;
    const QPointF corners[] = {{300, 200}, {500, 400}, {100, 400}, {300, 200}};
    for (int side = 0; side < 3; ++side) // 20 px steps, closed
        for (int k = 0; k < 20; ++k) {
            const QPointF p = corners[side] + (corners[side + 1] - corners[side]) * (k / 20.0);
            triangle.push_back({float(p.x()), float(p.y()), 1});
        }
    triangle.push_back(triangle.front());
    ring.groups.push_back(object(QStringLiteral("Ring"), triangle));
    ring.groups.push_back(object(QStringLiteral("Lone"), line));
    source.frames.push_back(ring);
    source.settings.playStart = 0;
    source.settings.playEnd = -1;
    model::Document doc;
    doc.reset(source.frames, source.settings, 1000000);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(model::serializeFinbook(doc));
    return path;
}

} // namespace

class TestCliExportObj : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void suffixChoosesObj();
    void formatOptionChoosesObj();
    void glbIsOneFile();
    void frameOptionPicksTheDrawing();
    void existingTargetNeedsOverwrite();
    void nothingMeshableExitsTwo_data();
    void nothingMeshableExitsTwo();
    void badFrameArguments_data();
    void badFrameArguments();

private:
    QTemporaryDir m_dir;
    QString m_file;
};

void TestCliExportObj::initTestCase()
{
    QVERIFY(QFile::exists(kFinbook));
    QVERIFY(m_dir.isValid());
    m_file = saveDocument(m_dir.filePath(QStringLiteral("doc.finbook")));
    QVERIFY(!m_file.isEmpty());
}

void TestCliExportObj::suffixChoosesObj()
{
    const QString out = m_dir.filePath(QStringLiteral("suffix/walk.obj"));
    const QString mtl = m_dir.filePath(QStringLiteral("suffix/walk.mtl"));
    const Run run = runFinbook({QStringLiteral("export"), m_file, out});
    QCOMPARE(run.code, 0);
    QCOMPARE(run.out, (out + QLatin1Char('\n') + mtl + QLatin1Char('\n')).toLocal8Bit());
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    QVERIFY(readAll(out).contains("mtllib walk.mtl\n"));
    QVERIFY(readAll(mtl).contains("newmtl "));
    QVERIFY(!objects(out).isEmpty());
    QCOMPARE(filesIn(QFileInfo(out).path()), QStringList({"walk.mtl", "walk.obj"}));
}

void TestCliExportObj::formatOptionChoosesObj()
{
    const QString out = m_dir.filePath(QStringLiteral("format/model"));
    const Run run = runFinbook(
        {QStringLiteral("export"), m_file, out, QStringLiteral("--format"), QStringLiteral("obj")});
    QCOMPARE(run.code, 0);
    QVERIFY(!objects(out).isEmpty());
    QVERIFY(QFileInfo::exists(out + QStringLiteral(".mtl")));
    // A suffix naming another format is a contradiction.
    const Run clash = runFinbook({QStringLiteral("export"), m_file,
                                  m_dir.filePath(QStringLiteral("format/x.gif")),
                                  QStringLiteral("--format=obj")});
    QCOMPARE(clash.code, 2);
    QVERIFY2(isOneLine(clash.err), clash.err.constData());
}

void TestCliExportObj::glbIsOneFile()
{
    // By suffix, frame 4: one file, the closed triangle "Ring" only (the line is left out).
    const QString out = m_dir.filePath(QStringLiteral("glb/ring.glb"));
    const Run run =
        runFinbook({QStringLiteral("export"), m_file, out, QStringLiteral("--frame=4")});
    QCOMPARE(run.code, 0);
    QCOMPARE(run.out, (out + QLatin1Char('\n')).toLocal8Bit());
    QCOMPARE(filesIn(QFileInfo(out).path()), QStringList({"ring.glb"}));
    const QByteArray bytes = readAll(out);
    QVERIFY(bytes.startsWith("glTF"));
    QVERIFY(bytes.contains(R"("nodes":[{"name":"Ring","mesh":0}])"));
    // By --format, on a name without a suffix.
    const QString plain = m_dir.filePath(QStringLiteral("glb/model"));
    QCOMPARE(runFinbook({QStringLiteral("export"), m_file, plain, QStringLiteral("--format"),
                         QStringLiteral("glb")})
                 .code,
             0);
    QVERIFY(readAll(plain).startsWith("glTF"));
}

void TestCliExportObj::frameOptionPicksTheDrawing()
{
    const QString first = m_dir.filePath(QStringLiteral("frames/first.obj"));
    const QString second = m_dir.filePath(QStringLiteral("frames/second.obj"));
    QCOMPARE(
        runFinbook({QStringLiteral("export"), m_file, first, QStringLiteral("--frame=1")}).code, 0);
    QCOMPARE(runFinbook({QStringLiteral("export"), m_file, second, QStringLiteral("--frame"),
                         QStringLiteral("2")})
                 .code,
             0);
    QCOMPARE(objects(first), objects(second));  // the same character ...
    QVERIFY(readAll(first) != readAll(second)); // ... in another drawing
    // Without --frame: the play range's first frame.
    const QString byDefault = m_dir.filePath(QStringLiteral("frames/default.obj"));
    QCOMPARE(runFinbook({QStringLiteral("export"), m_file, byDefault}).code, 0);
    QCOMPARE(readAll(byDefault), readAll(first).replace("first.mtl", "default.mtl"));

    // A closed shape beside a line: the shape is made 3D, the line left out and said so (on
    // stderr: stdout lists the files only).
    const QString ring = m_dir.filePath(QStringLiteral("frames/ring.obj"));
    const Run run =
        runFinbook({QStringLiteral("export"), m_file, ring, QStringLiteral("--frame=4")});
    QCOMPARE(run.code, 0);
    QVERIFY2(isOneLine(run.err) && run.err.contains("1 object of frame 4") &&
                 run.err.contains("left out"),
             run.err.constData());
    QCOMPARE(run.out.count('\n'), 2);
    QCOMPARE(objects(ring), QStringList({QStringLiteral("Ring")}));
}

void TestCliExportObj::existingTargetNeedsOverwrite()
{
    const QString out = m_dir.filePath(QStringLiteral("again.obj"));
    const QString mtl = m_dir.filePath(QStringLiteral("again.mtl"));
    QCOMPARE(runFinbook({QStringLiteral("export"), m_file, out}).code, 0);
    QFile::resize(out, 10);
    QFile::resize(mtl, 5);
    Run run = runFinbook({QStringLiteral("export"), m_file, out});
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err) && run.err.contains("--overwrite"), run.err.constData());
    QCOMPARE(QFileInfo(out).size(), qint64(10));
    QCOMPARE(QFileInfo(mtl).size(), qint64(5));
    // The material file alone in the way is refused as well.
    QFile::remove(out);
    run = runFinbook({QStringLiteral("export"), m_file, out});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains("again.mtl"), run.err.constData());
    QVERIFY(!QFileInfo::exists(out));
    QCOMPARE(QFileInfo(mtl).size(), qint64(5));
    run = runFinbook({QStringLiteral("export"), m_file, out, QStringLiteral("--overwrite")});
    QCOMPARE(run.code, 0);
    QVERIFY(QFileInfo(out).size() > 10000);
    QVERIFY(QFileInfo(mtl).size() > 5);
}

void TestCliExportObj::nothingMeshableExitsTwo_data()
{
    QTest::addColumn<QString>("frame");
    QTest::newRow("a dot") << "3";
}

void TestCliExportObj::nothingMeshableExitsTwo()
{
    QFETCH(QString, frame);
    const QString folder = m_dir.filePath(QStringLiteral("nothing"));
    const Run run =
        runFinbook({QStringLiteral("export"), m_file, folder + QStringLiteral("/dot.obj"),
                    QStringLiteral("--frame"), frame});
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err), run.err.constData());
    QVERIFY2(run.err.toLower().contains("frame " + frame.toLatin1()), run.err.constData());
    QVERIFY(run.out.isEmpty());
    QVERIFY(!QFileInfo::exists(folder));
}

void TestCliExportObj::badFrameArguments_data()
{
    QTest::addColumn<QStringList>("arguments");
    const QString out = m_dir.filePath(QStringLiteral("bad/out.obj"));
    const QString x = QStringLiteral("export");
    QTest::newRow("frame zero") << QStringList{x, m_file, out, QStringLiteral("--frame=0")};
    QTest::newRow("frame word") << QStringList{x, m_file, out, QStringLiteral("--frame=two")};
    QTest::newRow("frame past the end") << QStringList{x, m_file, out, QStringLiteral("--frame=9")};
    QTest::newRow("frame and range")
        << QStringList{x, m_file, out, QStringLiteral("--frame=1"), QStringLiteral("--range=1-2")};
    QTest::newRow("range of frames") << QStringList{x, m_file, out, QStringLiteral("--range=1-2")};
    QTest::newRow("mtl target") << QStringList{x, m_file, m_dir.filePath("bad/out.mtl"),
                                               QStringLiteral("--format=obj")};
}

void TestCliExportObj::badFrameArguments()
{
    QFETCH(QStringList, arguments);
    const Run run = runFinbook(arguments);
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err), run.err.constData());
    QVERIFY(run.out.isEmpty());
    QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("bad"))));
}

QTEST_GUILESS_MAIN(TestCliExportObj)
#include "tst_cli_export_obj.moc"
