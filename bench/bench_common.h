// The measuring tools the benchmarks share: CPU time, peak memory, medians.
#pragma once

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <functional>
#include <vector>

namespace meshdiff::timing {

//! CPU seconds of the process so far (all threads).
inline double cpu_seconds()
{
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

//! Peak resident memory of the process, in MiB (ru_maxrss is in KiB on Linux).
inline double peak_rss_mib()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024.0;
}

//! The median of \p v (the upper one of an even count), 0 when empty.
inline double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

//! The median wall time of \p runs calls of \p f, in seconds.
inline double median_seconds(int runs, const std::function<void()>& f)
{
    std::vector<double> t;
    for (int k = 0; k < runs; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return median(t);
}

}  // namespace meshdiff::timing
