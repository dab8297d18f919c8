// Linked into every QtTest executable (tests/CMakeLists.txt). In sanitizer builds it makes the
// process wait at exit until QtTest's watchdog thread has gone.
//
// QtTest runs the test functions under a watchdog QThread ("QtTest Watchdog"). Its QThreadData
// is released twice: by the QThread's destructor, at the end of QTest::qExec(), and by the
// thread's own thread-specific-data destructor, which runs after QThread::wait() has already
// returned. When the process exits while the thread is still in that last step, LeakSanitizer's
// check at exit can find the QThreadData (152 bytes, allocated in QThread::QThread from
// QTest::qRun) unreferenced: CI failed deform/tst_arap that way, and it happened here about
// once in 240 runs with the machine loaded. Waiting for the thread closes that window without a
// suppression that would hide a real leak in QtCore's allocations.
//
// The handler is registered during the executable's static initialization, after QtCore's, so
// it runs before QtCore's destructors at exit.

#if defined(__SANITIZE_ADDRESS__)

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace {

bool watchdogAlive()
{
    // The error_code forms throw nothing: an exception would end the process in atexit.
    std::error_code error;
    for (std::filesystem::directory_iterator task("/proc/self/task", error), end;
         !error && task != end; task.increment(error)) {
        std::ifstream comm(task->path() / "comm");
        std::string name;
        if (std::getline(comm, name) && name == "QtTest Watchdog")
            return true;
    }
    return false;
}

void awaitWatchdog()
{
    // The thread has been told to end and joined by QThread::wait(); what remains takes
    // microseconds. The bound only keeps a broken assumption from hanging the test.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (watchdogAlive() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

[[maybe_unused]] const bool registered = std::atexit(awaitWatchdog) == 0;

} // namespace

#endif
