// finbook-bench: subcommands register themselves; each prints one JSON object per line.
#pragma once

#include <QStringList>

#include <functional>
#include <string>

namespace finbook::bench {

using BenchFunction = std::function<int(const QStringList &args)>;

// Registers `name` (e.g. "io") with a one-line usage text. Returns true so it can
// initialise a static in the bench's own file.
bool registerBench(const char *name, const char *usage, BenchFunction fn);

// Peak resident set size of this process in bytes (VmHWM), 0 if unknown.
long long peakResidentBytes();

// CPU time of the calling thread in ms: unlike wall time it leaves out the time other processes
// of a busy machine take the core away (caches shared with them still slow it).
double threadCpuMs();

// Median of a list of samples (copies; fine for bench sizes).
double median(std::vector<double> samples);
double percentile(std::vector<double> samples, double p);

} // namespace finbook::bench

#define FINBOOK_BENCH(name, usage, fn)                                                             \
    static const bool finbook_bench_registered_##fn = finbook::bench::registerBench(name, usage, fn)
