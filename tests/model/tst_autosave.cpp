// Autosave and recovery copies: written after the interval and after a burst of edits, off
// the GUI thread and atomically; removed when the document is saved, replaced or closed;
// found again after the process died; never taken from a Finbook that is still running.
#include "tst_file_sample.h"

#include <finbook/model/commands.h>
#include <finbook/model/recovery/autosaver.h>

#include <QSignalSpy>
#include <QTemporaryDir>

#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace finbook::model;
using namespace file_test;

namespace {
// The document a copy holds, as today's canonical bytes (its ancillary sections left out).
QByteArray documentIn(const QString &copy)
{
    auto loaded = loadFinbook(copy);
    if (!loaded)
        return QByteArray("unreadable: ") + loaded.error().message.toUtf8();
    Document d;
    adoptLoadedDocument(d, std::move(*loaded));
    return serializeFinbook(d);
}

void hold(Document &doc, int frame, int value)
{
    doc.undoStack()->push(new SetFrameHoldCommand(&doc, doc.frameAt(frame).id, value));
}
} // namespace

class TestAutosave : public QObject {
    Q_OBJECT
private slots:
    void copyAfterTheInterval();
    void copyAfterABurstOfEdits();
    void nothingToCopyWhenClean();
    void savingOrReplacingRemovesTheCopy();
    void endedSessionsCopiesAreOrphans();
    void killedProcessCopiesAreOrphans();
    void runningSessionsCopiesAreNotOrphans();
    void adoptedOrphanBelongsToTheDocument();
    void everyCopyIsWhole();
    void fullDiskIsReported();
};

void TestAutosave::copyAfterTheInterval()
{
    QTemporaryDir dir;
    RecoverySession session(dir.path());
    QVERIFY(session.isValid());
    Document doc;
    buildSample(doc);
    Autosaver autosaver(&doc, &session);
    autosaver.setInterval(30);
    autosaver.setDocumentInfo(QStringLiteral("sample.finbook"),
                              QStringLiteral("/x/sample.finbook"));
    QSignalSpy written(&autosaver, &Autosaver::copyWritten);
    hold(doc, 0, 9);
    QVERIFY(written.wait(5000));
    QCOMPARE(written.first().first().toString(), autosaver.copyPath());
    QCOMPARE(documentIn(autosaver.copyPath()), serializeFinbook(doc));
    const auto copy = readRecoveryCopy(autosaver.copyPath());
    QVERIFY(copy);
    QCOMPARE(copy->info.title, QStringLiteral("sample.finbook"));
    QCOMPARE(copy->info.originalPath, QStringLiteral("/x/sample.finbook"));
    QCOMPARE(copy->info.frames, 3);
    QVERIFY(qAbs(copy->info.savedAt.secsTo(QDateTime::currentDateTimeUtc())) < 60);
    QVERIFY(!copy->thumbnail.isNull());
    QCOMPARE(copy->thumbnail.width(), 160);
}

void TestAutosave::copyAfterABurstOfEdits()
{
    QTemporaryDir dir;
    RecoverySession session(dir.path());
    Document doc;
    buildSample(doc);
    Autosaver autosaver(&doc, &session);
    autosaver.setInterval(3600 * 1000);
    autosaver.setBurst(5, 20);
    QSignalSpy written(&autosaver, &Autosaver::copyWritten);
    for (int i = 0; i < 4; ++i)
        hold(doc, 0, 2 + i);
    QVERIFY(!written.wait(300)); // four edits: no burst yet
    hold(doc, 1, 7);
    QVERIFY(written.wait(5000));
    QCOMPARE(documentIn(autosaver.copyPath()), serializeFinbook(doc));
}

void TestAutosave::nothingToCopyWhenClean()
{
    QTemporaryDir dir;
    RecoverySession session(dir.path());
    Document doc;
    buildSample(doc);
    Autosaver autosaver(&doc, &session);
    autosaver.setInterval(10);
    QTest::qWait(100);
    autosaver.autosaveNow();
    autosaver.waitForIdle();
    QVERIFY(!QFile::exists(autosaver.copyPath()));
    hold(doc, 0, 4);
    doc.undoStack()->undo(); // back to the state on disk
    autosaver.autosaveNow();
    autosaver.waitForIdle();
    QVERIFY(!QFile::exists(autosaver.copyPath()));
}

