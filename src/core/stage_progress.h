// A stage of the Progress of the calling thread (meshdiff/core/progress.h), shared
// by the threads of a parallel loop: tick() counts work with one atomic
// addition, calls Progress::advance() and asks cancelled() each time the count
// passes a multiple of 1/100 of the stage, and returns false once cancelled,
// so that the loop skips its remaining iterations (an exception must not leave
// an OpenMP region); finish(), after the region, throws Cancelled then.
// Without a Progress every call is one test of a null pointer.
#pragma once

#include "meshdiff/core/progress.h"
#include "meshdiff/error.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <string_view>

namespace meshdiff::detail {

class StageProgress
{
public:
    //! Starts stage \p name of \p total units (0: not known; then advance()
    //! is called every \p unknown_step units).
    StageProgress(std::string_view name, std::size_t total, std::size_t unknown_step = 4096,
                  Progress* progress = current_progress())
        : progress_(progress),
          total_(total),
          step_(total ? std::max<std::size_t>(1, total / 100) : std::max<std::size_t>(1, unknown_step))
    {
        if (progress_) {
            check_cancelled(progress_);
            progress_->stage(name, total);
        }
    }
    StageProgress(const StageProgress&) = delete;
    StageProgress& operator=(const StageProgress&) = delete;

    //! Counts \p n more units done; false once the run is cancelled. Thread-safe.
    bool tick(std::size_t n = 1)
    {
        if (!progress_) return true;
        if (stop_.load(std::memory_order_relaxed)) return false;
        const std::size_t before = done_.fetch_add(n, std::memory_order_relaxed);
        if ((before + n) / step_ != before / step_) {
            progress_->advance(total_ ? std::min(before + n, total_) : before + n);
            if (progress_->cancelled()) stop_.store(true, std::memory_order_relaxed);
        }
        return !stop_.load(std::memory_order_relaxed);
    }
    //! False once the run is cancelled (without counting). Thread-safe.
    bool running() const
    {
        if (!progress_) return true;
        if (stop_.load(std::memory_order_relaxed)) return false;
        return !progress_->cancelled();
    }
    //! Throws Cancelled if the run was cancelled (call outside parallel regions).
    void check() const
    {
        if (progress_ && (stop_.load(std::memory_order_relaxed) || progress_->cancelled())) throw Cancelled();
    }
    //! Ends the stage: throws Cancelled if the run was cancelled, else reports
    //! done == total (or the final count when the total is not known).
    void finish()
    {
        if (!progress_ || finished_) return;
        check();
        finished_ = true;
        progress_->advance(total_ ? total_ : done_.load(std::memory_order_relaxed));
    }

private:
    Progress* progress_;
    std::size_t total_;
    std::size_t step_;
    std::atomic<std::size_t> done_{0};
    std::atomic<bool> stop_{false};
    bool finished_ = false;
};

}  // namespace meshdiff::detail
