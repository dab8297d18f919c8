// What an export does to what is already at its target: a sequence replaced as a whole or not
// at all, a target that appears meanwhile never silently replaced, one export at a time per
// target, and the temporaries of killed exports cleaned up by the next one.
#include "export_support.h"

#include <finbook/model/export/exporter.h>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace finbook;
using namespace finbook::test;
using model::ExportFormat;

namespace {

model::ExportOptions optionsFor(ExportFormat format, const QString &target)
{
    model::ExportOptions o;
    o.format = format;
    o.target = target;
    return o;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeAll(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// Every file of `folder` (hidden ones too) with its bytes.
QMap<QString, QByteArray> contents(const QString &folder)
{
    QMap<QString, QByteArray> files;
    for (const QString &name : filesIn(folder))
        files.insert(name, QFileInfo(QDir(folder).filePath(name)).isDir()
                               ? QByteArray("<dir>")
                               : readAll(QDir(folder).filePath(name)));
    return files;
}

// A folder holding an "old" export of 12 frames, each file saying which it is.
QString oldSequence(const QTemporaryDir &dir, const QString &name)
{
    const QString folder = dir.filePath(name);
    QDir().mkpath(folder);
    for (int i = 1; i <= 12; ++i)
        writeAll(
            QDir(folder).filePath(QStringLiteral("frame_%1.png").arg(i, 4, 10, QLatin1Char('0'))),
            "old " + QByteArray::number(i));
    return folder;
}

} // namespace

class TestExportTarget : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void folderInTheWayReplacesNothing();
    void failedSwapRestoresTheOldSequence();
    void targetAppearingMeanwhileIsKept_data();
    void targetAppearingMeanwhileIsKept();
    void oneExportAtATimePerTarget_data();
    void oneExportAtATimePerTarget();
    void leftoversOfKilledExportsAreRemoved();
    void othersFilesAreNotLeftovers();
    void rootFolderIsRefused();
    void nativeNameIsTheFinalName();

private:
    model::ExportSource m_source; // 12 drawings, 18 ticks
    model::ExportSource m_twelve; // the same without holds: 12 ticks
    QTemporaryDir m_dir;
};

void TestExportTarget::initTestCase()
{
    m_source = exampleWithHolds();
    QVERIFY2(m_source.frames.size() == 12, "the example has 12 frames");
    m_twelve = loadExample();
    QVERIFY(m_dir.isValid());
}

// Frame 5 of the old sequence is a folder: with overwrite, the export used to replace frames
// 1-4, fail at 5 and say "nothing was exported". Now it is refused before anything changes.
void TestExportTarget::folderInTheWayReplacesNothing()
{
    const QString folder = oldSequence(m_dir, QStringLiteral("blocked"));
    QFile::remove(QDir(folder).filePath(QStringLiteral("frame_0005.png")));
    QVERIFY(QDir(folder).mkdir(QStringLiteral("frame_0005.png")));
    const auto before = contents(folder);
    model::ExportOptions o = optionsFor(ExportFormat::PngSequence, folder);
    o.overwrite = true;
    const auto result = model::exportAnimation(m_twelve, o);
    QVERIFY(!result);
    QCOMPARE(result.error().code, model::ExportErrorCode::BadOptions);
    QVERIFY2(result.error().message.contains(QLatin1String("frame_0005.png")),
             qPrintable(result.error().message));
    QCOMPARE(contents(folder), before);
}

// The folder appears while the frames are written (after the check): moving the new frames
// into place fails at frame 5, and frames 1-4 go back to what they were.
void TestExportTarget::failedSwapRestoresTheOldSequence()
{
    const QString folder = oldSequence(m_dir, QStringLiteral("swap"));
    const auto before = contents(folder);
    model::ExportOptions o = optionsFor(ExportFormat::PngSequence, folder);
    o.overwrite = true;
    const auto result = model::exportAnimation(m_twelve, o, [&](qint64 done, qint64 total) {
        if (done == total) { // all written, not yet moved
            QFile::remove(QDir(folder).filePath(QStringLiteral("frame_0005.png")));
            QDir(folder).mkdir(QStringLiteral("frame_0005.png"));
        }
        return true;
    });
    QVERIFY(!result);
    QCOMPARE(result.error().code, model::ExportErrorCode::WriteFailed);
    auto expected = before;
    expected[QStringLiteral("frame_0005.png")] = "<dir>";
    QCOMPARE(contents(folder), expected);

    // Without the obstacle the whole sequence is replaced, and nothing else stays.
    QVERIFY(QDir(folder).rmdir(QStringLiteral("frame_0005.png")));
    QVERIFY(model::exportAnimation(m_twelve, o));
    const auto after = contents(folder);
    QCOMPARE(after.size(), 12);
    for (const QByteArray &bytes : after)
        QVERIFY(bytes.startsWith("\x89PNG"));
}

void TestExportTarget::targetAppearingMeanwhileIsKept_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<QString>("target");
    QTest::addColumn<QString>("appearing"); // relative to the target
    QTest::newRow("html") << int(ExportFormat::Html) << "page.html"
                          << "";
    QTest::newRow("png") << int(ExportFormat::PngSequence) << "frames"
                         << "frame_0003.png";
}

