#include "core/derivations.h"

#include <atomic>
#include <functional>
#include <mutex>
#include <string_view>

namespace meshdiff::detail {

namespace {

std::atomic<bool> g_on{false};
std::mutex g_mutex;
DerivationCounts g_counts;

}  // namespace

MeshKey mesh_key(const Mesh& mesh)
{
    const std::string_view bytes(reinterpret_cast<const char*>(mesh.points.data()),
                                 mesh.points.size() * sizeof(mesh.points[0]));
    return {static_cast<const void*>(mesh.points.data()), std::hash<std::string_view>{}(bytes)};
}

void note_derivation(Derived what, const Mesh& mesh)
{
    if (!g_on.load(std::memory_order_relaxed)) return;
    const MeshKey key = mesh_key(mesh);
    const std::lock_guard<std::mutex> lock(g_mutex);
    ++g_counts[{key, what}];
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
