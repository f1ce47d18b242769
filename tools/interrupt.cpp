#include "interrupt.h"

#include <signal.h>

#include <atomic>

namespace meshdiff::cli {

namespace {

std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free atomic");

extern "C" void on_interrupt(int signo)
{
    int expected = 0;
    g_signal.compare_exchange_strong(expected, signo);
}

}  // namespace

void install_interrupt_handlers()
{
    struct sigaction sa = {};
    sa.sa_handler = on_interrupt;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;  // reads and writes go on; the flag is polled
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
}

bool interrupted()
{
    return g_signal.load(std::memory_order_relaxed) != 0;
}

int interrupt_signal()
{
    return g_signal.load(std::memory_order_relaxed);
}

}  // namespace meshdiff::cli
