//! \file frontend/options.h
//! \brief The rules of the options that the front ends (the CLI, batch,
//! Python) share, in one home: the text forms of the list options (`1-20`,
//! `default`, `0.001,0.005`), the Hausdorff method and the rule that turns
//! "which tolerances were given" into HausdorffOptions, and the thread limit.
//! The limits themselves sit beside the options they bound (roughness.h:
//! kMaxLevels, metric_levels.h: kMaxRadii, sampling.h: kMaxSamples, ...);
//! every refusal is an OptionError (error.h) naming the field, which each
//! front end words with its own spelling (options_fields() lists the fields).
#pragma once

#include "meshdiff/distance/hausdorff.h"
#include "meshdiff/enum_names.h"
#include "meshdiff/error.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace meshdiff {

//! The field paths an OptionError may name, each once (as in CompareOptions;
//! "threads" is the thread count of a call, "outputs.*" the files of
//! CompareOutputs / ProfileOutputs). A front end maps every one of them to
//! its spelling; its tests check that none is missing.
const std::vector<std::string>& option_fields();

//! The message of \p e with every field written as \p spell spells it:
//! "spell(field): problem", where the problem's "{field}" placeholders (other
//! fields it mentions) are spelled too. \p spell returns "" for a field the
//! front end does not know; the path itself is used then.
template <class Spell>
std::string worded(const OptionError& e, Spell spell)
{
    auto name = [&](const std::string& field) {
        std::string s = spell(field);
        return s.empty() ? field : s;
    };
    std::string problem;
    const std::string& p = e.problem();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const auto close = p[i] == '{' ? p.find('}', i) : std::string::npos;
        if (close == std::string::npos) {
            problem += p[i];
            continue;
        }
        problem += name(p.substr(i + 1, close - i - 1));
        i = close;
    }
    return name(e.field()) + ": " + problem;
}

//! Parses one level, a whole number in 1..kMaxLevel written in decimal.
//! \throw OptionError("profile.levels") otherwise.
int parse_level(const std::string& item);

//! Parses a level list such as "1,2,5,10,20", "1-20" or "1-5,10"; "" is no level.
//! \throw OptionError("profile.levels") on a malformed list, a level outside
//!        1..kMaxLevel or more than kMaxLevels levels.
std::vector<int> parse_levels(const std::string& text);

//! Parses a radius list such as "0.05,0.1,0.2", "default" (default_radii()),
//! or "" (none).
//! \throw OptionError("profile.radii") on a malformed list, a radius not
//!        finite, <= 0 or > kMaxRadius, or more than kMaxRadii radii.
std::vector<double> parse_radii(const std::string& text);

//! Parses F-score thresholds such as "0.001,0.005" (relative to the
//! diagonal), or "" (none).
//! \throw OptionError("summary.fscore_thresholds") on a malformed list, a
//!        threshold not in (0, kMaxFscoreThreshold] or more than
//!        kMaxFscoreThresholds thresholds.
std::vector<double> parse_fscore(const std::string& text);

//! The whole of \p text as a number (a decimal or exponent form; "inf" and
//! "nan" parse, for the rules to refuse).
//! \throw OptionError(\p field) if it is not a number.
double parse_number(const char* field, const std::string& text);

//! The whole of \p text as a whole number in 0..2^64-1 (digits only).
//! \throw OptionError(\p field) if it is not one.
std::uint64_t parse_whole_number(const char* field, const std::string& text);

//! The value spelt \p name of an option enum, as parse_enum(), refusing an
//! unknown name with an OptionError naming \p field.
template <class E, class = decltype(EnumNames<E>::names)>
E parse_enum_option(const char* field, const std::string& name)
{
    try {
        return parse_enum<E>(name);
    } catch (const InvalidArgumentError& e) {
        throw OptionError(field, e.what());
    }
}

//! How the comparison reports the one-sided Hausdorff distances.
enum class HausdorffMethod
{
    Certified,  //!< an interval holding the true value (hausdorff.h), seeded with the sampled maximum
    Sampled,    //!< the sampled maximum only (Metro)
};

template <>
struct EnumNames<HausdorffMethod>
{
    static constexpr const char* what = "Hausdorff method";
    static constexpr std::array<EnumName<HausdorffMethod>, 2> names{
        {{HausdorffMethod::Certified, "certified"}, {HausdorffMethod::Sampled, "sampled"}}};
};

//! What a user asked of the Hausdorff distance: unset fields were not given.
struct HausdorffRequest
{
    HausdorffMethod method = HausdorffMethod::Certified;
    std::optional<double> relative_tolerance;  //!< width relative to the value
    std::optional<double> absolute_tolerance;  //!< width in the meshes' unit
    std::optional<std::size_t> budget;         //!< HausdorffOptions::max_evaluations
};

//! The Hausdorff options of CompareOptions for \p request (std::nullopt:
//! sampled). The rule: the interval stops once its width is at most
//! max(relative x value, absolute), as Python's math.isclose; a tolerance not
//! given is 0, except that with neither given the relative one is
//! kDefaultHausdorffTolerance. The budget not given is the default one.
//! \throw OptionError for a tolerance or budget with the sampled method, or a
//!        value outside the limits of validate(HausdorffOptions).
std::optional<HausdorffOptions> hausdorff_options(const HausdorffRequest& request);

//! The most worker threads a call may ask for (0: all cores).
constexpr int kMaxThreads = 1024;

//! \throw OptionError("threads") unless 0 <= \p threads <= kMaxThreads.
void validate_threads(long long threads);

//! The thread count to give OpenMP for a request of \p threads (0: leave the
//! default, returned as 0). More threads than cores are first tried: if the
//! system cannot start that many (a memory limit, a process limit), the count
//! that could be started is returned and \p warning says so (without the
//! option's name, which the front end adds), instead of
//! OpenMP ending the process when it fails to create them.
//! \throw OptionError as validate_threads().
int usable_threads(long long threads, std::string& warning);

//! The batch front end's own options (`meshdiff batch`): the most shards a
//! pair list is split into, and the longest time one pair may take.
constexpr std::size_t kMaxShards = 1'000'000;
constexpr double kMaxPairTimeout = 1e7;  //!< seconds (115 days)

//! \throw OptionError("batch.shard") unless 0 <= \p index < \p count <= kMaxShards.
void validate_shard(std::size_t index, std::size_t count, const std::string& text);

//! \throw OptionError("batch.pair_timeout") unless 0 <= \p seconds <= kMaxPairTimeout (0: none).
void validate_pair_timeout(double seconds);

}  // namespace meshdiff
