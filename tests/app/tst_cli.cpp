// The `finbook` command line, run as a real process: info and export on the bundled example,
// and every bad file or argument ends in exit code 2 with exactly one line on stderr.
#include "cli.h"
#include "cli_run.h"

#include <finbook/model/camera/camera_commands.h>
#include <finbook/model/finbook_file.h>

#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QTextStream>
#include <QtEndian>
#include <QtTest>

#include <unordered_set>

using namespace finbook;
using namespace cli_run;

namespace {

const QString kExample = QStringLiteral(FINBOOK_SOURCE_DIR "/resources/examples/walk.finbook");

QByteArray exampleBytes()
{
    QFile f(kExample);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &bytes)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(bytes);
    return path;
}

} // namespace

class TestCli : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void versionAndHelp();
    void helpAndErrorsInFrenchAndJapanese();
    void infoMatchesTheFile();
    void infoInProcessMatchesBinary();
    void exportWritesEveryFrame();
    void cameraInInfoAndExport();
    void badFilesExitTwo_data();
    void badFilesExitTwo();
    void badArgumentsExitTwo_data();
    void badArgumentsExitTwo();
    void unwritableOutputFails();

private:
    QTemporaryDir m_dir;
};

void TestCli::initTestCase()
{
    QVERIFY(QFile::exists(QStringLiteral(FINBOOK_BINARY_DIR "/bin/finbook")));
    QVERIFY2(QFile::exists(kExample), qPrintable(kExample));
    QVERIFY(m_dir.isValid());
}

void TestCli::versionAndHelp()
{
    const Run version = runFinbook({QStringLiteral("--version")});
    QCOMPARE(version.code, 0);
    QCOMPARE(version.out.trimmed(), QByteArray("finbook ") + app::finbookVersion().toUtf8());
    const Run help = runFinbook({QStringLiteral("--help")});
    QCOMPARE(help.code, 0);
    QVERIFY(help.out.contains("finbook info FILE"));
    QVERIFY(help.out.contains("Usage: finbook"));
    QVERIFY(help.err.isEmpty());
    // Help and argument errors speak the chosen language too.
    const Run german =
        runFinbook({QStringLiteral("--lang"), QStringLiteral("de"), QStringLiteral("--help")});
    QCOMPARE(german.code, 0);
    QVERIFY2(german.out.contains("Aufruf: finbook"), german.out.constData());
    const Run bad = runFinbook({QStringLiteral("--lang=de"), QStringLiteral("--bogus")});
    QCOMPARE(bad.code, 2);
    QVERIFY2(bad.err.contains("Unbekannte Option"), bad.err.constData());
}

