// Timing helpers shared by the worst-case benchmarks (firtp_worst_tick, firtp_plan_stream).
//
// Two clocks per measured call: the wall clock (steady_clock) and this thread's CPU clock
// (CLOCK_THREAD_CPUTIME_ID). On a shared, non-real-time machine the wall clock's maxima include
// the scheduler giving the core to other jobs; the thread CPU clock does not count that time, so
// its maxima are the code's (plus cache and TLB misses after a preemption, which it does count).
#pragma once

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace firtp::bench {

inline std::int64_t thread_cpu_ns() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

inline std::int64_t wall_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// A field of /proc/self/status in KiB ("VmRSS", "VmHWM"); 0 where unavailable.
inline long proc_status_kib(const std::string& field) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind(field + ":", 0) == 0) return std::stol(line.substr(field.size() + 1));
    return 0;
}

// Peak resident set of this program so far, KiB: VmHWM, the high-water mark of this address
// space. Not getrusage's ru_maxrss: Linux carries that over exec from the parent (a Python
// or ctest parent's size would show up as ours); where /proc is missing, ru_maxrss it is.
inline long peak_rss_kib() {
    if (const long hwm = proc_status_kib("VmHWM"); hwm > 0) return hwm;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

// Current resident set (VmRSS), KiB.
inline long current_rss_kib() { return proc_status_kib("VmRSS"); }

// Durations in ns: counted in buckets of `bucket_ns` below `limit_ns` (quantiles are a bucket's
// lower edge), the rare longer ones kept as they are; mean and max are exact. Memory is fixed up
// front, so recording allocates only for outliers.
class Histogram {
public:
    explicit Histogram(std::int64_t bucket_ns = 1, std::int64_t limit_ns = 200'000)
        : bucket_(bucket_ns), counts_(static_cast<std::size_t>(limit_ns / bucket_ns), 0) {}

    void add(std::int64_t ns) {
        ns = std::max<std::int64_t>(ns, 0);
        ++n_;
        sum_ += static_cast<double>(ns);
        max_ = std::max(max_, ns);
        if (ns / bucket_ < static_cast<std::int64_t>(counts_.size()))
            ++counts_[static_cast<std::size_t>(ns / bucket_)];
        else
            outliers_.push_back(ns);
    }

    std::uint64_t count() const { return n_; }
    double mean() const { return n_ ? sum_ / static_cast<double>(n_) : 0.0; }
    std::int64_t max() const { return max_; }

    // Smallest value v with at least q of the samples <= v.
    std::int64_t quantile(double q) {
        if (n_ == 0) return 0;
        const auto rank = static_cast<std::uint64_t>(q * static_cast<double>(n_ - 1)) + 1;
        std::uint64_t seen = 0;
        for (std::size_t i = 0; i < counts_.size(); ++i) {
            seen += counts_[i];
            if (seen >= rank) return static_cast<std::int64_t>(i) * bucket_;
        }
        std::sort(outliers_.begin(), outliers_.end());
        return outliers_[static_cast<std::size_t>(rank - seen - 1)];
    }

    // {"mean":..,"p50":..,"p99":..,"p9999":..,"max":..} in ns.
    std::string json() {
        char text[256];
        std::snprintf(text, sizeof text,
                      "{\"count\":%llu,\"mean\":%.1f,\"p50\":%lld,\"p99\":%lld,\"p9999\":%lld,\"max\":%lld}",
                      static_cast<unsigned long long>(n_), mean(), static_cast<long long>(quantile(0.5)),
                      static_cast<long long>(quantile(0.99)), static_cast<long long>(quantile(0.9999)),
                      static_cast<long long>(max_));
        return text;
    }

private:
    std::int64_t bucket_;
    std::vector<std::uint64_t> counts_;
    std::vector<std::int64_t> outliers_;
    std::uint64_t n_ = 0;
    double sum_ = 0.0;
    std::int64_t max_ = 0;
};

}  // namespace firtp::bench
