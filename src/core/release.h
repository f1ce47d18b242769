// Private: emptying a container and giving its storage back. `v = {}` does
// not: for a std::vector it assigns an empty initializer list, which keeps
// the capacity (the plan's 3M edges, 60 MB, stayed allocated that way while
// the face samples were queried).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace meshdiff::detail {

//! Empties \p v and frees its storage.
template <class Container>
void release(Container& v)
{
    Container().swap(v);
}

//! Gives back to the system the memory pages of an array's front that is
//! no longer read: those wholly inside [\p data, \p end) and past \p done
//! bytes from \p data (what earlier calls discarded; 0 at first, moved here).
//! Their contents are then undefined; the array keeps its size, capacity and
//! the rest of its values, and is freed as usual. For an array consumed
//! front to back (the sample plan's edge list, 36 MB for 3M edges, while the
//! edge samples are queried). Linux: madvise(MADV_DONTNEED); elsewhere nothing.
inline void discard_front(const void* data, const void* end, std::size_t& done)
{
#if defined(__linux__)
    static const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
    const auto base = std::uintptr_t(data);
    const std::uintptr_t lo = (base + done + page - 1) / page * page;
    const std::uintptr_t hi = std::uintptr_t(end) / page * page;
    if (hi > lo && madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_DONTNEED) == 0) done = hi - base;
#else
    (void)data;
    (void)end;
    (void)done;
#endif
}

}  // namespace meshdiff::detail
