// Crash recovery with the real executable: Finbook edits a document (through its own menu
// actions), autosave writes a recovery copy, the process is killed with SIGKILL, and the next
// start restores the copy; the restored document must equal what was autosaved: every frame,
// object, rig and pose. Two running Finbooks never take each other's copies.
#include <finbook/model/finbook_file.h>
#include <finbook/model/recovery/recovery_store.h>

#include <QDir>
#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace finbook;

namespace {
const QString kBinary = QStringLiteral(FINBOOK_BINARY_DIR "/bin/finbook");
// Two frames of a caged and a boned object, both posed (the fuzzer's seed of the rigs).
const QString kRigs = QStringLiteral(FINBOOK_SOURCE_DIR "/tests/fuzz/seeds/cage_skeleton.finbook");

QProcessEnvironment environment(const QString &recovery, const QStringList &hooks)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("FINBOOK_RECOVERY_DIR"), recovery);
    env.insert(QStringLiteral("FINBOOK_AUTOSAVE_MS"), QStringLiteral("100"));
    for (const QString &hook : hooks)
        env.insert(hook.section(QLatin1Char('='), 0, 0), hook.section(QLatin1Char('='), 1));
    return env;
}

// Canonical bytes of the document in a file (ancillary sections left out).
QByteArray documentIn(const QString &path)
{
    auto loaded = model::loadFinbook(path);
    if (!loaded)
        return "unreadable: " + loaded.error().message.toUtf8();
    model::Document doc;
    model::adoptLoadedDocument(doc, std::move(*loaded));
    return model::serializeFinbook(doc);
}

QStringList copiesIn(const QString &folder)
{
    return QDir(folder).entryList({QStringLiteral("*.finbook")}, QDir::Files, QDir::Name);
}

// Waits until a copy in `folder` holds `frames` frames; returns its path.
QString waitForCopy(const QString &folder, int frames, int ms = 20000)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms) {
        for (const QString &name : copiesIn(folder))
            if (auto copy = model::readRecoveryCopy(QDir(folder).filePath(name));
                copy && copy->info.frames == frames)
                return copy->path;
        QTest::qWait(20);
    }
    return {};
}

struct Restart {
    int code = -1;
    QByteArray out, err;
    QByteArray dump;
    QList<QByteArray> state; // "clean" or "modified", then the window's file
};

// Starts Finbook again, lets it answer the recovery prompt with `answer`, dumps its document.
Restart restart(const QString &recovery, const QString &dumpPath, const QString &answer)
{
    QProcess p;
    p.setProcessEnvironment(
        environment(recovery, {QStringLiteral("FINBOOK_TEST_RECOVERY=") + answer,
                               QStringLiteral("FINBOOK_TEST_DUMP=") + dumpPath}));
    p.start(kBinary, {});
    Restart r;
    if (!p.waitForFinished(60000) || p.exitStatus() != QProcess::NormalExit)
        return r;
    r.code = p.exitCode();
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    QFile dump(dumpPath), state(dumpPath + QStringLiteral(".state"));
    if (dump.open(QIODevice::ReadOnly))
        r.dump = dump.readAll();
    if (state.open(QIODevice::ReadOnly))
        r.state = state.readAll().split('\n');
    return r;
}
} // namespace

class TestCrashRecovery : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void killedFinbookIsRecovered();
    void untitledDocumentIsRecovered();
    void runningFinbooksKeepTheirCopies();
};

void TestCrashRecovery::initTestCase()
{
    QVERIFY(QFile::exists(kBinary));
    QVERIFY(QFile::exists(kRigs));
}

