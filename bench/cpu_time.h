// CPU time of the whole process (every thread, user + system), for benchmarks on a shared
// machine: next to a wall time it shows how much of it was spent waiting for a core.
// Spinning TBB workers count as busy.
#pragma once

#include <sys/resource.h>

namespace opal::bench {

inline double processCpuMilliseconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto ms = [](const timeval& t) { return 1e3 * double(t.tv_sec) + 1e-3 * double(t.tv_usec); };
    return ms(usage.ru_utime) + ms(usage.ru_stime);
}

}  // namespace opal::bench
