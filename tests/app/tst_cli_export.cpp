// `finbook export` and `finbook info` as a user runs them: every format from the bundled example
// (with holds added), the options, several files at once, and every refusal or failure ending
// in one line on stderr, the promised exit code and nothing at the target.
#include "../model/export_support.h"
#include "cli_run.h"

#include <finbook/model/document.h>
#include <finbook/model/finbook_file.h>

#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <cstdio>
#include <dirent.h>
#include <map>
#include <sys/stat.h>
#include <unistd.h>

using namespace finbook;
using namespace finbook::test;
using namespace cli_run;

namespace {

const QString kFinbook = QStringLiteral(FINBOOK_BINARY_DIR "/bin/finbook");

QString shellQuote(const QString &s)
{
    return QLatin1Char('\'') + QString(s).replace(QLatin1String("'"), QLatin1String("'\\''")) +
           QLatin1Char('\'');
}

QString saveDocument(const model::ExportSource &source, const QString &path)
{
    model::Document doc;
    doc.reset(source.frames, source.settings, 1000000);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(model::serializeFinbook(doc));
    return path;
}

bool haveFfmpeg()
{
    return !program("ffmpeg").isEmpty() && !program("ffprobe").isEmpty();
}

// Every entry of `folder` (hidden ones too) with its bytes.
std::map<QString, QByteArray> folderContents(const QString &folder)
{
    std::map<QString, QByteArray> contents;
    const QDir dir(folder);
    for (const QString &name :
         dir.entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot)) {
        QFile f(dir.filePath(name));
        contents[name] = f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<not a file>");
    }
    return contents;
}

void copyFolder(const QString &from, const QString &to)
{
    QDir().mkpath(to);
    for (const auto &[name, bytes] : folderContents(from)) {
        QFile f(QDir(to).filePath(name));
        if (f.open(QIODevice::WriteOnly))
            f.write(bytes);
    }
}

// Whether process `pid` has ended (gone, or a zombie nobody has reaped yet).
bool processEnded(qint64 pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return true;
    const QByteArray text = stat.readAll();
    const qsizetype close = text.lastIndexOf(')');
    return close < 0 || text.mid(close + 2, 1) == "Z";
}

} // namespace

class TestCliExport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void infoCountsTicks();
    void exportsEveryFormat_data();
    void exportsEveryFormat();
    void optionsReachTheExport();
    void severalFilesWithOutDir();
    void badArgumentsExitTwo_data();
    void badArgumentsExitTwo();
    void existingTargetNeedsOverwrite();
    void fullDiskFailsCleanly_data();
    void fullDiskFailsCleanly();
    void missingFfmpegFails();
    void progressOnlyOnATerminal();
    void progressNameIsPrintedHarmless();
    void dashDashEndsOptions();
    void folderNamedLikeAFileIsRefused();
    void rootFolderIsRefused();
    void fileInTheWayOfTheFolderExitsTwo();
    void tooLargeNeedsMaxFrames();
    void namesThatAreNotUtf8();
    void overwriteLeavesOnlyTheNewSequence();
    void swapSurvivesAKillAtEveryStep();
    void encoderGroupEndsWithTheExport_data();
    void encoderGroupEndsWithTheExport();

private:
    QTemporaryDir m_dir;
    QString m_held; // the example with holds: 12 drawings, 18 ticks
};

void TestCliExport::initTestCase()
{
    QVERIFY(QFile::exists(kFinbook));
    QVERIFY(m_dir.isValid());
    m_held = saveDocument(exampleWithHolds(), m_dir.filePath(QStringLiteral("held.finbook")));
    QVERIFY(!m_held.isEmpty());
}

void TestCliExport::infoCountsTicks()
{
    const auto info = [](const QString &file) {
        const Run run = runFinbook({QStringLiteral("info"), file});
        return QJsonDocument::fromJson(run.out).object();
    };
    const QJsonObject plain = info(examplePath());
    QCOMPARE(plain[QStringLiteral("ticks")].toInteger(), qint64(12));
    QCOMPARE(plain[QStringLiteral("duration_s")].toDouble(), 1.0);
    const QJsonObject held = info(m_held);
    QCOMPARE(held[QStringLiteral("frames")].toInteger(), qint64(12));
    QCOMPARE(held[QStringLiteral("ticks")].toInteger(), qint64(18));
    QCOMPARE(held[QStringLiteral("duration_s")].toDouble(), 1.5);
    // Only the play range counts: frames 3-8 hold 3+1+1+1+1+2 ticks.
    model::ExportSource ranged = exampleWithHolds();
    ranged.settings.playStart = 2;
    ranged.settings.playEnd = 7;
    ranged.settings.fps = 6;
    const QJsonObject part =
        info(saveDocument(ranged, m_dir.filePath(QStringLiteral("part.finbook"))));
    QCOMPARE(part[QStringLiteral("ticks")].toInteger(), qint64(9));
    QCOMPARE(part[QStringLiteral("duration_s")].toDouble(), 1.5);
}

