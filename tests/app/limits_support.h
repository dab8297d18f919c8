// Running the real `finbook` executable and measuring what it costs: peak resident memory and
// wall time of one child process (wait4 reports the child's own peak, nothing of ours).
#pragma once

#include <QByteArray>
#include <QElapsedTimer>
#include <QFile>
#include <QStringList>

#include <csignal>
#include <fcntl.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace limits_test {

// Under AddressSanitizer (preset "asan") memory figures mean little (shadow memory, the
// quarantine) and an address-space cap stops the process before main().
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kUnderAsan = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kUnderAsan = true;
#else
constexpr bool kUnderAsan = false;
#endif
#else
constexpr bool kUnderAsan = false;
#endif

struct Measured {
    int code = -1;       // exit code, -1 when it did not exit normally (crash, kill)
    long peakMiB = -1;   // ru_maxrss of the child
    double seconds = 0;  // wall time
    QByteArray out, err; // what it printed (at most a few pages are expected)
};

inline QByteArray readAllFrom(int fd)
{
    QByteArray bytes;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof(buffer))) > 0;)
        bytes.append(buffer, n);
    return bytes;
}

// Runs `finbook arguments...` with its output in temporary files (so a chatty child never
// blocks on a pipe) and returns its exit code, peak memory and time.
// `addressSpaceMiB` > 0 caps the child's address space (RLIMIT_AS) to provoke running out
// of memory. `signal` is sent after `signalAfterMs` (when > 0); SIGKILL after `killAfterMs`
// (when > 0), by default after 4 minutes: a child that hangs fails its check (exit -1) instead
// of holding the whole test until ctest's timeout, with nothing said.
inline Measured runMeasured(const QStringList &arguments, long addressSpaceMiB = 0,
                            int signalAfterMs = 0, int signal = SIGTERM, int killAfterMs = 240000)
{
    std::vector<QByteArray> args{QByteArray(FINBOOK_BINARY_DIR "/bin/finbook")};
    for (const QString &a : arguments)
        args.push_back(QFile::encodeName(a));
    std::vector<char *> argv;
    for (QByteArray &a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    char outName[] = "/tmp/finbook-limits-out-XXXXXX";
    char errName[] = "/tmp/finbook-limits-err-XXXXXX";
    const int outFd = ::mkstemp(outName), errFd = ::mkstemp(errName);
    ::unlink(outName);
    ::unlink(errName);
    Measured m;
    QElapsedTimer clock;
    clock.start();
    const pid_t child = ::fork();
    if (child == 0) {
        if (addressSpaceMiB > 0) {
            const rlim_t cap = rlim_t(addressSpaceMiB) << 20;
            const struct rlimit limit {
                cap, cap
            };
            ::setrlimit(RLIMIT_AS, &limit);
        }
        ::dup2(outFd, 1);
        ::dup2(errFd, 2);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    int status = 0;
    struct rusage usage {};
    // Sends `signal` once `signalAfterMs` have passed (0: never), and SIGKILL at `killAfterMs`
    // (0: never), so a run that would go on for ever still ends and counts as failed.
    bool signalled = false;
    pid_t done = 0;
    while (child > 0 && (signalAfterMs > 0 || killAfterMs > 0) &&
           (done = ::wait4(child, &status, WNOHANG, &usage)) == 0) {
        if (signalAfterMs > 0 && !signalled && clock.elapsed() >= signalAfterMs) {
            ::kill(child, signal);
            signalled = true;
        }
        if (killAfterMs > 0 && clock.elapsed() >= killAfterMs)
            ::kill(child, SIGKILL);
        ::usleep(20000);
    }
    if (child > 0 && (done == child || ::wait4(child, &status, 0, &usage) == child)) {
        m.seconds = double(clock.nsecsElapsed()) / 1e9;
        m.peakMiB = usage.ru_maxrss / 1024;
        m.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    ::lseek(outFd, 0, SEEK_SET);
    ::lseek(errFd, 0, SEEK_SET);
    m.out = readAllFrom(outFd);
    m.err = readAllFrom(errFd);
    ::close(outFd);
    ::close(errFd);
    return m;
}

// A tmpfs mounted on `dir` while it lives; only root may mount (mounted() says if it worked).
class TinyDisk {
public:
    TinyDisk(const QString &dir, const char *options)
        : m_dir(QFile::encodeName(dir))
    {
        if (::geteuid() == 0)
            m_mounted = ::mount("tmpfs", m_dir.constData(), "tmpfs", 0, options) == 0;
    }
    ~TinyDisk()
    {
        if (m_mounted)
            ::umount2(m_dir.constData(), MNT_DETACH);
    }
    TinyDisk(const TinyDisk &) = delete;
    TinyDisk &operator=(const TinyDisk &) = delete;
    bool mounted() const { return m_mounted; }

private:
    QByteArray m_dir;
    bool m_mounted = false;
};

} // namespace limits_test
