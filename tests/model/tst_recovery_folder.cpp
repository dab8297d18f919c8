// What the recovery folder may hold (issue 25, item 3): a link named like a copy pointing at
// /dev/zero made every start read for ever, a 2 GiB sparse file cost seconds and gigabytes at
// every start. Copies are read by File → Open's rules (regular files only, bounded in size,
// refused unread) and listing reads only what describes them, so the list appears at once.
// Each listing runs in a child process with its memory capped and an alarm set: before the
// fix it ran out of memory or never came back.
#include "tst_file_sample.h"

#include <finbook/model/recovery/recovery_store.h>

#include <QDir>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace finbook::model;
using namespace file_test;

namespace {

// Under AddressSanitizer the process already maps terabytes of shadow memory, so an
// address-space cap would make its next allocation fail; the child then keeps only the alarm.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kCapAddressSpace = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kCapAddressSpace = false;
#else
constexpr bool kCapAddressSpace = true;
#endif
#else
constexpr bool kCapAddressSpace = true;
#endif
QByteArray copyBytes(const QString &title)
{
    Document doc;
    buildSample(doc);
    RecoveryInfo info;
    info.title = title;
    info.savedAt = QDateTime::currentDateTimeUtc();
    info.frames = doc.frameCount();
    return recoveryCopyBytes(doc.layers(), doc.settings(), info);
}

bool write(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// How many orphans a fresh session in `folder` lists, in a child process with at most 512 MiB
// of address space (not under ASan) and 30 s: -1 when it did not come back (crash, out of memory,
// alarm).
int orphansListed(const QString &folder, double *seconds = nullptr)
{
    QElapsedTimer clock;
    clock.start();
    const pid_t child = ::fork();
    if (child == 0) {
        const struct rlimit cap {
            rlim_t(512) << 20, rlim_t(512) << 20
        };
        if (kCapAddressSpace)
            ::setrlimit(RLIMIT_AS, &cap);
        ::alarm(30);
        RecoverySession session(folder);
        const auto copies = session.orphans();
        ::_exit(session.isValid() ? int(std::min<std::size_t>(copies.size(), 200)) : 255);
    }
    int status = 0;
    if (child < 0 || ::waitpid(child, &status, 0) != child)
        return -1;
    if (seconds)
        *seconds = double(clock.nsecsElapsed()) / 1e9;
    return WIFEXITED(status) && WEXITSTATUS(status) != 255 ? WEXITSTATUS(status) : -1;
}
} // namespace

class TestRecoveryFolder : public QObject {
    Q_OBJECT
private slots:
    void aRealCopyIsListed();
    void linksDevicesPipesAndFoldersAreNotRead();
    void aHugeSparseCopyIsListedWithoutReadingIt();
    void copiesBeyondTheSizeBoundAreRefusedUnread();
    void impostorsWithHugeSectionsAreNotRead();
    void thousandsOfCopiesListQuickly();
};

void TestRecoveryFolder::aRealCopyIsListed()
{
    QTemporaryDir dir;
    QVERIFY(write(dir.filePath(QStringLiteral("111-a-1.finbook")), copyBytes(QStringLiteral("x"))));
    QCOMPARE(orphansListed(dir.path()), 1);
    const auto copy = readRecoveryCopy(dir.filePath(QStringLiteral("111-a-1.finbook")));
    QVERIFY(copy);
    QCOMPARE(copy->info.title, QStringLiteral("x"));
    QVERIFY(!copy->thumbnail.isNull());
}

void TestRecoveryFolder::linksDevicesPipesAndFoldersAreNotRead()
{
    QTemporaryDir dir;
    const QByteArray real = QFile::encodeName(dir.filePath(QStringLiteral("real.bin")));
    QVERIFY(write(QString::fromLocal8Bit(real), copyBytes(QStringLiteral("linked"))));
    const auto name = [&](int n) {
        return QFile::encodeName(dir.filePath(QStringLiteral("222-b-%1.finbook").arg(n)));
    };
    QCOMPARE(::symlink("/dev/zero", name(1).constData()), 0);
    QCOMPARE(::symlink("/dev/urandom", name(2).constData()), 0);
    QCOMPARE(::mkfifo(name(3).constData(), 0600), 0);
    QCOMPARE(::mkdir(name(4).constData(), 0700), 0);
    QCOMPARE(::symlink(real.constData(), name(5).constData()), 0); // a copy is never a link
    double seconds = 0;
    QCOMPARE(orphansListed(dir.path(), &seconds), 0);
    qInfo("listed in %.3f s", seconds);
    for (int n = 1; n <= 5; ++n)
        QVERIFY(!readRecoveryCopy(QFile::decodeName(name(n))));
}

// A real copy followed by 2 GiB of (sparse) zeros: listed from its first few kilobytes.
void TestRecoveryFolder::aHugeSparseCopyIsListedWithoutReadingIt()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("333-c-1.finbook"));
    QVERIFY(write(path, copyBytes(QStringLiteral("sparse"))));
    QVERIFY(::truncate(QFile::encodeName(path).constData(), off_t(2) << 30) == 0);
    double seconds = 0;
    QCOMPARE(orphansListed(dir.path(), &seconds), 1);
    qInfo("a 2 GiB copy listed in %.3f s", seconds);
}

void TestRecoveryFolder::copiesBeyondTheSizeBoundAreRefusedUnread()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("444-d-1.finbook"));
    QVERIFY(write(path, copyBytes(QStringLiteral("huge"))));
    if (::truncate(QFile::encodeName(path).constData(), off_t(kMaxRecoveryCopyBytes) + 1) != 0)
        QSKIP("the file system cannot hold a sparse file that large");
    QCOMPARE(orphansListed(dir.path()), 0);
    QVERIFY(!readRecoveryCopy(path));
}

// A .finbook whose first section claims nearly 2 GiB, its description after that: found by
// seeking over the sections, not by reading them; one claiming more than the file is refused.
void TestRecoveryFolder::impostorsWithHugeSectionsAreNotRead()
{
    QTemporaryDir dir;
    const QByteArray copy = copyBytes(QStringLiteral("impostor"));
    QByteArray lying = copy;
    putU32(lying, 12 + 4, 0x7fff0000u); // the DOCU section's length, low word
    const QString path = dir.filePath(QStringLiteral("555-e-1.finbook"));
    QVERIFY(write(path, lying));
    QVERIFY(!readRecoveryCopy(path));
    QVERIFY(::truncate(QFile::encodeName(path).constData(), off_t(3) << 30) == 0);
    QCOMPARE(orphansListed(dir.path()), 0); // the description is not where the length says
}

// Hundreds of copies (and of sessions): the newest hundred are listed, quickly.
void TestRecoveryFolder::thousandsOfCopiesListQuickly()
{
    QTemporaryDir dir;
    const QByteArray copy = copyBytes(QStringLiteral("many"));
    for (int i = 0; i < 300; ++i)
        QVERIFY(write(dir.filePath(QStringLiteral("%1-s-1.finbook").arg(1000 + i)), copy));
    double seconds = 0;
    QCOMPARE(orphansListed(dir.path(), &seconds), 100);
    qInfo("300 copies: 100 listed in %.3f s", seconds);
}

QTEST_GUILESS_MAIN(TestRecoveryFolder)
#include "tst_recovery_folder.moc"