void TestCliExport::exportsEveryFormat_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("target");
    QTest::addColumn<int>("files");
    QTest::addColumn<bool>("needsFfmpeg");
    QTest::newRow("png folder") << QStringList{} << "frames" << 18 << false;
    QTest::newRow("svg") << QStringList{QStringLiteral("--format"), QStringLiteral("svg")}
                         << "vectors" << 18 << false;
    QTest::newRow("html") << QStringList{} << "walk.html" << 1 << false;
    QTest::newRow("gif") << QStringList{} << "walk.gif" << 1 << true;
    QTest::newRow("mp4") << QStringList{} << "walk.mp4" << 1 << true;
    QTest::newRow("webm") << QStringList{} << "walk.webm" << 1 << true;
    QTest::newRow("apng") << QStringList{} << "walk.apng" << 1 << true;
    QTest::newRow("lottie json") << QStringList{} << "walk.json" << 1 << false;
    QTest::newRow("dotlottie") << QStringList{} << "walk.lottie" << 1 << false;
    QTest::newRow("lottie by --format")
        << QStringList{QStringLiteral("--format"), QStringLiteral("json")} << "shot.json" << 1
        << false;
    QTest::newRow("gif by --format")
        << QStringList{QStringLiteral("--format=gif")} << "anim" << 1 << true;
}

void TestCliExport::exportsEveryFormat()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, target);
    QFETCH(int, files);
    QFETCH(bool, needsFfmpeg);
    if (needsFfmpeg && !haveFfmpeg())
        QSKIP("ffmpeg/ffprobe not installed (bash .ci/setup installs them)");
    const QString out = m_dir.filePath(QStringLiteral("every/") + target);
    const Run run = runFinbook(QStringList{QStringLiteral("export"), m_held, out} + arguments);
    QCOMPARE(run.code, 0);
    QVERIFY2(run.err.isEmpty(), run.err.constData()); // no progress: stderr is not a terminal
    QCOMPARE(run.out.count('\n'), qsizetype(files));
    const QStringList written =
        QString::fromLocal8Bit(run.out).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (const QString &file : written)
        QVERIFY2(QFileInfo(file).size() > 0, qPrintable(file));
    if (files == 1)
        QCOMPARE(written.first(), out);
    if (out.endsWith(QLatin1String(".json"))) { // a Lottie file of the whole shot
        QFile file(out);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject lottie = QJsonDocument::fromJson(file.readAll()).object();
        QCOMPARE(lottie[QStringLiteral("op")].toInt(), 18);
        QCOMPARE(lottie[QStringLiteral("w")].toInt(), 1280);
        QVERIFY(!lottie[QStringLiteral("layers")].toArray().isEmpty());
    }
    if (needsFfmpeg) {
        const QJsonObject stream = probe(out);
        const bool gif = stream[QStringLiteral("codec_name")].toString() == QLatin1String("gif");
        QCOMPARE(stream[QStringLiteral("nb_read_frames")].toString().toInt(), gif ? 12 : 18);
        QCOMPARE(stream[QStringLiteral("width")].toInt(), 1280);
    }
}

void TestCliExport::optionsReachTheExport()
{
    const QString png = m_dir.filePath(QStringLiteral("options/png"));
    Run run = runFinbook({QStringLiteral("export"), m_held, png, QStringLiteral("--range"),
                          QStringLiteral("3-8"), QStringLiteral("--scale"), QStringLiteral("0.25"),
                          QStringLiteral("--background"), QStringLiteral("#ff0000")});
    QCOMPARE(run.code, 0);
    QCOMPARE(run.out.count('\n'), qsizetype(9)); // ticks of frames 3-8
    const QImage red(QDir(png).filePath(QStringLiteral("frame_0001.png")));
    QCOMPARE(red.size(), QSize(320, 180));
    QCOMPARE(red.pixel(0, 0), qRgb(255, 0, 0));

    const QString clear = m_dir.filePath(QStringLiteral("options/clear"));
    run = runFinbook({QStringLiteral("export"), m_held, clear, QStringLiteral("--transparent"),
                      QStringLiteral("--one-per-drawing"), QStringLiteral("--range=12")});
    QCOMPARE(run.code, 0);
    QCOMPARE(run.out.count('\n'), qsizetype(2)); // frame 12 once, and its exposure sheet
    const QImage transparent(QDir(clear).filePath(QStringLiteral("frame_0012.png")));
    QCOMPARE(qAlpha(transparent.pixel(0, 0)), 0);
    QFile sheet(QDir(clear).filePath(QStringLiteral("frame_exposures.json")));
    QVERIFY(sheet.open(QIODevice::ReadOnly));
    QVERIFY(sheet.readAll().contains("\"hold\": 4"));

    if (!haveFfmpeg())
        QSKIP("ffmpeg/ffprobe not installed");
    const QString mp4 = m_dir.filePath(QStringLiteral("options/part.mp4"));
    run = runFinbook({QStringLiteral("export"), m_held, mp4, QStringLiteral("--range=3-8"),
                      QStringLiteral("--scale=0.25"), QStringLiteral("--fps=24")});
    QCOMPARE(run.code, 0);
    const QJsonObject stream = probe(mp4);
    QCOMPARE(stream[QStringLiteral("nb_read_frames")].toString().toInt(), 9);
    QCOMPARE(stream[QStringLiteral("width")].toInt(), 320);
    QCOMPARE(stream[QStringLiteral("r_frame_rate")].toString(), QStringLiteral("24/1"));
}

