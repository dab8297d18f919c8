// Kill during save: a child process saves two versions of a document over and over onto one
// file (with its backup), and is killed with SIGKILL at random moments. After every kill the
// file is one of the two versions, byte for byte, and opens; so is the backup. This binary is
// also the child: `model_tst_kill_during_save --saver PATH`.
#include "tst_file_sample.h"

#include <QDir>
#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

using namespace finbook::model;
using namespace file_test;

namespace {
// Two versions of a few megabytes each, so a save takes long enough to be hit in the middle.
void version(Document &doc, int which)
{
    std::vector<Frame> frames;
    Id next = 1;
    for (int f = 0; f < 40 + which * 7; ++f) {
        Frame frame;
        frame.id = next++;
        StrokeGroup g;
        g.id = next++;
        g.name = QStringLiteral("v%1 f%2").arg(which).arg(f);
        for (int s = 0; s < 10; ++s) {
            auto data = std::make_shared<StrokeData>();
            for (int i = 0; i < 1000; ++i)
                data->points.push_back({float(i + which), float(s * f), 1.0f});
            g.strokes.push_back({next++, std::move(data)});
        }
        frame.groups.push_back(std::move(g));
        frames.push_back(std::move(frame));
    }
    doc.reset(std::move(frames), DocumentSettings(), next);
}

int runSaver(const char *path)
{
    Document a, b;
    version(a, 0);
    version(b, 1);
    const QString target = QString::fromLocal8Bit(path);
    for (long round = 0;; ++round) {
        if (saveFinbook(round % 2 ? b : a, target))
            return 3;
        if (round == 1) { // both versions are on disk once: ready to be killed
            const char ready = 'r';
            if (::write(1, &ready, 1) != 1)
                return 4;
        }
    }
}
} // namespace

class TestKillDuringSave : public QObject {
    Q_OBJECT
private slots:
    void killAtRandomMoments();
};

void TestKillDuringSave::killAtRandomMoments()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("target.finbook"));
    Document a, b;
    version(a, 0);
    version(b, 1);
    const QByteArray bytesA = serializeFinbook(a), bytesB = serializeFinbook(b);
    QVERIFY(bytesA != bytesB);
    QElapsedTimer clock;
    clock.start();
    QVERIFY(!saveFinbook(a, path));
    const double saveMs = double(clock.nsecsElapsed()) / 1e6;

    QRandomGenerator random(141414);
    const QByteArray self = QFile::encodeName(QCoreApplication::applicationFilePath());
    const QByteArray target = QFile::encodeName(path);
    const int kRuns = 120;
    int intact = 0, wasA = 0, wasB = 0;
    for (int run = 0; run < kRuns; ++run) {
        int fds[2];
        QVERIFY(::pipe(fds) == 0);
        const pid_t child = ::fork();
        QVERIFY(child >= 0);
        if (child == 0) {
            ::dup2(fds[1], 1);
            ::close(fds[0]);
            ::execl(self.constData(), self.constData(), "--saver", target.constData(), nullptr);
            ::_exit(127);
        }
        ::close(fds[1]);
        char ready = 0;
        QCOMPARE(::read(fds[0], &ready, 1), ssize_t(1)); // two saves done
        ::close(fds[0]);
        // Somewhere within the next two saves: writing, syncing, linking or renaming.
        ::usleep(useconds_t(random.bounded(std::max(2.0, 2.5 * saveMs)) * 1000.0));
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        QVERIFY2(WIFSIGNALED(status), "the saver stopped on its own");

        const QByteArray now = fileBytes(path);
        const QByteArray backup = fileBytes(finbookBackupPath(path));
        const bool isA = now == bytesA, isB = now == bytesB;
        QVERIFY2(isA || isB,
                 qPrintable(
                     QStringLiteral("run %1: %2 bytes, neither version").arg(run).arg(now.size())));
        QVERIFY2(backup == bytesA || backup == bytesB, qPrintable(QString::number(run)));
        QVERIFY(readFinbook(now));
        wasA += isA;
        wasB += isB;
        ++intact;
    }
    // Killed saves leave hidden temporary files (never the target); the next save removes them.
    const auto leftovers = [&] {
        return int(QDir(dir.path())
                       .entryList({QStringLiteral(".*.tmp")}, QDir::Files | QDir::Hidden)
                       .size());
    };
    qInfo("kill during save: %d runs, %d intact (%d A, %d B), one save %.0f ms, %d temporary "
          "files left by kills",
          kRuns, intact, wasA, wasB, saveMs, leftovers());
    QCOMPARE(intact, kRuns);
    QVERIFY(wasA > 0 && wasB > 0); // the kills did land at different points of the cycle
    QVERIFY(!saveFinbook(b, path));
    const QStringList left =
        QDir(dir.path()).entryList({QStringLiteral(".*.tmp")}, QDir::Files | QDir::Hidden);
    QVERIFY2(left.isEmpty(), qPrintable(left.join(QLatin1Char(' '))));
}

int main(int argc, char **argv)
{
    if (argc == 3 && qstrcmp(argv[1], "--saver") == 0)
        return runSaver(argv[2]);
    QCoreApplication app(argc, argv);
    TestKillDuringSave test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_kill_during_save.moc"
