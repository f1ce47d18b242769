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
    d.original = s0;
    d.processed = s1;
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

LevelValue level_value(const LevelRoughness& l)
{
    return {l.level, l.radius, l.sigma, l.vertices_used > 0};
}

std::vector<LevelValue> level_values(const std::vector<LevelRoughness>& levels)
{
    std::vector<LevelValue> v;
    v.reserve(levels.size());
    for (const auto& l : levels) v.push_back(level_value(l));
    return v;
}

LevelDistance level_distance(const LevelValue& a, const LevelValue& b, double k)
{
    LevelDistance d;
    if (a.has_data && b.has_data) {
        d = level_distance(a.level, a.value, b.value, k);
    } else {
        if (!(k > 0.0) || !std::isfinite(k)) throw OptionError("k", fmt::format("{} must be finite and > 0", k));
        d.level = a.level;
        d.defined = false;
        d.relative_change_defined = false;
        d.original = a.has_data ? a.value : 0.0;
        d.processed = b.has_data ? b.value : 0.0;
        d.original_data = a.has_data;
        d.processed_data = b.has_data;
    }
    d.radius = a.radius;
    return d;
}

std::vector<LevelDistance> level_distances(const std::vector<LevelValue>& a, const std::vector<LevelValue>& b, double k,
                                           bool by_radius)
{
    if (!(k > 0.0) || !std::isfinite(k)) throw OptionError("k", fmt::format("{} must be finite and > 0", k));
    std::vector<LevelDistance> out;
    for (const auto& la : a)
        for (const auto& lb : b)
            if (by_radius ? la.radius == lb.radius : la.level == lb.level) {
                out.push_back(level_distance(la, lb, k));
                break;
            }
    return out;
}

RoughnessDistance roughness_distance(const RoughnessProfile& a, const RoughnessProfile& b, double k)
{
    if (!(k > 0.0) || !std::isfinite(k)) throw OptionError("k", fmt::format("{} must be finite and > 0", k));
    RoughnessDistance r;
    r.k = k;
    r.levels = level_distances(level_values(a.levels), level_values(b.levels), k);
    if (a.has_global && b.has_global) {
        r.has_global = true;
        r.global = level_distance(level_value(a.global), level_value(b.global), k);
    }
    r.radii = level_distances(level_values(a.radii), level_values(b.radii), k, true);
    return r;
}

}  // namespace meshdiff