void TestCliExport::severalFilesWithOutDir()
{
    const QString second = m_dir.filePath(QStringLiteral("second.finbook"));
    QVERIFY(QFile::copy(examplePath(), second));
    const QString dir = m_dir.filePath(QStringLiteral("batch"));
    Run run = runFinbook({QStringLiteral("export"), m_held, second, QStringLiteral("--format"),
                          QStringLiteral("html"), QStringLiteral("--out-dir"), dir});
    QCOMPARE(run.code, 0);
    QCOMPARE(run.out, (QDir(dir).filePath(QStringLiteral("held.html")) + QLatin1Char('\n') +
                       QDir(dir).filePath(QStringLiteral("second.html")) + QLatin1Char('\n'))
                          .toLocal8Bit());
    run = runFinbook({QStringLiteral("export"), m_held, second, QStringLiteral("--out-dir"), dir});
    QCOMPARE(run.code, 0); // PNG by default: a folder per file
    QCOMPARE(QDir(QDir(dir).filePath(QStringLiteral("held"))).entryList(QDir::Files).size(),
             qsizetype(18));
    QCOMPARE(QDir(QDir(dir).filePath(QStringLiteral("second"))).entryList(QDir::Files).size(),
             qsizetype(12));
}

void TestCliExport::badArgumentsExitTwo_data()
{
    QTest::addColumn<QStringList>("arguments");
    const QString out = m_dir.filePath(QStringLiteral("bad/out"));
    const QString e = examplePath();
    const QString x = QStringLiteral("export");
    QTest::newRow("unknown suffix") << QStringList{x, e, out + QStringLiteral(".xyz")};
    QTest::newRow("single png file") << QStringList{x, e, out + QStringLiteral(".png")};
    QTest::newRow("unknown format") << QStringList{x, e, out, QStringLiteral("--format=bmp")};
    QTest::newRow("format against suffix")
        << QStringList{x, e, out + QStringLiteral(".mp4"), QStringLiteral("--format=gif")};
    QTest::newRow("range backwards") << QStringList{x, e, out, QStringLiteral("--range=5-2")};
    QTest::newRow("range words") << QStringList{x, e, out, QStringLiteral("--range=a-b")};
    QTest::newRow("range past the end") << QStringList{x, e, out, QStringLiteral("--range=2-40")};
    QTest::newRow("scale zero") << QStringList{x, e, out, QStringLiteral("--scale=0")};
    QTest::newRow("scale word") << QStringList{x, e, out, QStringLiteral("--scale=big")};
    QTest::newRow("scale huge") << QStringList{x, e, out, QStringLiteral("--scale=500")};
    QTest::newRow("fps too high") << QStringList{x, e, out, QStringLiteral("--fps=99")};
    QTest::newRow("bad colour") << QStringList{x, e, out, QStringLiteral("--background=nope")};
    QTest::newRow("transparent mp4")
        << QStringList{x, e, out + QStringLiteral(".mp4"), QStringLiteral("--transparent")};
    QTest::newRow("transparent and background") << QStringList{
        x, e, out, QStringLiteral("--transparent"), QStringLiteral("--background=#fff")};
    QTest::newRow("per drawing gif")
        << QStringList{x, e, out + QStringLiteral(".gif"), QStringLiteral("--one-per-drawing")};
    QTest::newRow("three without out-dir") << QStringList{x, e, e, out};
    QTest::newRow("out-dir without files") << QStringList{x, QStringLiteral("--out-dir"), out};
    QTest::newRow("unknown option") << QStringList{x, e, out, QStringLiteral("--speed=2")};
    QTest::newRow("export option for info")
        << QStringList{QStringLiteral("info"), e, QStringLiteral("--scale=2")};
}

void TestCliExport::badArgumentsExitTwo()
{
    QFETCH(QStringList, arguments);
    const Run run = runFinbook(arguments);
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err), run.err.constData());
    QVERIFY(run.out.isEmpty());
    QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("bad"))));
}

