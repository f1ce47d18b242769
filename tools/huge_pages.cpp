// The command-line tool's operator new: large blocks on transparent huge pages.
//
// Every array of a large mesh (points, faces, adjacency, index, samples,
// distances) is a fresh mapping (main.cpp's mmap threshold) whose pages the
// kernel hands out one 4 KiB page fault at a time; on the virtual machines we
// measure on, a page fault costs several microseconds. A block of 2 MiB and
// more is marked MADV_HUGEPAGE, so that where the kernel's transparent huge
// pages are "madvise" (Debian's default) each aligned 2 MiB of it is one
// fault, not 512. The same blocks, the same bytes: only how the kernel backs
// them changes. 2 x 1M compare: page faults 975K -> 75K, 25.4 -> 19.8 s;
// docs/performance.md, "Issue 30, huge pages, one heap and the serial steps".
//
// Only the executable replaces operator new (the library and the Python
// module leave the allocator to their host program), and not under the
// sanitizers, whose own operator new checks every new against its delete.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

#include "sanitized.h"

#if defined(__linux__) && !defined(MESHDIFF_SANITIZED)
#include <sys/mman.h>

#if defined(MADV_HUGEPAGE)
namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;  // x86-64 and arm64 (4 KiB pages)

// Marks the aligned 2 MiB stretches of [p, p + size) for huge pages; a
// kernel without them refuses the advice, which changes nothing.
void advise_huge(void* p, std::size_t size)
{
    const auto begin = (std::uintptr_t(p) + kHugePage - 1) & ~(kHugePage - 1);
    const auto end = (std::uintptr_t(p) + size) & ~(kHugePage - 1);
    if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

}  // namespace

// The standard's behaviour (new_handler, bad_alloc); free() releases the block,
// as the default operator delete does.
void* operator new(std::size_t size)
{
    for (;;) {
        if (void* p = std::malloc(size == 0 ? 1 : size)) {
            if (size >= kHugePage) advise_huge(p, size);
            return p;
        }
        const std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

void* operator new[](std::size_t size)
{
    return ::operator new(size);
}

// The over-aligned forms (C++17: a type aligned beyond 16 bytes, such as the
// closest-point index's 64-byte nodes, 40 MB for 2M faces), which otherwise
// keep the library's aligned_alloc() and 4 KiB pages.
void* operator new(std::size_t size, std::align_val_t alignment)
{
    const std::size_t a = std::max(std::size_t(alignment), sizeof(void*));
    for (;;) {
        void* p = nullptr;
        if (posix_memalign(&p, a, size == 0 ? 1 : size) == 0) {
            if (size >= kHugePage) advise_huge(p, size);
            return p;
        }
        const std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

void* operator new[](std::size_t size, std::align_val_t alignment)
{
    return ::operator new(size, alignment);
}

void operator delete(void* p) noexcept
{
    std::free(p);
}

void operator delete[](void* p) noexcept
{
    std::free(p);
}

void operator delete(void* p, std::size_t) noexcept
{
    std::free(p);
}

void operator delete[](void* p, std::size_t) noexcept
{
    std::free(p);
}

void operator delete(void* p, std::align_val_t) noexcept
{
    std::free(p);
}

void operator delete[](void* p, std::align_val_t) noexcept
{
    std::free(p);
}

void operator delete(void* p, std::size_t, std::align_val_t) noexcept
{
    std::free(p);
}

void operator delete[](void* p, std::size_t, std::align_val_t) noexcept
{
    std::free(p);
}

#endif  // MADV_HUGEPAGE
#endif  // __linux__ && !MESHDIFF_SANITIZED
