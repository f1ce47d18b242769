#include "geometry/simd.h"

#include <atomic>

namespace meshdiff::detail {

namespace {
std::atomic<bool> allowed{true};
}  // namespace

bool cpu_has_avx512()
{
#if MESHDIFF_HAVE_AVX512_KERNELS
    static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw");
    return has;
#else
    return false;
#endif
}

bool use_avx512()
{
    return cpu_has_avx512() && allowed.load(std::memory_order_relaxed);
}

bool cpu_has_avx2()
{
#if MESHDIFF_HAVE_AVX512_KERNELS
    static const bool has = __builtin_cpu_supports("avx2");
    return has;
#else
    return false;
#endif
}

bool use_avx2()
{
    return cpu_has_avx2() && allowed.load(std::memory_order_relaxed);
}

bool allow_vector_kernels(bool allow)
{
    return allowed.exchange(allow);
}

}  // namespace meshdiff::detail