void TestCliExport::existingTargetNeedsOverwrite()
{
    const QString page = m_dir.filePath(QStringLiteral("again.html"));
    QCOMPARE(runFinbook({QStringLiteral("export"), m_held, page}).code, 0);
    const QDateTime written = QFileInfo(page).lastModified();
    QFile::resize(page, 10);
    Run run = runFinbook({QStringLiteral("export"), m_held, page});
    QCOMPARE(run.code, 2);
    QVERIFY(isOneLine(run.err));
    QVERIFY2(run.err.contains("--overwrite"), run.err.constData());
    QCOMPARE(QFileInfo(page).size(), qint64(10));
    run = runFinbook({QStringLiteral("export"), m_held, page, QStringLiteral("--overwrite")});
    QCOMPARE(run.code, 0);
    QVERIFY(QFileInfo(page).size() > 10000);
    Q_UNUSED(written);
    // The PNG folder form too: an existing frame is not replaced without --overwrite.
    const QString folder = m_dir.filePath(QStringLiteral("again"));
    QCOMPARE(runFinbook({QStringLiteral("export"), m_held, folder}).code, 0);
    QCOMPARE(runFinbook({QStringLiteral("export"), m_held, folder}).code, 2);
    QCOMPARE(
        runFinbook({QStringLiteral("export"), m_held, folder, QStringLiteral("--overwrite")}).code,
        0);
}

void TestCliExport::fullDiskFailsCleanly_data()
{
    QTest::addColumn<QString>("target");
    QTest::addColumn<bool>("needsFfmpeg");
    QTest::newRow("png") << "frames" << false;
    QTest::newRow("html") << "walk.html" << false;
    QTest::newRow("gif") << "walk.gif" << true;
    QTest::newRow("mp4") << "walk.mp4" << true;
    QTest::newRow("obj") << "walk.obj" << false;
    QTest::newRow("lottie") << "walk.json" << false;
    QTest::newRow("dotlottie") << "walk.lottie" << false;
}

// Files cannot grow past 8 KiB (ulimit -f; SIGXFSZ ignored so writes fail with EFBIG), as
// when the disk fills during the export. Before, the PNG export said nothing and left empty
// or cut PNGs; now it fails with one line and leaves nothing.
void TestCliExport::fullDiskFailsCleanly()
{
    QFETCH(QString, target);
    QFETCH(bool, needsFfmpeg);
    if (needsFfmpeg && !haveFfmpeg())
        QSKIP("ffmpeg not installed");
    const QString folder =
        m_dir.filePath(QStringLiteral("full_") + QString::fromLatin1(QTest::currentDataTag()));
    QVERIFY(QDir().mkpath(folder));
    const QString out = QDir(folder).filePath(target);
    const QString command = QStringLiteral("trap '' XFSZ; ulimit -f 8; exec %1 export %2 %3")
                                .arg(shellQuote(kFinbook), shellQuote(m_held), shellQuote(out));
    const Run run = runProgram(QStringLiteral("/bin/sh"), {QStringLiteral("-c"), command});
    QCOMPARE(run.code, 1);
    QVERIFY2(isOneLine(run.err), run.err.constData());
    qInfo("%s", run.err.trimmed().constData());
    QVERIFY(run.out.isEmpty());
    QCOMPARE(filesIn(folder), QStringList());
}

void TestCliExport::missingFfmpegFails()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("FINBOOK_FFMPEG"), m_dir.filePath(QStringLiteral("nowhere/ffmpeg")));
    const QString out = m_dir.filePath(QStringLiteral("noffmpeg/walk.mp4"));
    const Run run = runProgram(kFinbook, {QStringLiteral("export"), m_held, out}, env);
    QCOMPARE(run.code, 1);
    QVERIFY(isOneLine(run.err));
    QVERIFY2(run.err.contains("ffmpeg"), run.err.constData());
    QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("noffmpeg"))));
}

void TestCliExport::progressOnlyOnATerminal()
{
    if (program("script").isEmpty())
        QSKIP("script (util-linux) not installed");
    const QString out = m_dir.filePath(QStringLiteral("tty.html"));
    // script(1) gives the command a terminal; what it printed there comes back on stdout.
    const QString command = QStringLiteral("%1 export %2 %3")
                                .arg(shellQuote(kFinbook), shellQuote(m_held), shellQuote(out));
    const Run run = runProgram(program("script"),
                               {QStringLiteral("-qec"), command, QStringLiteral("/dev/null")});
    QCOMPARE(run.code, 0);
    QVERIFY2(run.out.contains("tty.html: 12/12 (100%)"), run.out.constData());
    QVERIFY(QFileInfo::exists(out));
}

// A file name holding a terminal escape reaches the progress line written out (\x1B), as it
// does in error lines; before, the terminal received the escape itself.
void TestCliExport::progressNameIsPrintedHarmless()
{
    if (program("script").isEmpty())
        QSKIP("script (util-linux) not installed");
    const QString out = m_dir.filePath(QStringLiteral("tty\x1b[31mred.html"));
    const QString command = QStringLiteral("%1 export %2 %3")
                                .arg(shellQuote(kFinbook), shellQuote(m_held), shellQuote(out));
    const Run run = runProgram(program("script"),
                               {QStringLiteral("-qec"), command, QStringLiteral("/dev/null")});
    QCOMPARE(run.code, 0);
    QVERIFY2(!run.out.contains("\x1b[31m"), run.out.constData());
    QVERIFY2(run.out.contains("tty\\x1b[31mred.html: 12/12 (100%)"), run.out.constData());
}

