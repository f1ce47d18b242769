#include "progress_display.h"

#include "interrupt.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>

namespace meshdiff::cli {

namespace {
// How long a run must take before the terminal display shows itself.
constexpr std::chrono::milliseconds kTerminalDelay{2000};
// How often the display thread redraws.
constexpr std::chrono::milliseconds kRedraw{100};
}  // namespace

void add_progress_options(CLI::App* sub, ProgressCliOptions& o)
{
    auto* progress = sub->add_flag("--progress", o.progress,
                                   "show the progress of each stage on stderr from the start, also when stderr is "
                                   "not a terminal (then as plain lines, for logs); by default it shows only on a "
                                   "terminal and once the run has taken 2 s");
    sub->add_flag("-q,--quiet", o.quiet, "no progress display")->excludes(progress);
}

ProgressMode progress_mode(const ProgressCliOptions& o, bool stderr_is_terminal)
{
    if (o.quiet) return ProgressMode::Off;
    if (stderr_is_terminal) return ProgressMode::Terminal;
    return o.progress ? ProgressMode::Lines : ProgressMode::Off;
}

ProgressDisplay::ProgressDisplay(ProgressMode mode, std::chrono::milliseconds delay, std::FILE* out)
    : mode_(mode), delay_(delay), out_(out)
{
    if (mode_ != ProgressMode::Off) thread_ = std::thread([this] { run(); });
}

ProgressDisplay::ProgressDisplay(const ProgressCliOptions& o)
    : ProgressDisplay(progress_mode(o, ::isatty(2) == 1), o.progress ? std::chrono::milliseconds(0) : kTerminalDelay)
{}

ProgressDisplay::~ProgressDisplay()
{
    finish(false);
}

void ProgressDisplay::stage(std::string_view name, std::size_t total)
{
    if (mode_ == ProgressMode::Off) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    if (finished_) return;
    const auto now = Clock::now();
    if (!name_.empty()) draw(now, true);
    name_ = std::string(name);
    total_ = total;
    stage_start_ = now;
    done_.store(0, std::memory_order_relaxed);
    shown_ = false;
    printed_tenth_ = 0;
    printed_at_ = now;
}

void ProgressDisplay::advance(std::size_t done)
{
    if (mode_ == ProgressMode::Off) return;
    std::size_t seen = done_.load(std::memory_order_relaxed);
    while (done > seen && !done_.compare_exchange_weak(seen, done, std::memory_order_relaxed)) {}
}

bool ProgressDisplay::cancelled() const
{
    return interrupted();
}

void ProgressDisplay::finish(bool completed)
{
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!finished_ && mode_ != ProgressMode::Off && !name_.empty()) {
            if (completed) {
                draw(Clock::now(), true);
            } else if (shown_) {
                std::fputs("\n", out_);  // the error message goes on a line of its own
                std::fflush(out_);
            }
        }
        finished_ = true;
        stop_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void ProgressDisplay::run()
{
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
        wake_.wait_for(lock, kRedraw, [this] { return stop_; });
        if (!stop_ && !name_.empty()) draw(Clock::now(), false);
    }
}

std::string ProgressDisplay::line(std::size_t done, Clock::time_point now) const
{
    const double seconds = std::chrono::duration<double>(now - stage_start_).count();
    if (total_ == 0) return fmt::format("{} {} {:.1f} s", name_, done, seconds);
    const auto percent = unsigned(std::floor(100.0 * double(std::min(done, total_)) / double(total_)));
    return fmt::format("{} {}% {:.1f} s", name_, percent, seconds);
}

void ProgressDisplay::draw(Clock::time_point now, bool final)
{
    const std::size_t done = done_.load(std::memory_order_relaxed);
    if (mode_ == ProgressMode::Terminal) {
        if (!shown_ && now - start_ < delay_) return;
        std::fprintf(out_, "\r\033[K%s%s", line(done, now).c_str(), final ? "\n" : "");
        shown_ = !final;
    } else {
        bool print = final;
        if (!final && total_ > 0) {
            const std::size_t tenth = 10 * std::min(done, total_) / total_;
            if (tenth >= 1 && tenth < 10 && tenth + 1 > printed_tenth_) {
                print = true;
                printed_tenth_ = tenth + 1;
            }
        } else if (!final && now - printed_at_ >= std::chrono::seconds(1)) {
            print = true;
        }
        if (!print) return;
        printed_at_ = now;
        std::fprintf(out_, "%s\n", line(done, now).c_str());
    }
    std::fflush(out_);
}

}  // namespace meshdiff::cli
