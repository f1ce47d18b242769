//! \file options.h
//! \brief Option parsing helpers shared by the subcommands.
#pragma once

#include "meshdiff/compare.h"
#include "meshdiff/corsini.h"
#include "meshdiff/curvature.h"
#include "meshdiff/roughness.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace meshdiff::cli {

//! Parses a level list such as "1,2,5,10,20" or "1-20" or "1-5,10".
//! \throw InvalidArgumentError on a malformed list or a level < 1.
std::vector<int> parse_levels(const std::string& text);

//! Parses a radius list such as "0.05,0.1,0.2", or "default" (default_radii()),
//! or "" (none).
//! \throw InvalidArgumentError on a malformed list, a radius not finite, <= 0
//!        or > kMaxRadius, or more than kMaxRadii radii.
std::vector<double> parse_radii(const std::string& text);

//! Parses F-score thresholds such as "0.001,0.005" (relative to the diagonal),
//! or "" (none).
//! \throw InvalidArgumentError on a malformed list, a threshold not in (0, 1e6]
//!        or more than kMaxFscoreThresholds thresholds.
std::vector<double> parse_fscore(const std::string& text);

//! Options of the roughness profile shared by profile, compare and batch.
struct ProfileCliOptions
{
    std::string levels = "1-20";
    std::string radii;  // empty: no metric level
    bool no_global = false;
    std::string curvature = "goldfeather";
    std::string weighting = "none";
    std::string measure = "sigma";  // only profile and compare offer --measure
    bool unbiased_variance = false;
};
//! \param with_radii also offer --radii (not for smooth, whose records hold ring levels only)
void add_profile_options(CLI::App* sub, ProfileCliOptions& o, bool with_radii = true);

//! --measure and --unbiased-variance (profile and compare only).
void add_measure_options(CLI::App* sub, ProfileCliOptions& o);

//! The library options for the parsed command-line options.
ProfileOptions to_profile_options(const ProfileCliOptions& o, bool keep_vertex_data);

//! The Corsini options (levels, global, variance) for the parsed options.
//! \throw InvalidArgumentError if --radii was given, or --unbiased-variance
//!        without --measure corsini.
CorsiniOptions to_corsini_options(const ProfileCliOptions& o);

//! Options of a comparison shared by compare and batch.
struct CompareCliOptions
{
    ProfileCliOptions profile;
    double k = 1e-4;
    bool no_roughness = false;
    bool no_distance = false;
    std::size_t samples = 0;  // 0: Metro's default budget
    double density = 0.0;     // 0: unset
    std::string face_sampling = "similar";
    std::uint64_t seed = 1;
    bool no_vertex_samples = false, no_edge_samples = false, no_face_samples = false;
    std::string hausdorff = "certified";
    double hausdorff_tolerance = 0.0;  // 0: 1e-4, or none when an absolute tolerance is given
    double hausdorff_abs_tolerance = 0.0;
    std::size_t hausdorff_budget = 0;  // 0: the library's default
    std::string fscore;                // F-score thresholds, relative; empty: none
    std::size_t histogram = 0;         // histogram bins; 0: none
};
void add_compare_options(CLI::App* sub, CompareCliOptions& o);
CompareOptions to_compare_options(const CompareCliOptions& o);

//! A validator for a numeric option: the value must parse as a finite number
//! in [lo, hi] (and be a whole number if \p integer); the message states the range.
CLI::Validator in_range(double lo, double hi, bool integer = false);
//! A validator: a finite number > 0 (up to \p hi).
CLI::Validator positive(double hi = 1e300);

//! The largest thread count accepted by --threads.
constexpr int kMaxThreads = 1024;
//! The largest --hausdorff-budget (bounds of triangles; each costs some 100
//! bytes while open).
constexpr double kMaxHausdorffBudget = 1e9;
//! The most levels a --levels list may hold (each level keeps a value per vertex).
constexpr std::size_t kMaxLevels = 200;

//! The most radii a --radii list may hold.
constexpr std::size_t kMaxRadii = 64;
//! The largest radius --radii accepts (on the unit-scaled mesh, whose mean
//! vertex distance to the centroid is 1: far larger than any mesh).
constexpr double kMaxRadius = 1000.0;

//! Sets the OpenMP thread count when \p threads > 0.
void set_threads(int threads);

//! Refuses to write the output \p output of option \p what (e.g. "--json")
//! onto one of \p inputs: the same file, also through links.
//! \throw InvalidArgumentError naming both.
void refuse_overwriting_inputs(const std::string& what, const std::string& output,
                               const std::vector<std::string>& inputs);

//! Writes \p j to FILE (atomically: output_file.h), or to stdout for "-".
//! \throw IoError if the file cannot be written.
void write_json(const std::string& target, const nlohmann::json& j);

}  // namespace meshdiff::cli