// "--" ends the options for `export` as it does for `info`: a file named "-x.finbook" is a
// file, not the options -x, -., -f ...
void TestCliExport::dashDashEndsOptions()
{
    const QString folder = m_dir.filePath(QStringLiteral("dashes"));
    QVERIFY(QDir().mkpath(folder));
    QVERIFY(QFile::copy(m_held, QDir(folder).filePath(QStringLiteral("-x.finbook"))));
    QProcess process;
    process.setWorkingDirectory(folder);
    process.start(kFinbook, {QStringLiteral("export"), QStringLiteral("--"),
                             QStringLiteral("-x.finbook"), QStringLiteral("-out.html")});
    QVERIFY(process.waitForFinished(60000));
    QVERIFY2(process.exitCode() == 0, process.readAllStandardError().constData());
    QVERIFY(QFileInfo(QDir(folder).filePath(QStringLiteral("-out.html"))).size() > 1000);
    // Options before "--" still count.
    process.start(kFinbook,
                  {QStringLiteral("export"), QStringLiteral("--scale=0.5"), QStringLiteral("--"),
                   QStringLiteral("-x.finbook"), QStringLiteral("-frames")});
    QVERIFY(process.waitForFinished(60000));
    QVERIFY2(process.exitCode() == 0, process.readAllStandardError().constData());
    const QImage first(QDir(folder).filePath(QStringLiteral("-frames/frame_0001.png")));
    QCOMPARE(first.size(), exampleWithHolds().settings.canvasSize / 2);
}

// An existing folder called "anim.gif" is not a place for PNG frames unless asked for.
void TestCliExport::folderNamedLikeAFileIsRefused()
{
    const QString folder = m_dir.filePath(QStringLiteral("anim.gif"));
    QVERIFY(QDir().mkpath(folder));
    Run run = runFinbook({QStringLiteral("export"), m_held, folder});
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err) && run.err.contains("--format png"), run.err.constData());
    QCOMPARE(filesIn(folder), QStringList());
    run = runFinbook({QStringLiteral("export"), m_held, folder, QStringLiteral("--format=png")});
    QCOMPARE(run.code, 0);
    QCOMPARE(filesIn(folder).size(), 18);
}

// "export walk.finbook /" is a slip, never a wish to strew frames over the root folder.
void TestCliExport::rootFolderIsRefused()
{
    const QStringList before = filesIn(QStringLiteral("/"));
    const Run run = runFinbook({QStringLiteral("export"), m_held, QStringLiteral("/")});
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err) && run.err.contains("/frame"), run.err.constData());
    QCOMPARE(filesIn(QStringLiteral("/")), before);
}

// The README promises exit code 2 for a file in the way; it was 1 for a file where the PNG
// folder should be.
void TestCliExport::fileInTheWayOfTheFolderExitsTwo()
{
    const QString blocked = m_dir.filePath(QStringLiteral("blocked"));
    QFile file(blocked);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("mine");
    file.close();
    const Run run = runFinbook({QStringLiteral("export"), m_held, blocked});
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err), run.err.constData());
    QCOMPARE(QFileInfo(blocked).size(), qint64(4));
}

// More frames than the limits allow need --max-frames; a limit below the export refuses it.
void TestCliExport::tooLargeNeedsMaxFrames()
{
    model::ExportSource held = exampleWithHolds();
    for (model::Frame &f : held.frames)
        f.hold = 1000; // 12,000 ticks: 16.7 minutes at 12 fps
    while (held.frames.size() < 101)
        held.frames.push_back(held.frames.back());
    model::Id next = 100000; // copies need ids of their own
    for (model::Frame &f : held.frames) {
        f.id = next++;
        for (model::StrokeGroup &g : f.groups) {
            g.id = next++;
            for (model::Stroke &stroke : g.strokes)
                stroke.id = next++;
        }
    }
    const QString file = saveDocument(held, m_dir.filePath(QStringLiteral("long.finbook")));
    QVERIFY(!file.isEmpty());
    const QString folder = m_dir.filePath(QStringLiteral("long"));
    // 101,000 PNG files: refused at once, with the way out named.
    Run run = runFinbook({QStringLiteral("export"), file, folder});
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err) && run.err.contains("--max-frames"), run.err.constData());
    QVERIFY(!QFileInfo::exists(folder));
    // 28 hours of GIF at 1 frame per second: refused before ffmpeg is started.
    const QString gif = m_dir.filePath(QStringLiteral("long.gif"));
    run = runFinbook({QStringLiteral("export"), file, gif, QStringLiteral("--fps=1")});
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err) && run.err.contains("--max-frames"), run.err.constData());
    QVERIFY(!QFileInfo::exists(gif));
    // An explicit limit below what the export needs refuses it too.
    run = runFinbook({QStringLiteral("export"), m_held, folder, QStringLiteral("--max-frames=17")});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains("18"), run.err.constData());
    QVERIFY(!QFileInfo::exists(folder));
    run = runFinbook({QStringLiteral("export"), m_held, folder, QStringLiteral("--max-frames=18")});
    QCOMPARE(run.code, 0);
    QCOMPARE(run.out.count('\n'), 18);
}