// French and Japanese, chosen with --lang or taken from the system's language: the help
// (Qt's own texts included), argument errors and command errors, each error one line.
void TestCli::helpAndErrorsInFrenchAndJapanese()
{
    const Run french =
        runFinbook({QStringLiteral("--lang"), QStringLiteral("fr"), QStringLiteral("--help")});
    QCOMPARE(french.code, 0);
    const QString frenchHelp = QString::fromUtf8(french.out);
    QVERIFY2(frenchHelp.contains(QStringLiteral("Utilisation : finbook")), french.out.constData());
    QVERIFY(frenchHelp.contains(QStringLiteral("ouvrir FILE dans l'éditeur")));
    QVERIFY(frenchHelp.contains(QStringLiteral("Afficher l'aide sur les options")));

    const Run japanese = runFinbook({QStringLiteral("--lang=ja"), QStringLiteral("--help")});
    QCOMPARE(japanese.code, 0);
    const QString japaneseHelp = QString::fromUtf8(japanese.out);
    QVERIFY2(japaneseHelp.contains(QStringLiteral("使い方: finbook")), japanese.out.constData());
    QVERIFY(japaneseHelp.contains(QStringLiteral("FILE をエディターで開く")));
    QVERIFY(japaneseHelp.contains(QStringLiteral("コマンドラインオプションのヘルプを表示する")));
    QVERIFY(!japaneseHelp.contains(QStringLiteral("Displays help")));

    const Run badFrench = runFinbook({QStringLiteral("--lang=fr"), QStringLiteral("--bogus")});
    QCOMPARE(badFrench.code, 2);
    QVERIFY(isOneLine(badFrench.err));
    QVERIFY2(QString::fromUtf8(badFrench.err).contains(QStringLiteral("; voir finbook --help.")),
             badFrench.err.constData());
    const Run badJapanese = runFinbook({QStringLiteral("--lang=ja"), QStringLiteral("--bogus")});
    QCOMPARE(badJapanese.code, 2);
    QVERIFY(isOneLine(badJapanese.err));
    const QString japaneseError = QString::fromUtf8(badJapanese.err).trimmed();
    QVERIFY2(japaneseError.endsWith(QStringLiteral("。finbook --help を参照してください。")),
             badJapanese.err.constData());
    QVERIFY(!japaneseError.contains(QStringLiteral("。;")));

    const Run missing = runFinbook({QStringLiteral("--lang"), QStringLiteral("ja"),
                                    QStringLiteral("info"), m_dir.filePath("none.finbook")});
    QCOMPARE(missing.code, 2);
    QVERIFY(isOneLine(missing.err));
    QVERIFY2(QString::fromUtf8(missing.err).contains(QStringLiteral("を開けません")),
             missing.err.constData());

    // No --lang: the system's language decides (LC_ALL overrides the test's C.UTF-8).
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove(QStringLiteral("LANGUAGE"));
    environment.insert(QStringLiteral("LC_ALL"), QStringLiteral("fr_FR.UTF-8"));
    const Run system = runFinbook({QStringLiteral("frob"), QStringLiteral("x")}, environment);
    QCOMPARE(system.code, 2);
    QVERIFY2(QString::fromUtf8(system.err).contains(QStringLiteral("Commande inconnue")),
             system.err.constData());
    environment.insert(QStringLiteral("LC_ALL"), QStringLiteral("ja_JP.UTF-8"));
    const Run systemJa = runFinbook({QStringLiteral("frob"), QStringLiteral("x")}, environment);
    QVERIFY2(QString::fromUtf8(systemJa.err).contains(QStringLiteral("不明なコマンド「frob」")),
             systemJa.err.constData());
}

void TestCli::infoMatchesTheFile()
{
    const Run run = runFinbook({QStringLiteral("info"), kExample});
    QCOMPARE(run.code, 0);
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    QVERIFY(isOneLine(run.out));
    QJsonParseError error;
    const QJsonObject info = QJsonDocument::fromJson(run.out, &error).object();
    QCOMPARE(error.error, QJsonParseError::NoError);

    auto loaded = model::loadFinbook(kExample);
    QVERIFY(loaded);
    qint64 objects = 0, strokes = 0, points = 0, fills = 0;
    std::unordered_set<const model::StrokeData *> distinct;
    for (const model::Frame &f : loaded->frames) {
        objects += qint64(f.groups.size());
        for (const model::StrokeGroup &g : f.groups) {
            strokes += qint64(g.strokes.size());
            fills += qint64(g.fills.size());
            for (const model::Stroke &s : g.strokes) {
                points += qint64(s.data->points.size());
                distinct.insert(s.data.get());
            }
        }
    }
    QCOMPARE(info[QStringLiteral("format_version")].toInteger(), model::kFinbookFormatVersion);
    QCOMPARE(info[QStringLiteral("frames")].toInteger(), qint64(loaded->frames.size()));
    QCOMPARE(info[QStringLiteral("objects")].toInteger(), objects);
    QCOMPARE(info[QStringLiteral("strokes")].toInteger(), strokes);
    QCOMPARE(info[QStringLiteral("points")].toInteger(), points);
    QCOMPARE(info[QStringLiteral("stroke_data")].toInteger(), qint64(distinct.size()));
    QCOMPARE(info[QStringLiteral("fills")].toInteger(-1), fills);
    QCOMPARE(info[QStringLiteral("fps")].toInt(), loaded->settings.fps);
    QCOMPARE(info[QStringLiteral("canvas_width")].toInt(), loaded->settings.canvasSize.width());
    QCOMPARE(info[QStringLiteral("canvas_height")].toInt(), loaded->settings.canvasSize.height());
    // The example as promised: a scene of three layers, one a walk cycle of at least 12 frames
    // with several objects each, its ground line shared by every frame.
    const QJsonArray layers = info[QStringLiteral("layers")].toArray();
    QCOMPARE(layers.size(), 3);
    QVERIFY(loaded->frames.size() >= 12);
    qint64 mostCels = 0;
    for (const QJsonValue &l : layers)
        mostCels = std::max(mostCels, l.toObject()[QStringLiteral("cels")].toInteger());
    QVERIFY(mostCels >= 12);
    QVERIFY(objects >= 7 * mostCels);
    QVERIFY(qint64(distinct.size()) < strokes);
    QCOMPARE(info[QStringLiteral("picture_objects")].toInteger(-1), 0);
    // A file with picture objects: counted, with the bytes each distinct picture is saved in.
    const Run pictures =
        runFinbook({QStringLiteral("info"),
                    QStringLiteral(FINBOOK_SOURCE_DIR "/tests/fuzz/seeds/pictures.finbook")});
    QCOMPARE(pictures.code, 0);
    const QJsonObject pictureInfo = QJsonDocument::fromJson(pictures.out).object();
    QCOMPARE(pictureInfo[QStringLiteral("picture_objects")].toInteger(), 2);
    QCOMPARE(pictureInfo[QStringLiteral("pictures")].toInteger(), 2);
    QVERIFY(pictureInfo[QStringLiteral("picture_bytes")].toInteger() > 100);
}

