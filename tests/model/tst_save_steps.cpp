// Every step of a save failing or killed (issue 25, item 7), through the test seam around the
// system calls (io/atomic_file_faults.h): the file is the old one or the new one, complete,
// and the backup "NAME~" is the old backup until the new file is in place. A save used to
// replace the backup with the current file before renaming the new file over it, so a rename
// failing (EIO, ENOSPC, EROFS) or a kill right there lost the older backup. Also names with
// wildcard characters (item 11): the leftovers of killed saves are still cleaned, silently.
#include "tst_file_sample.h"

#include <finbook/model/io/atomic_file_faults.h>

#include <QDir>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <cerrno>
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

using namespace finbook::model;
using namespace file_test;

namespace {
QStringList entries(const QString &dir)
{
    return QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::System, QDir::Name);
}

// The file saved three times, holding versions 1, 2 (saved) and 3 (being saved).
struct Versions {
    QByteArray first, second;
};

Versions saveTwice(Document &doc, const QString &path)
{
    Versions v;
    buildSample(doc);
    if (saveFinbook(doc, path))
        return {};
    v.first = fileBytes(path);
    doc.setFrameHold(doc.frameAt(0).id, 7);
    if (saveFinbook(doc, path))
        return {};
    v.second = fileBytes(path);
    doc.setFrameHold(doc.frameAt(0).id, 9);
    if (v.first == v.second)
        return {}; // three different versions, or nothing is shown
    return v;
}

class HookGuard {
public:
    explicit HookGuard(AtomicFaultHook hook)
        : m_previous(setAtomicFaultHook(std::move(hook)))
    {}
    ~HookGuard() { setAtomicFaultHook(m_previous); }

private:
    AtomicFaultHook m_previous;
};

const AtomicStep kSteps[] = {AtomicStep::CreateTemporary, AtomicStep::SyncTemporary,
                             AtomicStep::CloseTemporary,  AtomicStep::LinkBackup,
                             AtomicStep::CopyBackup,      AtomicStep::ReplaceTarget,
                             AtomicStep::ReplaceBackup,   AtomicStep::RestoreTarget};
const char *const kStepNames[] = {"create", "sync",         "close",          "link",
                                  "copy",   "replace file", "replace backup", "restore file"};
} // namespace

class TestSaveSteps : public QObject {
    Q_OBJECT
private slots:
    void failureAtEveryStepKeepsFileAndBackup_data();
    void failureAtEveryStepKeepsFileAndBackup();
    void backupThatCannotBeReplacedNorUndoneKeepsTheOldBackup();
    void killAtEveryStepKeepsTheOldBackup_data();
    void killAtEveryStepKeepsTheOldBackup();
    void namesWithWildcardsCleanTheirLeftovers_data();
    void namesWithWildcardsCleanTheirLeftovers();
};

void TestSaveSteps::failureAtEveryStepKeepsFileAndBackup_data()
{
    QTest::addColumn<int>("step");
    QTest::addColumn<int>("error");
    QTest::addColumn<bool>("noLinks"); // links fail with EXDEV first: the backup is a copy
    for (std::size_t s = 0; s < std::size(kSteps); ++s) {
        if (kSteps[s] == AtomicStep::RestoreTarget)
            continue; // reached only when replacing the backup failed (the next test)
        for (const auto &[error, name] :
             {std::pair{EIO, "EIO"}, std::pair{ENOSPC, "ENOSPC"}, std::pair{EROFS, "EROFS"}})
            for (const bool noLinks : {false, true})
                if (!noLinks || kSteps[s] != AtomicStep::LinkBackup)
                    QTest::addRow("%s %s%s", kStepNames[s], name, noLinks ? " (no links)" : "")
                        << int(kSteps[s]) << error << noLinks;
    }
}

void TestSaveSteps::failureAtEveryStepKeepsFileAndBackup()
{
    QFETCH(int, step);
    QFETCH(int, error);
    QFETCH(bool, noLinks);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.finbook"));
    Document doc;
    const Versions v = saveTwice(doc, path);
    QVERIFY(!v.second.isEmpty());
    QCOMPARE(fileBytes(finbookBackupPath(path)), v.first);
    bool failed = false;
    {
        HookGuard guard([&](AtomicStep s) {
            if (noLinks && s == AtomicStep::LinkBackup)
                return EXDEV;
            if (!failed && s == AtomicStep(step)) {
                failed = true;
                return error;
            }
            return 0;
        });
        const auto result = saveFinbook(doc, path);
        if (!failed) {
            // The step never came (no copy when links work): the save went through.
            QVERIFY(AtomicStep(step) == AtomicStep::CopyBackup && !noLinks);
            QVERIFY(!result);
            return;
        }
        QVERIFY2(result, "a failed step reported success");
        QVERIFY2(result->message.contains(QLatin1String("unchanged")), qPrintable(result->message));
    }
    QCOMPARE(fileBytes(path), v.second);
    QCOMPARE(fileBytes(finbookBackupPath(path)), v.first);
    QCOMPARE(entries(dir.path()),
             QStringList({QStringLiteral("a.finbook"), QStringLiteral("a.finbook~")}));
    // And the next save works and rotates the backup.
    QVERIFY(!saveFinbook(doc, path));
    QCOMPARE(fileBytes(finbookBackupPath(path)), v.second);
}