// The entries of a folder named by bytes, as the system has them (QDir would decode them).
QList<QByteArray> rawEntries(const QByteArray &folder)
{
    QList<QByteArray> names;
    if (DIR *dir = ::opendir(folder.constData())) {
        while (const dirent *entry = ::readdir(dir))
            if (qstrcmp(entry->d_name, ".") != 0 && qstrcmp(entry->d_name, "..") != 0)
                names << QByteArray(entry->d_name);
        ::closedir(dir);
    }
    std::sort(names.begin(), names.end());
    return names;
}

bool isRegularFile(const QByteArray &path)
{
    struct stat status {};
    return ::stat(path.constData(), &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0;
}

// A Latin-1 file name ("caf\xe9.finbook") could not be opened: Qt read it as "caf\uFFFD".
// Now it opens (info and export). An output so named was refused, and before that written
// under the name with U+FFFD; now every kind of output is written under exactly the bytes
// given, for a file, a sequence's folder, a folder on the way and --out-dir alike, with the
// usual refusals, lock and cleaning of leftovers.
void TestCliExport::namesThatAreNotUtf8()
{
    const QString folder = m_dir.filePath(QStringLiteral("latin1"));
    QVERIFY(QDir().mkpath(folder));
    const QByteArray here = QFile::encodeName(folder) + '/';
    const QByteArray raw = here + "caf\xe9.finbook";
    QFile source(m_held);
    QVERIFY(source.open(QIODevice::ReadOnly));
    const QByteArray bytes = source.readAll();
    FILE *copy = std::fopen(raw.constData(), "wb");
    QVERIFY(copy);
    QCOMPARE(std::fwrite(bytes.constData(), 1, std::size_t(bytes.size()), copy),
             std::size_t(bytes.size()));
    std::fclose(copy);
    const auto shell = [&](const QString &arguments) {
        // printf makes the bytes 0xE9 (\351) and 0xFF (\377); QProcess passes only UTF-8.
        return runProgram(
            QStringLiteral("/bin/sh"),
            {QStringLiteral("-c"), QStringLiteral("cd %1 && exec %2 %3")
                                       .arg(shellQuote(folder), shellQuote(kFinbook), arguments)});
    };
    Run run = shell(QStringLiteral("info \"$(printf 'caf\\351.finbook')\""));
    QVERIFY2(run.code == 0, run.err.constData());
    QVERIFY(run.out.contains("\"frames\":12"));
    run = shell(QStringLiteral("export \"$(printf 'caf\\351.finbook')\" out.html"));
    QVERIFY2(run.code == 0, run.err.constData());
    QVERIFY(QFileInfo(QDir(folder).filePath(QStringLiteral("out.html"))).size() > 1000);

    // Every kind of output, under the bytes given; stdout names it by them too.
    struct Kind {
        const char *name; // as printf writes it
        QByteArray bytes;
        bool folder;
        bool ffmpeg;
    };
    const Kind kinds[] = {{"x\\377.html", "x\xff.html", false, false},
                          {"x\\377.gif", "x\xff.gif", false, true},
                          {"x\\377.mp4", "x\xff.mp4", false, true},
                          {"x\\377.webm", "x\xff.webm", false, true},
                          {"x\\377.apng", "x\xff.apng", false, true},
                          {"png\\377 --format png", "png\xff", true, false},
                          {"svg\\377 --format svg", "svg\xff", true, false}};
    for (const Kind &kind : kinds) {
        if (kind.ffmpeg && !haveFfmpeg())
            continue;
        const QString name = QString::fromLatin1(kind.name);
        const QString printed = name.section(QLatin1Char(' '), 0, 0);
        const QString options = name.section(QLatin1Char(' '), 1);
        run = shell(QStringLiteral("export \"$(printf 'caf\\351.finbook')\" \"$(printf '%1')\" "
                                   "--scale=0.25 %2")
                        .arg(printed, options));
        QVERIFY2(run.code == 0, (QByteArray(kind.name) + ": " + run.err).constData());
        if (kind.folder) {
            QCOMPARE(run.out.count('\n'), 18);
            QVERIFY2(run.out.startsWith(kind.bytes + "/frame_0001."), run.out.constData());
            const QList<QByteArray> frames = rawEntries(here + kind.bytes);
            QCOMPARE(frames.size(), 18); // no lock, no staging folder left
            QVERIFY(isRegularFile(here + kind.bytes + '/' + frames.first()));
        } else {
            QCOMPARE(run.out, kind.bytes + '\n');
            QVERIFY2(isRegularFile(here + kind.bytes), kind.name);
        }
    }
    if (haveFfmpeg()) {
        // ffprobe is given a UTF-8 name for it: a link.
        QString error;
        const QString link = QDir(folder).filePath(QStringLiteral("link.gif"));
        QVERIFY(::symlink("x\xff.gif", QFile::encodeName(link).constData()) == 0);
        const QJsonObject stream = probe(link, &error);
        QVERIFY2(!stream.isEmpty(), qPrintable(error));
        QCOMPARE(stream[QStringLiteral("nb_read_frames")].toString().toInt(), 12);
        QCOMPARE(stream[QStringLiteral("width")].toInt(), 320);
        QFile::remove(link);
    }
    // Nothing was written under the name with U+FFFD, and no temporary stayed.
    for (const QByteArray &entry : rawEntries(QFile::encodeName(folder))) {
        QVERIFY2(!entry.contains("\xef\xbf\xbd"), entry.constData());
        QVERIFY2(!entry.startsWith('.'), entry.constData());
    }

    // An existing file is kept without --overwrite and replaced with it; the leftover of a
    // killed export to it (its temporary has the valid name, with U+FFFD) is cleaned.
    const QString html = QStringLiteral("export \"$(printf 'caf\\351.finbook')\" "
                                        "\"$(printf 'x\\377.html')\" --scale=0.25");
    run = shell(html);
    QCOMPARE(run.code, 2);
    QVERIFY2(isOneLine(run.err) && run.err.contains("--overwrite"), run.err.constData());
    const QString leftover = QDir(folder).filePath(QStringLiteral(".x\uFFFD.html.Ab12Cd.part"));
    QVERIFY(QFile(leftover).open(QIODevice::WriteOnly));
    run = shell(html + QStringLiteral(" --overwrite"));
    QVERIFY2(run.code == 0, run.err.constData());
    QVERIFY(!QFileInfo::exists(leftover));
    // The lock is taken on that name too: an export holding it makes the next one wait.
    {
        QLockFile lock(QDir(folder).filePath(QStringLiteral(".x\uFFFD.html.export-lock")));
        lock.setStaleLockTime(0);
        QVERIFY(lock.tryLock(0));
        run = shell(html + QStringLiteral(" --overwrite"));
        QCOMPARE(run.code, 1);
        QVERIFY2(isOneLine(run.err) && run.err.contains("Another export"), run.err.constData());
    }

    // Folders on the way named by such bytes are made, and removed again after a failure.
    run = shell(QStringLiteral("export \"$(printf 'caf\\351.finbook')\" "
                               "\"$(printf 'd\\351/e\\351/y\\377.html')\" --scale=0.25"));
    QVERIFY2(run.code == 0, run.err.constData());
    QCOMPARE(run.out, QByteArray("d\xe9/e\xe9/y\xff.html\n"));
    QVERIFY(isRegularFile(here + "d\xe9/e\xe9/y\xff.html"));
    run = shell(QStringLiteral("export \"$(printf 'caf\\351.finbook')\" "
                               "\"$(printf 'n\\351/m\\351')\" --scale=0.25 --range=1-2 "
                               "--max-frames=1"));
    QCOMPARE(run.code, 2);
    QVERIFY(!rawEntries(QFile::encodeName(folder)).contains("n\xe9"));
    // --out-dir: the output is named after the input by its bytes.
    run = shell(QStringLiteral("export \"$(printf 'caf\\351.finbook')\" "
                               "--out-dir \"$(printf 'o\\351')\" --format html --scale=0.25"));
    QVERIFY2(run.code == 0, run.err.constData());
    QCOMPARE(run.out, QByteArray("o\xe9/caf\xe9.html\n"));
    QVERIFY(isRegularFile(here + "o\xe9/caf\xe9.html"));
    // QTemporaryDir cannot name these entries to remove them.
    runProgram(QStringLiteral("/bin/rm"), {QStringLiteral("-rf"), folder});
}

// --overwrite with fewer frames than the sequence already there: the old frames past the new
// end go too (they used to stay, mixing two exports); other files in the folder stay.
void TestCliExport::overwriteLeavesOnlyTheNewSequence()
{
    const QString folder = m_dir.filePath(QStringLiteral("shorter"));
    QCOMPARE(runFinbook({QStringLiteral("export"), m_held, folder}).code, 0);
    QCOMPARE(folderContents(folder).size(), std::size_t(18));
    QFile other(QDir(folder).filePath(QStringLiteral("notes.txt")));
    QVERIFY(other.open(QIODevice::WriteOnly));
    other.write("mine");
    other.close();
    const QString fresh = m_dir.filePath(QStringLiteral("shorter-fresh"));
    QCOMPARE(
        runFinbook({QStringLiteral("export"), m_held, fresh, QStringLiteral("--range=3-8")}).code,
        0);
    QCOMPARE(runFinbook({QStringLiteral("export"), m_held, folder, QStringLiteral("--range=3-8"),
                         QStringLiteral("--overwrite")})
                 .code,
             0);
    std::map<QString, QByteArray> expected = folderContents(fresh);
    expected[QStringLiteral("notes.txt")] = "mine";
    QVERIFY(folderContents(folder) == expected);
}

// A sequence export replacing another is killed (as kill -9 would) before each rename of its
// swap in turn; the next export to the folder, with --overwrite or without, finds the folder
// all old or all new and leaves no hidden folder behind. It used to be mixed (new frames, old
// ones, one missing), and a later --overwrite deleted the set-aside originals.
void TestCliExport::swapSurvivesAKillAtEveryStep()
{
    const QString oldFrames = m_dir.filePath(QStringLiteral("swap-old"));
    const QString newFrames = m_dir.filePath(QStringLiteral("swap-new"));
    // Tiny pictures: the swap is what is tested, and the export runs 60 times.
    const QString small = QStringLiteral("--scale=0.05");
    QCOMPARE(runFinbook({QStringLiteral("export"), m_held, oldFrames, small}).code, 0); // 18 files
    QCOMPARE(runFinbook({QStringLiteral("export"), m_held, newFrames, small,
                         QStringLiteral("--range=3-8")})
                 .code,
             0); // 9 files, other pictures
    const auto before = folderContents(oldFrames), after = folderContents(newFrames);
    QCOMPARE(before.size(), std::size_t(18));
    QCOMPARE(after.size(), std::size_t(9));
    int killed = 0;
    for (int step = 1; step < 100; ++step) {
        const QString folder = m_dir.filePath(QStringLiteral("swap-%1").arg(step));
        copyFolder(oldFrames, folder);
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("FINBOOK_TEST_KILL_AT_SWAP_STEP"), QString::number(step));
        const Run swap = runFinbook({QStringLiteral("export"), m_held, folder, small,
                                     QStringLiteral("--range=3-8"), QStringLiteral("--overwrite")},
                                    env);
        if (swap.code == 0) { // past the last step: the swap ended
            QVERIFY(folderContents(folder) == after);
            break;
        }
        QCOMPARE(swap.code, -1); // killed
        ++killed;
        // The next export: with --overwrite every other time, without it otherwise.
        const bool overwrite = step % 2 == 1;
        QStringList next{QStringLiteral("export"), m_held, folder, small,
                         QStringLiteral("--range=3-8")};
        if (overwrite)
            next << QStringLiteral("--overwrite");
        const Run again = runFinbook(next);
        const auto now = folderContents(folder);
        if (overwrite) {
            QCOMPARE(again.code, 0);
            QVERIFY2(now == after, qPrintable(QStringLiteral("step %1").arg(step)));
        } else {
            QCOMPARE(again.code, 2); // frames in the way: all old, or all new
            QVERIFY2(now == before || now == after,
                     qPrintable(QStringLiteral("step %1: %2 entries").arg(step).arg(now.size())));
        }
    }
    // The journal, 9 new files each with an old one set aside, 9 old ones past the end, the end.
    QCOMPARE(killed, 1 + 9 * 2 + 9 + 1);
}