void TestCli::infoInProcessMatchesBinary()
{
    QString error;
    const QByteArray json = app::documentInfoJson(kExample, &error);
    QVERIFY2(!json.isEmpty(), qPrintable(error));
    QCOMPARE(json, runFinbook({QStringLiteral("info"), kExample}).out.trimmed());

    QString out, err;
    QTextStream outStream(&out), errStream(&err);
    QCOMPARE(app::runHeadlessCommand({QStringLiteral("info")}, outStream, errStream), 2);
    QVERIFY(out.isEmpty());
    QCOMPARE(err.count(QLatin1Char('\n')), 1);
}

void TestCli::exportWritesEveryFrame()
{
    auto loaded = model::loadFinbook(kExample);
    QVERIFY(loaded);
    const QString outDir = m_dir.filePath(QStringLiteral("export/nested"));
    const Run run = runFinbook({QStringLiteral("export"), kExample, outDir});
    QCOMPARE(run.code, 0);
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    const QStringList pngs =
        QDir(outDir).entryList({QStringLiteral("*.png")}, QDir::Files, QDir::Name);
    // One picture per tick of the shot (the camera moves on every tick).
    const qsizetype ticks =
        qsizetype(QJsonDocument::fromJson(runFinbook({QStringLiteral("info"), kExample}).out)
                      .object()[QStringLiteral("ticks")]
                      .toInteger());
    QCOMPARE(ticks, 12);
    QCOMPARE(pngs.size(), ticks);
    QCOMPARE(pngs.first(), QStringLiteral("frame_0001.png"));
    QCOMPARE(run.out.count('\n'), ticks);
    const QRgb background = loaded->settings.background;
    for (const QString &name : pngs) {
        const QImage image(QDir(outDir).filePath(name));
        QCOMPARE(image.size(), loaded->settings.canvasSize);
        qint64 inked = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                inked += image.pixel(x, y) != background;
        QVERIFY2(inked > 2000,
                 qPrintable(QStringLiteral("%1: %2 inked pixels").arg(name).arg(inked)));
        QCOMPARE(image.pixel(0, 0), background);
    }
}

// A page with a dot at (150, 50) and a camera zoomed in twice on it: `info` counts the keys,
// `export` frames the shot (the dot in the middle), `--no-camera` the page (the dot where it
// was drawn).
void TestCli::cameraInInfoAndExport()
{
    model::Document doc;
    model::DocumentSettings settings;
    settings.canvasSize = QSize(200, 100);
    doc.reset(std::vector<model::Frame>{}, settings, 1);
    doc.undoStack()->push(new model::InsertFrameCommand(&doc, 0));
    auto dot = std::make_shared<model::StrokeData>();
    dot->width = 8.0f;
    dot->points = {{149.5f, 50.0f, 1.0f}, {150.5f, 50.0f, 1.0f}};
    doc.undoStack()->push(new model::AddStrokeCommand(&doc, doc.frameAt(0).groups.at(0).id, dot));
    for (qint64 tick : {0, 6}) {
        model::CameraKey key;
        key.tick = tick;
        key.center = QPointF(150, 50);
        key.zoom = 2.0;
        doc.undoStack()->push(model::setCameraKeyCommand(&doc, key).release());
    }
    const QString file = m_dir.filePath(QStringLiteral("camera.finbook"));
    QVERIFY(!model::saveFinbook(doc, file));
    const Run info = runFinbook({QStringLiteral("info"), file});
    QCOMPARE(info.code, 0);
    const QJsonObject o = QJsonDocument::fromJson(info.out).object();
    QCOMPARE(o[QStringLiteral("camera_keys")].toInteger(), 2);
    QCOMPARE(o[QStringLiteral("camera_last_tick")].toInteger(), 6);
    const auto darkX = [](const QString &path) {
        const QImage image(path);
        double sum = 0, n = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                if (qGray(image.pixel(x, y)) < 100) {
                    sum += x + 0.5;
                    n += 1;
                }
        return n > 0 ? sum / n : -1.0;
    };
    for (const bool camera : {true, false}) {
        const QString out =
            m_dir.filePath(camera ? QStringLiteral("shot") : QStringLiteral("page"));
        QStringList args{QStringLiteral("export"), file, out};
        if (!camera)
            args << QStringLiteral("--no-camera");
        const Run run = runFinbook(args);
        QCOMPARE(run.code, 0);
        const double x = darkX(QDir(out).filePath(QStringLiteral("frame_0001.png")));
        QVERIFY2(std::abs(x - (camera ? 100.0 : 150.0)) < 1.0, qPrintable(QString::number(x)));
    }
}

