// Run-time choice of the vector kernels. The library is built for the
// baseline x86-64 (SSE2); a kernel with an AVX-512 or AVX2 variant compiles
// that variant for its target (__attribute__((target(...))) or #pragma GCC
// target) and takes it only where the CPU has it (AVX-512F and AVX-512BW;
// AVX2), so one binary runs everywhere. Every variant
// gives bitwise the same results as the baseline (the same additions in the
// same order); tests switch the variants off and on to check that.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__)
#define MESHDIFF_HAVE_AVX512_KERNELS 1
#else
#define MESHDIFF_HAVE_AVX512_KERNELS 0
#endif

#include <atomic>

namespace meshdiff::detail {

//! Whether this CPU has the AVX-512 subsets the kernels use (F, BW).
bool cpu_has_avx512();

//! Whether this CPU has AVX2.
bool cpu_has_avx2();

//! The variants the kernels take now: kUseAvx2 and kUseAvx512 where the CPU
//! has them and they are allowed (allow_vector_kernels()). Read on every
//! query and every bound of the certification, so one relaxed load, not a
//! call: set before main() runs (0, the baseline kernels, until then, which
//! give the same bits) and by allow_vector_kernels().
constexpr unsigned kUseAvx2 = 1u, kUseAvx512 = 2u;
extern std::atomic<unsigned> vector_variants;

//! Whether the kernels take their AVX-512 variants now: the CPU has them and
//! they are allowed.
inline bool use_avx512()
{
    return (vector_variants.load(std::memory_order_relaxed) & kUseAvx512) != 0;
}

//! Whether the kernels take their AVX2 variants now.
inline bool use_avx2()
{
    return (vector_variants.load(std::memory_order_relaxed) & kUseAvx2) != 0;
}

//! For tests and benchmarks: allows (the default) or forbids all vector
//! variants (AVX-512 and AVX2); returns the previous setting.
bool allow_vector_kernels(bool allow);

}  // namespace meshdiff::detail
