//! \file options.h
//! \brief The command line's names for the library's options. Every rule,
//! limit and default lives in the library (meshdiff/options.h and the options
//! structs' validate()); here each option is only registered under its
//! spelling, kept as the text the user gave, and handed to the library's
//! parsers. cli_spelling() is the one table from options field to flag, used
//! to word the library's OptionErrors.
#pragma once

#include "meshdiff/compare.h"
#include "meshdiff/report/outputs.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace meshdiff::cli {

//! The flag of an options field (meshdiff/options.h: option_fields()), e.g.
//! "profile.levels" -> "--levels"; "" for a field the command line does not
//! offer.
std::string cli_spelling(const std::string& field);

//! An option's text as given, and whether it was given.
struct Given
{
    std::string text;
    CLI::Option* option = nullptr;
    bool given() const { return option != nullptr && option->count() > 0; }
};

//! Options of the roughness profile shared by profile, compare and batch.
struct ProfileCliOptions
{
    Given levels, radii, curvature, weighting, measure, normalize, trim, bootstrap, bootstrap_seed;
    bool no_global = false;
    bool unbiased_variance = false;
    bool paper = false;
};
//! \param with_radii also offer --radii (not for smooth, whose records hold ring levels only)
//! \param with_measure also offer --measure and --unbiased-variance (not for smooth)
//! \param defaults the options an option not given keeps (shown in --help)
void add_profile_options(CLI::App* sub, ProfileCliOptions& o, bool with_radii = true, bool with_measure = true,
                         const ProfileOptions& defaults = {});

//! The library options for the parsed options (\p defaults, the library's,
//! where an option was not given), validated.
//! \throw OptionError as validate(ProfileOptions).
ProfileOptions to_profile_options(const ProfileCliOptions& o, ProfileOptions defaults = {});

//! The measure and its variance flag.
RoughnessMeasure to_measure(const ProfileCliOptions& o);

//! Options of a comparison shared by compare and batch.
struct CompareCliOptions
{
    ProfileCliOptions profile;
    Given k, local_trim, samples, density, face_sampling, seed, hausdorff, hausdorff_tolerance, hausdorff_abs_tolerance,
        hausdorff_budget, fscore, histogram;
    bool no_roughness = false;
    bool no_local = false;
    bool no_distance = false;
    bool no_vertex_samples = false, no_edge_samples = false, no_face_samples = false;
};
void add_compare_options(CLI::App* sub, CompareCliOptions& o);

//! \throw OptionError as validate(CompareOptions).
CompareOptions to_compare_options(const CompareCliOptions& o);

//! The outputs of compare (and, per pair, of batch).
struct CompareOutputCliOptions
{
    CompareOutputs outputs;
    std::vector<std::string> color_range;  // MIN MAX as given
    Given html_face_budget;
};
void add_compare_output_options(CLI::App* sub, CompareOutputCliOptions& o);
//! \throw OptionError for a colour range that is not two numbers.
CompareOutputs to_compare_outputs(const CompareOutputCliOptions& o);

//! --html-face-budget N (compare and profile).
void add_html_face_budget_option(CLI::App* sub, Given& budget);
//! The face budget \p budget gives, or the default.
//! \throw OptionError("outputs.html_face_budget") for a text that is not a whole number.
std::size_t html_face_budget(const Given& budget);

//! --threads, kept as given (0: all cores).
void add_threads_option(CLI::App* sub, Given& threads);

//! Sets the OpenMP thread count when --threads N > 0.
//! \throw OptionError if N is outside the library's limit.
void set_threads(const Given& threads);

}  // namespace meshdiff::cli