void TestCliExport::encoderGroupEndsWithTheExport_data()
{
    QTest::addColumn<int>("signal");
    QTest::newRow("export finishes") << 0;
    QTest::newRow("SIGTERM") << int(SIGTERM);
    QTest::newRow("SIGKILL") << int(SIGKILL);
}

// An encoder that leaves a process in the background (a wrapper script, a plugin): when the
// export ends, however it ends, that process ends too. It used to survive a killed export.
void TestCliExport::encoderGroupEndsWithTheExport()
{
    QFETCH(int, signal);
    QTemporaryDir dir;
    const QString pidFile = dir.filePath(QStringLiteral("background.pid"));
    // Starts a sleeper in the background, then either takes every frame and writes a small
    // output (the export finishes) or takes none (the export waits until it is stopped).
    const QString script = dir.filePath(QStringLiteral("ffmpeg"));
    {
        QFile f(script);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("#!/bin/sh\nsleep 300 &\necho $! > " + shellQuote(pidFile).toUtf8() +
                "\nfor a; do last=$a; done\n" +
                (signal == 0 ? QByteArray("cat > /dev/null\necho mp4 > \"${last#file:}\"\n")
                             : QByteArray("sleep 300\n")));
        f.close();
        f.setPermissions(f.permissions() | QFileDevice::ExeOwner | QFileDevice::ExeUser);
    }
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("FINBOOK_FFMPEG"), script);
    QProcess process;
    process.setProcessEnvironment(env);
    process.start(kFinbook,
                  {QStringLiteral("export"), m_held, dir.filePath(QStringLiteral("a.mp4"))});
    QVERIFY(process.waitForStarted());
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(pidFile).size() > 0, 60000);
    QFile f(pidFile);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const qint64 background = f.readAll().trimmed().toLongLong();
    QVERIFY(background > 0);
    if (signal != 0)
        ::kill(pid_t(process.processId()), signal);
    QVERIFY(process.waitForFinished(60000));
    if (signal == 0)
        QCOMPARE(process.exitCode(), 0);
    QTRY_VERIFY_WITH_TIMEOUT(processEnded(background), 10000);
}

QTEST_GUILESS_MAIN(TestCliExport)
#include "tst_cli_export.moc"