void TestAutosave::savingOrReplacingRemovesTheCopy()
{
    QTemporaryDir dir;
    RecoverySession session(dir.path());
    Document doc;
    buildSample(doc);
    Autosaver autosaver(&doc, &session);
    hold(doc, 0, 4);
    autosaver.autosaveNow();
    autosaver.waitForIdle();
    QVERIFY(QFile::exists(autosaver.copyPath()));
    doc.undoStack()->setClean(); // what a save does
    autosaver.waitForIdle();
    QVERIFY(!QFile::exists(autosaver.copyPath()));

    hold(doc, 0, 5);
    autosaver.autosaveNow();
    autosaver.waitForIdle();
    QVERIFY(QFile::exists(autosaver.copyPath()));
    Document other;
    buildSample(other);
    doc.reset(other.frames(), other.settings(), other.nextId()); // New or Open
    autosaver.waitForIdle();
    QVERIFY(!QFile::exists(autosaver.copyPath()));

    hold(doc, 0, 6);
    autosaver.autosaveNow();
    autosaver.discard(); // the window closed without saving
    autosaver.waitForIdle();
    QVERIFY(!QFile::exists(autosaver.copyPath()));
    QCOMPARE(QDir(dir.path()).entryList({QStringLiteral("*.finbook")}, QDir::Files).size(), 0);
}

void TestAutosave::endedSessionsCopiesAreOrphans()
{
    QTemporaryDir dir;
    Document doc;
    buildSample(doc);
    QString copyPath;
    {
        RecoverySession ended(dir.path());
        Autosaver autosaver(&doc, &ended);
        autosaver.setDocumentInfo(QStringLiteral("Untitled"), QString());
        hold(doc, 0, 8);
        autosaver.autosaveNow();
        autosaver.waitForIdle();
        copyPath = autosaver.copyPath();
    } // quit with unsaved changes: the copy stays
    RecoverySession next(dir.path());
    const std::vector<RecoveryCopy> orphans = next.orphans();
    QCOMPARE(orphans.size(), std::size_t(1));
    QCOMPARE(orphans[0].path, copyPath);
    QCOMPARE(orphans[0].info.title, QStringLiteral("Untitled"));
    QCOMPARE(documentIn(orphans[0].path), serializeFinbook(doc));
    QVERIFY(next.discard(orphans[0]));
    QVERIFY(next.orphans().empty());
}

// A process that dies without any cleanup (SIGKILL) leaves its lock behind; the pid in it is
// dead, so its copies are orphans.
void TestAutosave::killedProcessCopiesAreOrphans()
{
    QTemporaryDir dir;
    Document doc;
    buildSample(doc);
    hold(doc, 0, 3);
    const QByteArray bytes = recoveryCopyBytes(
        doc.layers(), doc.settings(),
        {QStringLiteral("killed.finbook"), QString(), QDateTime::currentDateTimeUtc(), 3});
    int fds[2];
    QVERIFY(::pipe(fds) == 0);
    const pid_t child = ::fork();
    QVERIFY(child >= 0);
    if (child == 0) {
        auto *session = new RecoverySession(dir.path()); // never destroyed: as if killed
        QFile copy(session->copyPath(1));
        const bool ok = session->isValid() && copy.open(QIODevice::WriteOnly) &&
                        copy.write(bytes) == bytes.size();
        copy.close();
        (void)::write(fds[1], ok ? "1" : "0", 1);
        ::pause(); // wait for the kill
        ::_exit(0);
    }
    ::close(fds[1]);
    char ok = 0;
    QCOMPARE(::read(fds[0], &ok, 1), ssize_t(1));
    ::close(fds[0]);
    QCOMPARE(ok, '1');
    RecoverySession observer(dir.path());
    QVERIFY(observer.orphans().empty()); // alive: not ours to take
    ::kill(child, SIGKILL);
    ::waitpid(child, nullptr, 0);
    const std::vector<RecoveryCopy> orphans = observer.orphans();
    QCOMPARE(orphans.size(), std::size_t(1));
    QCOMPARE(orphans[0].info.title, QStringLiteral("killed.finbook"));
}