// Another program (or a Finbook without the lock) writes the target while this export runs.
// Without overwrite the export used to replace it and succeed; now it fails and keeps it.
void TestExportTarget::targetAppearingMeanwhileIsKept()
{
    QFETCH(int, format);
    QFETCH(QString, target);
    QFETCH(QString, appearing);
    const QString folder = m_dir.filePath(QStringLiteral("appear_") + QTest::currentDataTag());
    QVERIFY(QDir().mkpath(folder));
    const QString path = QDir(folder).filePath(target);
    const QString theirs = appearing.isEmpty() ? path : QDir(path).filePath(appearing);
    const auto result = model::exportAnimation(m_twelve, optionsFor(ExportFormat(format), path),
                                               [&](qint64 done, qint64 total) {
                                                   if (done == total)
                                                       writeAll(theirs, "theirs");
                                                   return true;
                                               });
    QVERIFY(!result);
    QCOMPARE(result.error().code, model::ExportErrorCode::TargetExists);
    QCOMPARE(readAll(theirs), QByteArray("theirs"));
    if (!appearing.isEmpty())
        QCOMPARE(filesIn(path), QStringList{appearing}); // none of the new frames stayed
    else
        QCOMPARE(filesIn(folder), QStringList{target});
}

void TestExportTarget::oneExportAtATimePerTarget_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<QString>("target");
    QTest::newRow("html") << int(ExportFormat::Html) << "page.html";
    QTest::newRow("png") << int(ExportFormat::PngSequence) << "frames";
    QTest::newRow("svg") << int(ExportFormat::SvgSequence) << "vectors";
}

// A second export to the same target while the first runs: it used to succeed and be
// replaced (or replace) silently. Now the second is refused and the first one's files stay.
void TestExportTarget::oneExportAtATimePerTarget()
{
    QFETCH(int, format);
    QFETCH(QString, target);
    const QString path = m_dir.filePath(QStringLiteral("busy_") + target);
    model::ExportOptions o = optionsFor(ExportFormat(format), path);
    o.overwrite = true;
    std::optional<model::ExportErrorCode> second;
    const auto first = model::exportAnimation(m_twelve, o, [&](qint64 done, qint64) {
        if (done == 2) {
            model::ExportOptions other = o;
            other.scale = 0.5;
            const auto result = model::exportAnimation(m_twelve, other);
            second = result ? std::optional<model::ExportErrorCode>() : result.error().code;
        }
        return true;
    });
    QVERIFY(first);
    QVERIFY(second.has_value());
    QCOMPARE(*second, model::ExportErrorCode::TargetBusy);
    // Once the first is done the target is free again.
    QVERIFY(model::exportAnimation(m_twelve, o));
    const QStringList files = exportsSequence(ExportFormat(format)) ? filesIn(path) : QStringList();
    QCOMPARE(files.size(), exportsSequence(ExportFormat(format)) ? 12 : 0);
}

// What kill -9 leaves: a ".NAME.XXXXXX.part" beside a file target, a ".finbook-export-XXXXXX"
// folder inside a sequence's folder, and the lock file. The next export removes them.
void TestExportTarget::leftoversOfKilledExportsAreRemoved()
{
    const QString folder = m_dir.filePath(QStringLiteral("killed"));
    QVERIFY(QDir().mkpath(folder + QStringLiteral("/frames/.finbook-export-Ab12Cd")));
    QVERIFY(
        writeAll(folder + QStringLiteral("/frames/.finbook-export-Ab12Cd/frame_0001.png"), "half"));
    QVERIFY(writeAll(folder + QStringLiteral("/.out.html.x1Y2z3.part"), "half"));
    // A lock whose process is gone: a pid that cannot be running.
    QVERIFY(writeAll(folder + QStringLiteral("/.out.html.export-lock"),
                     "2147483646\nfinbook\n" + QSysInfo::machineHostName().toUtf8() + "\n"));
    QVERIFY(model::exportAnimation(
        m_twelve, optionsFor(ExportFormat::Html, folder + QStringLiteral("/out.html"))));
    QVERIFY(model::exportAnimation(
        m_twelve, optionsFor(ExportFormat::PngSequence, folder + QStringLiteral("/frames"))));
    QCOMPARE(filesIn(folder), (QStringList{QStringLiteral("frames"), QStringLiteral("out.html")}));
    QCOMPARE(filesIn(folder + QStringLiteral("/frames")).size(), 12);
}