void TestCli::badFilesExitTwo_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("expected");
    const QByteArray valid = exampleBytes();
    QByteArray newer = valid;
    qToLittleEndian<quint32>(model::kFinbookFormatVersion + 1, newer.data() + 8);
    QByteArray noise(3000, '\0');
    for (qsizetype i = 0; i < noise.size(); ++i)
        noise[i] = char((i * 7919 + 13) % 251);
    QTest::newRow("missing") << m_dir.filePath(QStringLiteral("missing.finbook")) << "exists";
    QTest::newRow("garbage") << writeFile(m_dir, QStringLiteral("garbage.finbook"), noise)
                             << "not a Finbook";
    QTest::newRow("empty") << writeFile(m_dir, QStringLiteral("empty.finbook"), {}) << "empty";
    QTest::newRow("truncated") << writeFile(m_dir, QStringLiteral("cut.finbook"), valid.left(5000))
                               << "incomplete";
    QTest::newRow("newer") << writeFile(m_dir, QStringLiteral("newer.finbook"), newer)
                           << "newer version of Finbook";
    QTest::newRow("folder") << m_dir.path() << "folder";
    if (QFile::exists(QStringLiteral("/dev/zero"))) // endless: must be refused, not read
        QTest::newRow("endless device") << QStringLiteral("/dev/zero") << "not a file";
}

void TestCli::badFilesExitTwo()
{
    QFETCH(QString, path);
    QFETCH(QString, expected);
    for (const QStringList &args :
         {QStringList{QStringLiteral("info"), path},
          QStringList{QStringLiteral("export"), path, m_dir.filePath(QStringLiteral("never"))}}) {
        const Run run = runFinbook(args);
        QCOMPARE(run.code, 2);
        QVERIFY2(isOneLine(run.err), run.err.constData());
        QVERIFY2(QString::fromUtf8(run.err).contains(expected), run.err.constData());
        QVERIFY(run.out.isEmpty());
    }
    QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("never/frame_0001.png"))));
}

void TestCli::badArgumentsExitTwo_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("unknown option") << QStringList{QStringLiteral("--frobnicate")};
    QTest::newRow("option without value") << QStringList{QStringLiteral("--lang")};
    QTest::newRow("info without file") << QStringList{QStringLiteral("info")};
    QTest::newRow("info with two files") << QStringList{QStringLiteral("info"), kExample, kExample};
    QTest::newRow("export without folder") << QStringList{QStringLiteral("export"), kExample};
    QTest::newRow("unknown command")
        << QStringList{QStringLiteral("frobnicate"), QStringLiteral("a"), QStringLiteral("b")};
}

void TestCli::badArgumentsExitTwo()
{
    QFETCH(QStringList, arguments);
    const Run run = runFinbook(arguments);
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err), run.err.constData());
    QVERIFY(run.out.isEmpty());
}

void TestCli::unwritableOutputFails()
{
    const QString plain = writeFile(m_dir, QStringLiteral("plain.txt"), "x");
    const Run run =
        runFinbook({QStringLiteral("export"), kExample, plain + QStringLiteral("/out")});
    QCOMPARE(run.code, 1);
    QVERIFY2(isOneLine(run.err), run.err.constData());
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
