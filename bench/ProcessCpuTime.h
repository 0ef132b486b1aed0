// CPU seconds (user + system) this process has used: the benchmarks compare CPU, not wall time,
// because the machines they run on are shared.
#pragma once

#include <sys/resource.h>

namespace lenslab::bench {

inline double processCpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    const auto s = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return s(u.ru_utime) + s(u.ru_stime);
}

}  // namespace lenslab::bench
