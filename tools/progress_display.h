//! \file progress_display.h
//! \brief The progress display of the CLI on stderr, and its Ctrl-C: a
//! meshdiff::Progress (meshdiff/core/progress.h) that shows one line per stage
//! ("curvature 45% 1.2 s": the share of the stage done and the time spent in
//! it) and is cancelled() once SIGINT or SIGTERM arrived (interrupt.h).
//! When stderr is a terminal the line is redrawn in place, from the moment the
//! run has taken 2 s (at once with --progress); with --progress and stderr not
//! a terminal (a log), plain lines at each tenth of a stage (each second when
//! the total is not known) and at its end; never with --quiet. A thread of its
//! own redraws the line 10 times a second, so the computation only stores a
//! count. Nothing goes to stdout.
#pragma once

#include "meshdiff/core/progress.h"

#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

namespace meshdiff::cli {

//! --progress and --quiet.
struct ProgressCliOptions
{
    bool progress = false;
    bool quiet = false;
};
void add_progress_options(CLI::App* sub, ProgressCliOptions& o);

//! How the display shows itself.
enum class ProgressMode
{
    Off,       //!< nothing (--quiet, or stderr is not a terminal)
    Terminal,  //!< one line per stage redrawn with '\r', once the run has taken \p delay
    Lines      //!< plain lines (--progress with stderr not a terminal)
};

//! The mode for the options and whether stderr is a terminal.
ProgressMode progress_mode(const ProgressCliOptions& o, bool stderr_is_terminal);

class ProgressDisplay final : public Progress
{
public:
    //! \p out is stderr but for tests; \p delay: how long a Terminal display
    //! waits before it shows (2 s, 0 with --progress).
    ProgressDisplay(ProgressMode mode, std::chrono::milliseconds delay, std::FILE* out = stderr);
    //! The display for the options (progress_mode() of isatty(2)).
    explicit ProgressDisplay(const ProgressCliOptions& o);
    ~ProgressDisplay() override;

    void stage(std::string_view name, std::size_t total) override;
    void advance(std::size_t done) override;
    bool cancelled() const override;

    //! Ends the display: the last stage's line is completed (or, after a
    //! failure, ended as it stands). Called before the report is printed.
    void finish(bool completed = true);

private:
    using Clock = std::chrono::steady_clock;
    void run();
    // The line of the current stage, e.g. "curvature  45%  1.2 s".
    std::string line(std::size_t done, Clock::time_point now) const;
    // Draws the current stage (mutex held); \p final ends its line.
    void draw(Clock::time_point now, bool final);

    ProgressMode mode_;
    std::chrono::milliseconds delay_;
    std::FILE* out_;
    Clock::time_point start_ = Clock::now();
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    bool finished_ = false;
    std::string name_;  // the current stage; empty before the first
    std::size_t total_ = 0;
    Clock::time_point stage_start_ = start_;
    std::atomic<std::size_t> done_{0};
    bool shown_ = false;             // the current stage's line is on screen (Terminal)
    std::size_t printed_tenth_ = 0;  // Lines: the last tenth printed, + 1 (0: none)
    Clock::time_point printed_at_ = start_;
    std::thread thread_;
};

}  // namespace meshdiff::cli