void TestCrashRecovery::killedFinbookIsRecovered()
{
    QTemporaryDir dir;
    const QString recovery = dir.filePath(QStringLiteral("recovery"));
    const QString file = dir.filePath(QStringLiteral("rigs.finbook"));
    QVERIFY(QFile::copy(kRigs, file));
    const QByteArray onDisk = documentIn(file);

    QProcess editing;
    editing.setProcessEnvironment(
        environment(recovery, {QStringLiteral("FINBOOK_TEST_ACTIONS=frame.duplicate,"
                                              "frame.holdMore,object.new,frame.insertAfter")}));
    editing.start(kBinary, {file});
    QVERIFY(editing.waitForStarted());
    const QString copy = waitForCopy(recovery, 4); // 2 frames + a duplicate + an inserted one
    QVERIFY2(!copy.isEmpty(), editing.readAllStandardError().constData());
    const QByteArray autosaved = documentIn(copy);
    QVERIFY(autosaved != onDisk);
    editing.kill(); // SIGKILL: no clean-up of any kind
    QVERIFY(editing.waitForFinished());
    QCOMPARE(editing.exitStatus(), QProcess::CrashExit);
    QCOMPARE(documentIn(file), onDisk); // the file itself was never touched

    const Restart r =
        restart(recovery, dir.filePath(QStringLiteral("dump.finbook")), QStringLiteral("restore"));
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("recovery copies: 1"), r.out.constData());
    QVERIFY(!r.dump.isEmpty());
    auto restored = model::readFinbook(r.dump);
    QVERIFY(restored);
    model::Document d;
    model::adoptLoadedDocument(d, std::move(*restored));
    QCOMPARE(model::serializeFinbook(d), autosaved);
    QCOMPARE(r.state.value(0), QByteArray("modified")); // restored as unsaved work
    QCOMPARE(QString::fromUtf8(r.state.value(1)), QFileInfo(file).absoluteFilePath());
    // The copy was taken over by the second Finbook: the killed one's is gone.
    QVERIFY(!QFile::exists(copy));
    QCOMPARE(copiesIn(recovery).size(), 1);
}

void TestCrashRecovery::untitledDocumentIsRecovered()
{
    QTemporaryDir dir;
    const QString recovery = dir.filePath(QStringLiteral("recovery"));
    QProcess editing;
    editing.setProcessEnvironment(environment(
        recovery,
        {QStringLiteral("FINBOOK_TEST_ACTIONS=frame.insertAfter,object.new,frame.duplicate")}));
    editing.start(kBinary, {});
    QVERIFY(editing.waitForStarted());
    const QString copy = waitForCopy(recovery, 3);
    QVERIFY2(!copy.isEmpty(), editing.readAllStandardError().constData());
    const QByteArray autosaved = documentIn(copy);
    const auto described = model::readRecoveryCopy(copy);
    QVERIFY(described);
    QVERIFY(described->info.originalPath.isEmpty());
    QVERIFY(!described->thumbnail.isNull());
    editing.kill();
    QVERIFY(editing.waitForFinished());

    const Restart r =
        restart(recovery, dir.filePath(QStringLiteral("dump.finbook")), QStringLiteral("restore"));
    QCOMPARE(r.code, 0);
    auto restored = model::readFinbook(r.dump);
    QVERIFY(restored);
    model::Document d;
    model::adoptLoadedDocument(d, std::move(*restored));
    QCOMPARE(model::serializeFinbook(d), autosaved);
    QCOMPARE(r.state.value(0), QByteArray("modified"));
    QVERIFY(r.state.value(1).isEmpty()); // still untitled
}

void TestCrashRecovery::runningFinbooksKeepTheirCopies()
{
    QTemporaryDir dir;
    const QString recovery = dir.filePath(QStringLiteral("recovery"));
    QProcess first;
    first.setProcessEnvironment(
        environment(recovery, {QStringLiteral("FINBOOK_TEST_ACTIONS=frame.insertAfter")}));
    first.start(kBinary, {});
    QVERIFY(first.waitForStarted());
    const QString copy = waitForCopy(recovery, 2);
    QVERIFY(!copy.isEmpty());

    // A second Finbook starts while the first runs: it must not offer, take or delete the copy.
    const Restart second = restart(recovery, dir.filePath(QStringLiteral("second.finbook")),
                                   QStringLiteral("discard"));
    QCOMPARE(second.code, 0);
    QVERIFY2(!second.out.contains("recovery copies"), second.out.constData());
    QVERIFY(QFile::exists(copy));

    first.kill();
    QVERIFY(first.waitForFinished());
    const Restart third =
        restart(recovery, dir.filePath(QStringLiteral("third.finbook")), QStringLiteral("later"));
    QVERIFY2(third.out.contains("recovery copies: 1"), third.out.constData());
    QVERIFY(QFile::exists(copy)); // "later" keeps it
}

QTEST_GUILESS_MAIN(TestCrashRecovery)
#include "tst_crash_recovery.moc"
