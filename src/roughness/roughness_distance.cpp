#include "meshdiff/roughness/roughness_distance.h"

#include "meshdiff/error.h"

#include <fmt/format.h>

#include <cmath>

namespace meshdiff {

LevelDistance level_distance(int level, double s0, double s1, double k)
{
    if (!(k > 0.0) || !std::isfinite(k)) throw OptionError("k", fmt::format("{} must be finite and > 0", k));
    if (!(s0 >= 0.0) || !(s1 >= 0.0) || !std::isfinite(s0) || !std::isfinite(s1))
        throw InvalidArgumentError(fmt::format("roughness distance: sigmas {} and {} must be finite and >= 0", s0, s1));
    LevelDistance d;
    d.level = level;
    if (s0 > 0.0) {
        d.relative_change = (s1 - s0) / s0;
        d.distance = std::log(std::abs(s1 - s0) / s0 + k) - std::log(k);
    } else if (s1 > 0.0) {
        d.reference_zero = true;
        d.relative_change_defined = false;
        d.distance = std::log(1.0 + k) - std::log(k);
    } else {
        d.reference_zero = true;
    }
    return d;
}

RoughnessDistance roughness_distance(const RoughnessProfile& a, const RoughnessProfile& b, double k)
{
    if (!(k > 0.0) || !std::isfinite(k)) throw OptionError("k", fmt::format("{} must be finite and > 0", k));
    RoughnessDistance r;
    r.k = k;
    for (const auto& la : a.levels)
        for (const auto& lb : b.levels)
            if (la.level == lb.level) {
                r.levels.push_back(level_distance(la.level, la.sigma, lb.sigma, k));
                break;
            }
    if (a.has_global && b.has_global) {
        r.has_global = true;
        r.global = level_distance(0, a.global.sigma, b.global.sigma, k);
    }
    for (const auto& la : a.radii)
        for (const auto& lb : b.radii)
            if (la.radius == lb.radius) {
                LevelDistance d = level_distance(0, la.sigma, lb.sigma, k);
                d.radius = la.radius;
                r.radii.push_back(d);
                break;
            }
    return r;
}

}  // namespace meshdiff