void TestAutosave::runningSessionsCopiesAreNotOrphans()
{
    QTemporaryDir dir;
    RecoverySession first(dir.path()), second(dir.path());
    QVERIFY(first.isValid() && second.isValid());
    QVERIFY(first.id() != second.id());
    Document a, b;
    buildSample(a);
    buildSample(b);
    Autosaver autoA(&a, &first), autoB(&b, &second);
    hold(a, 0, 3);
    hold(b, 1, 4);
    autoA.autosaveNow();
    autoB.autosaveNow();
    autoA.waitForIdle();
    autoB.waitForIdle();
    QVERIFY(autoA.copyPath() != autoB.copyPath());
    QVERIFY(first.orphans().empty());
    QVERIFY(second.orphans().empty());
    // Even after a long time: QLockFile's own default would call a 30-second-old lock stale.
    QFile lock(dir.filePath(first.id() + QStringLiteral(".lock")));
    QVERIFY(lock.open(QIODevice::ReadWrite));
    QVERIFY(lock.setFileTime(QDateTime::currentDateTime().addDays(-2),
                             QFileDevice::FileModificationTime));
    lock.close();
    QVERIFY(second.orphans().empty());
    QVERIFY(QFile::exists(autoA.copyPath()) && QFile::exists(autoB.copyPath()));
}

void TestAutosave::adoptedOrphanBelongsToTheDocument()
{
    QTemporaryDir dir;
    Document doc;
    buildSample(doc);
    {
        RecoverySession ended(dir.path());
        Autosaver autosaver(&doc, &ended);
        hold(doc, 0, 8);
        autosaver.autosaveNow();
    }
    RecoverySession next(dir.path());
    const std::vector<RecoveryCopy> orphans = next.orphans();
    QCOMPARE(orphans.size(), std::size_t(1));
    Document restored;
    auto loaded = loadFinbook(orphans[0].path);
    QVERIFY(loaded);
    adoptLoadedDocument(restored, std::move(*loaded));
    Autosaver autosaver(&restored, &next);
    restored.undoStack()->resetClean();
    autosaver.adopt(orphans[0].path);
    autosaver.waitForIdle();
    QVERIFY(!QFile::exists(orphans[0].path));
    QCOMPARE(documentIn(autosaver.copyPath()), serializeFinbook(doc));
    QVERIFY(next.orphans().empty());
    restored.undoStack()->setClean(); // saved: the adopted copy goes
    autosaver.waitForIdle();
    QVERIFY(!QFile::exists(autosaver.copyPath()));
}

// Copies taken while edits keep coming: each one on disk is whole and opens.
void TestAutosave::everyCopyIsWhole()
{
    QTemporaryDir dir;
    RecoverySession session(dir.path());
    Document doc;
    buildSample(doc);
    Autosaver autosaver(&doc, &session);
    autosaver.setInterval(1);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
        hold(doc, i % 3, 1 + i % 50);
        QTest::qWait(1);
        if (QFile::exists(autosaver.copyPath()) && i % 5 == 0) {
            auto loaded = loadFinbook(autosaver.copyPath());
            QVERIFY2(loaded, loaded ? "" : qPrintable(loaded.error().message));
            ++checked;
        }
    }
    autosaver.autosaveNow();
    autosaver.waitForIdle();
    QCOMPARE(documentIn(autosaver.copyPath()), serializeFinbook(doc));
    QVERIFY(checked > 0);
}

void TestAutosave::fullDiskIsReported()
{
    QTemporaryDir dir;
    if (::geteuid() != 0 ||
        ::mount("tmpfs", QFile::encodeName(dir.path()).constData(), "tmpfs", 0, "size=64k") != 0)
        QSKIP("needs root to mount a tmpfs");
    {
        RecoverySession session(dir.path()); // its lock is made while there is room
        QFile filler(dir.filePath(QStringLiteral("filler")));
        QVERIFY(filler.open(QIODevice::WriteOnly | QIODevice::Unbuffered));
        const QByteArray block(4096, 'x');
        while (filler.write(block) == block.size()) {
        }
        QVERIFY(session.isValid());
        Document doc;
        buildSample(doc);
        Autosaver autosaver(&doc, &session);
        QSignalSpy failed(&autosaver, &Autosaver::copyFailed);
        hold(doc, 0, 5);
        autosaver.autosaveNow();
        autosaver.waitForIdle();
        QCOMPARE(failed.size(), 1);
        QVERIFY2(failed.first().first().toString().contains(QLatin1String("the disk is full")),
                 qPrintable(failed.first().first().toString()));
        QVERIFY(!QFile::exists(autosaver.copyPath()));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 2); // lock, filler
    }
    ::umount2(QFile::encodeName(dir.path()).constData(), MNT_DETACH);
}

QTEST_GUILESS_MAIN(TestAutosave)
#include "tst_autosave.moc"
