#include "core/derivations.h"

#include <atomic>
#include <mutex>

namespace meshdiff::detail {

namespace {

std::atomic<bool> g_on{false};
std::mutex g_mutex;
DerivationCounts g_counts;

}  // namespace

void note_derivation(Derived what, const Mesh& mesh)
{
    if (!g_on.load(std::memory_order_relaxed)) return;
    const std::lock_guard<std::mutex> lock(g_mutex);
    ++g_counts[{static_cast<const void*>(mesh.points.data()), what}];
}

void start_derivation_log()
{
    const std::lock_guard<std::mutex> lock(g_mutex);
    g_counts.clear();
    g_on.store(true);
}

DerivationCounts stop_derivation_log()
{
    const std::lock_guard<std::mutex> lock(g_mutex);
    g_on.store(false);
    return std::exchange(g_counts, {});
}

}  // namespace meshdiff::detail
