#include "bench.h"

#include <QApplication>
#include <QFile>
#include <QTextStream>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <map>
#include <vector>

namespace finbook::bench {
namespace {
struct Entry {
    const char *usage;
    BenchFunction fn;
};
std::map<std::string, Entry> &registry()
{
    static std::map<std::string, Entry> entries;
    return entries;
}
} // namespace

bool registerBench(const char *name, const char *usage, BenchFunction fn)
{
    registry()[name] = Entry{usage, std::move(fn)};
    return true;
}

long long peakResidentBytes()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return 0;
    const QList<QByteArray> lines = status.readAll().split('\n');
    for (const QByteArray &line : lines) {
        if (line.startsWith("VmHWM:")) {
            const QList<QByteArray> parts = line.simplified().split(' ');
            if (parts.size() >= 2)
                return parts[1].toLongLong() * 1024;
        }
    }
    return 0;
}

double threadCpuMs()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

double percentile(std::vector<double> samples, double p)
{
    if (samples.empty())
        return 0.0;
    std::sort(samples.begin(), samples.end());
    const double rank = p * double(samples.size() - 1);
    const auto lo = std::size_t(rank);
    const std::size_t hi = std::min(lo + 1, samples.size() - 1);
    return samples[lo] + (rank - double(lo)) * (samples[hi] - samples[lo]);
}

double median(std::vector<double> samples)
{
    return percentile(std::move(samples), 0.5);
}

} // namespace finbook::bench

int main(int argc, char **argv)
{
    // Widget benches (repaint, timeline) need a QApplication; the others do not mind one.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QStringList args = QCoreApplication::arguments().mid(1);
    auto &entries = finbook::bench::registry();
    if (args.isEmpty() || !entries.count(args.first().toStdString())) {
        std::fprintf(stderr, "usage: finbook-bench SUBCOMMAND [ARGS]\n");
        for (const auto &[name, entry] : entries)
            std::fprintf(stderr, "  %s %s\n", name.c_str(), entry.usage);
        return 2;
    }
    const std::string name = args.takeFirst().toStdString();
    return entries[name].fn(args);
}
