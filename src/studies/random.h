// Private: the portable random numbers of meshdiff. std::mt19937_64 is fully
// specified by the C++ standard, but the std:: distributions are not (libstdc++
// and libc++ map the same engine output to different numbers), so meshdiff maps
// the raw 64-bit outputs itself. A seed then gives the same numbers on every
// platform and standard library (shapes.h, noise.h).
#pragma once

#include <cmath>
#include <random>
#include <utility>

namespace meshdiff::detail {

//! Uniform in [0, 1) from one raw 64-bit output: the top 53 bits, scaled.
inline double uniform01(std::mt19937_64& rng)
{
    return double(rng() >> 11) * (1.0 / 9007199254740992.0);
}

//! Uniform in [-1, 1) from one raw output.
inline double uniform_pm1(std::mt19937_64& rng)
{
    return 2.0 * uniform01(rng) - 1.0;
}

//! Two independent standard normal numbers from exactly two raw outputs
//! (Box-Muller): r = sqrt(-2 ln(1 - u1)), returns (r cos(2 pi u2), r sin(2 pi
//! u2)), u1, u2 = uniform01(). 1 - u1 lies in (0, 1], so the logarithm is
//! finite. Beyond the engine and the mapping above, the values depend on
//! std::log, std::cos and std::sin of the C library (results agree to the last
//! bit wherever these are the same, e.g. glibc on x86-64 and aarch64).
inline std::pair<double, double> gaussian_pair(std::mt19937_64& rng)
{
    constexpr double kTwoPi = 6.283185307179586476925286766559;
    const double u1 = uniform01(rng);
    const double u2 = uniform01(rng);
    const double r = std::sqrt(-2.0 * std::log(1.0 - u1));
    const double t = kTwoPi * u2;
    return {r * std::cos(t), r * std::sin(t)};
}

}  // namespace meshdiff::detail