// Names that only look alike are other exports' or the user's files: left alone, whatever
// characters the target's name holds ("[" is no wildcard here).
void TestExportTarget::othersFilesAreNotLeftovers()
{
    const QString folder = m_dir.filePath(QStringLiteral("others"));
    QVERIFY(QDir().mkpath(folder));
    const QStringList kept{
        QStringLiteral(".a[1].html.Ab12Cd.partial"), QStringLiteral(".a[1].html.x.Ab12Cd.part"),
        QStringLiteral(".a1.html.Ab12Cd.part"), QStringLiteral(".finbook-export-Ab12Cd")};
    for (const QString &name : kept)
        QVERIFY(writeAll(QDir(folder).filePath(name), "keep"));
    QVERIFY(model::exportAnimation(
        m_twelve,
        optionsFor(ExportFormat::Html, QDir(folder).filePath(QStringLiteral("a[1].html")))));
    QStringList expected = kept;
    expected << QStringLiteral("a[1].html");
    expected.sort();
    QStringList now = filesIn(folder);
    now.sort();
    QCOMPARE(now, expected);
}

void TestExportTarget::rootFolderIsRefused()
{
    const auto result = model::exportAnimation(
        m_twelve, optionsFor(ExportFormat::PngSequence, QStringLiteral("/")));
    QVERIFY(!result);
    QCOMPARE(result.error().code, model::ExportErrorCode::BadOptions);
}

// A file whose name is not valid UTF-8 ("x\xff.html", given on the command line): target
// names it with U+FFFD, nativeName holds its bytes. The file is written, looked for and
// replaced under the bytes; the name with U+FFFD is never written.
void TestExportTarget::nativeNameIsTheFinalName()
{
    const QString folder = m_dir.filePath(QStringLiteral("native"));
    QVERIFY(QDir().mkpath(folder));
    const QByteArray bytes = QFile::encodeName(folder) + "/x\xff.html";
    const auto exists = [](const QByteArray &path) {
        struct stat status {};
        return ::stat(path.constData(), &status) == 0 && status.st_size > 0;
    };
    model::ExportOptions o =
        optionsFor(ExportFormat::Html, QDir(folder).filePath(QStringLiteral("x\uFFFD.html")));
    o.nativeName = "x\xff.html";
    o.scale = 0.25;
    auto result = model::exportAnimation(m_source, o);
    QVERIFY2(result, result ? "" : qPrintable(result.error().message));
    QVERIFY(exists(bytes));
    const auto entries = [&] {
        QList<QByteArray> names;
        if (DIR *dir = ::opendir(QFile::encodeName(folder).constData())) {
            while (const dirent *entry = ::readdir(dir))
                if (qstrcmp(entry->d_name, ".") != 0 && qstrcmp(entry->d_name, "..") != 0)
                    names << QByteArray(entry->d_name); // hidden ones too: no lock, no temporary
            ::closedir(dir);
        }
        return names;
    };
    QCOMPARE(entries(), QList<QByteArray>{"x\xff.html"});
    // There now: kept without overwrite, replaced with it.
    result = model::exportAnimation(m_source, o);
    QVERIFY(!result);
    QCOMPARE(result.error().code, model::ExportErrorCode::TargetExists);
    QCOMPARE(model::existingExportTargets(m_source, o), QStringList{o.target});
    ::truncate(bytes.constData(), 1);
    o.overwrite = true;
    result = model::exportAnimation(m_source, o);
    QVERIFY(result);
    struct stat status {};
    QVERIFY(::stat(bytes.constData(), &status) == 0 && status.st_size > 1000);
    QCOMPARE(entries(), QList<QByteArray>{"x\xff.html"});
    QVERIFY(::unlink(bytes.constData()) == 0);
}

QTEST_GUILESS_MAIN(TestExportTarget)
#include "tst_export_target.moc"