// Replacing the backup fails and so does putting the old file back: the new file is complete
// and stays, the old backup too (the file it replaced is left under its temporary name).
void TestSaveSteps::backupThatCannotBeReplacedNorUndoneKeepsTheOldBackup()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.finbook"));
    Document doc;
    const Versions v = saveTwice(doc, path);
    QVERIFY(!v.second.isEmpty());
    HookGuard guard([](AtomicStep s) {
        return s == AtomicStep::ReplaceBackup || s == AtomicStep::RestoreTarget ? EIO : 0;
    });
    QVERIFY(!saveFinbook(doc, path));
    QVERIFY(fileBytes(path) != v.second);
    QVERIFY(readFinbook(fileBytes(path)));
    QCOMPARE(fileBytes(finbookBackupPath(path)), v.first);
    bool keptSecond = false;
    for (const QString &name : entries(dir.path()))
        keptSecond = keptSecond || fileBytes(dir.filePath(name)) == v.second;
    QVERIFY(keptSecond);
}

void TestSaveSteps::killAtEveryStepKeepsTheOldBackup_data()
{
    QTest::addColumn<int>("step");
    for (std::size_t s = 0; s < std::size(kSteps); ++s)
        if (kSteps[s] != AtomicStep::RestoreTarget && kSteps[s] != AtomicStep::CopyBackup)
            QTest::newRow(kStepNames[s]) << int(kSteps[s]);
}

// A child process saves and is killed (SIGKILL) right before `step`: the file is the old or
// the new one, the backup the old backup or, once the file is new, the file it replaced.
void TestSaveSteps::killAtEveryStepKeepsTheOldBackup()
{
    QFETCH(int, step);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.finbook"));
    Document doc;
    const Versions v = saveTwice(doc, path);
    QVERIFY(!v.second.isEmpty());
    const pid_t child = ::fork();
    if (child == 0) {
        setAtomicFaultHook([step](AtomicStep s) {
            if (s == AtomicStep(step))
                ::raise(SIGKILL);
            return 0;
        });
        saveFinbook(doc, path);
        ::_exit(0);
    }
    QVERIFY(child > 0);
    int status = 0;
    QCOMPARE(::waitpid(child, &status, 0), child);
    QVERIFY2(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL, "the step was never reached");
    const QByteArray now = fileBytes(path), backup = fileBytes(finbookBackupPath(path));
    QVERIFY(readFinbook(now));
    if (now == v.second) {
        QVERIFY2(backup == v.first, "the old backup was lost while the file is still the old one");
    } else {
        QVERIFY(backup == v.first || backup == v.second);
    }
    // The next save cleans what the killed one left and keeps the file it replaces.
    const QByteArray before = fileBytes(path);
    QVERIFY(!saveFinbook(doc, path));
    QCOMPARE(fileBytes(finbookBackupPath(path)), before);
    QCOMPARE(entries(dir.path()),
             QStringList({QStringLiteral("a.finbook"), QStringLiteral("a.finbook~")}));
}

void TestSaveSteps::namesWithWildcardsCleanTheirLeftovers_data()
{
    QTest::addColumn<QString>("name");
    for (const char *name : {"a[1].finbook", "a[.finbook", "a*.finbook", "a?.finbook",
                             "a{b,c}.finbook", "a\\.finbook", "a(b)+.finbook", "a]b[.finbook"})
        QTest::newRow(name) << QString::fromLatin1(name);
}

// The name of the document was a wildcard pattern: "[" made no pattern at all (ten
// QRegularExpression warnings a save, and leftovers never removed), "*" matched others' files.
void TestSaveSteps::namesWithWildcardsCleanTheirLeftovers()
{
    QFETCH(QString, name);
    QTest::failOnWarning(QRegularExpression(QStringLiteral(".*")));
    QTemporaryDir dir;
    const QString path = dir.filePath(name);
    const pid_t gone = ::fork();
    if (gone == 0)
        ::_exit(0);
    QVERIFY(gone > 0);
    ::waitpid(gone, nullptr, 0);
    const QString leftover = dir.filePath(QStringLiteral(".%1.%2-k1.tmp").arg(name).arg(gone));
    const QString backupLeftover =
        dir.filePath(QStringLiteral(".%1~.%2-k2.tmp").arg(name).arg(gone));
    // Another document's leftover that a wildcard in the name would match.
    const QString other = dir.filePath(QStringLiteral(".aXY.finbook.%1-k3.tmp").arg(gone));
    for (const QString &file : {leftover, backupLeftover, other}) {
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
    }
    Document doc;
    buildSample(doc);
    QVERIFY(!saveFinbook(doc, path));
    doc.setFrameHold(doc.frameAt(0).id, 2);
    QVERIFY(!saveFinbook(doc, path));
    QVERIFY(!QFile::exists(leftover));
    QVERIFY(!QFile::exists(backupLeftover));
    QVERIFY(QFile::exists(other));
    QCOMPARE(entries(dir.path()),
             QStringList({other.mid(dir.path().size() + 1), name, name + QLatin1Char('~')}));
}

QTEST_GUILESS_MAIN(TestSaveSteps)
#include "tst_save_steps.moc"
