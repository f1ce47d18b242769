#include "geometry/simd.h"

#include <atomic>

namespace meshdiff::detail {

namespace {
std::atomic<bool> allowed{true};

// The variants this CPU has.
unsigned cpu_variants()
{
#if MESHDIFF_HAVE_AVX512_KERNELS
    __builtin_cpu_init();  // needed where this runs before main()
    return (__builtin_cpu_supports("avx2") ? kUseAvx2 : 0u) |
           (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") ? kUseAvx512 : 0u);
#else
    return 0u;
#endif
}
}  // namespace

std::atomic<unsigned> vector_variants{cpu_variants()};

bool cpu_has_avx512()
{
    static const bool has = (cpu_variants() & kUseAvx512) != 0;
    return has;
}

bool cpu_has_avx2()
{
    static const bool has = (cpu_variants() & kUseAvx2) != 0;
    return has;
}

bool allow_vector_kernels(bool allow)
{
    const bool before = allowed.exchange(allow);
    vector_variants.store(allow ? cpu_variants() : 0u, std::memory_order_relaxed);
    return before;
}

}  // namespace meshdiff::detail
