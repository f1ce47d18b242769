//! \file report/outputs.h
//! \brief The files a comparison or a profile writes beside its result (the
//! JSON report, distance maps, sample clouds, vertex data), and their rules:
//! which outputs exclude or need which options, that no output is an input
//! or another output. `meshdiff compare`, `meshdiff profile`, each pair of
//! `meshdiff batch` and Python's compare_files() / profile_file() all go
//! through these, so an output means the same in every front end. Refusals are
//! OptionErrors naming the field ("outputs.distance_maps", ...: options.h).
#pragma once

#include "meshdiff/compare.h"
#include "meshdiff/io/io.h"
#include "meshdiff/report/html.h"
#include "meshdiff/report/vertex_maps.h"
#include "meshdiff/roughness/corsini.h"
#include "meshdiff/roughness/roughness.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace meshdiff {

//! The outputs of a comparison; an empty path is no output.
struct CompareOutputs
{
    std::string json;                   //!< the JSON report; "-": standard output
    std::string distance_map;           //!< the processed mesh with its distances to the original (PLY)
    std::string distance_map_original;  //!< the original with its distances to the processed mesh (PLY)
    std::string distance_maps;          //!< prefix of both: PREFIX_original.ply, PREFIX_processed.ply
    std::string samples_out;            //!< both directions' samples with their distances (PLY point cloud)
    //! The HTML report (html.h): one self-contained page with the summary, the
    //! plots and both meshes in 3D coloured by their distances and roughness.
    //! It makes the comparison keep its per-vertex distances and D_L, and
    //! histograms of HtmlOptions's bins unless summary.histogram_bins is set
    //! (the JSON report then carries them too).
    std::string html;
    std::string command;  //!< the command line (or call) the HTML report shows
    //! Most faces the HTML report draws per mesh (HtmlOptions::face_budget):
    //! a larger mesh is drawn clustered, the page says so, and every number
    //! stays that of the full mesh. At least kMinHtmlFaceBudget; other than
    //! the default only with html.
    std::size_t html_face_budget = kDefaultHtmlFaceBudget;
    //! The colour range [MIN, MAX] of the distance maps, MIN < MAX, both
    //! finite; unset: [0, the largest distance] (of both maps when both are
    //! written).
    std::optional<std::pair<double, double>> color_range;
    //! Instead of a fixed range: [0, this percentile of both meshes' vertex
    //! distances] (distance_color_range()), for the maps and the HTML report;
    //! in (0, 100], 100 the largest. Neither set: kDefaultColorPercentile, for
    //! the maps and the HTML report alike.
    std::optional<double> color_percentile;
};

//! Sets the colour range of \p o from its text: "max" (color_percentile 100),
//! "pNN" (a percentile in (0, 100], e.g. p99 or p99.5) or "LO:HI" (color_range).
//! \throw OptionError("outputs.color_range") for any other text.
void parse_color_range(const std::string& text, CompareOutputs& o);

//! The two map paths \p o asks for (distance_maps expanded): original, processed.
std::pair<std::string, std::string> map_paths(const CompareOutputs& o);

//! The rules of \p o with \p options: distance_maps excludes the two single
//! map options; a colour range needs MIN < MAX, both finite, and excludes a
//! colour percentile, which is in (0, 100]; html_face_budget is at least
//! kMinHtmlFaceBudget and, when not the default, needs html; samples_out and
//! the maps need the surface distance; no two outputs name one file and no
//! output is one of \p inputs (also through links).
//! \throw OptionError naming the field.
void validate(const CompareOutputs& o, const CompareOptions& options, const std::vector<std::string>& inputs);

//! Histogram bins of the HTML report when the options ask for none.
constexpr std::size_t kHtmlHistogramBins = 40;

//! \p options with what \p o needs computed (vertex distances for maps and
//! the HTML report, the samples for samples_out; for the HTML report also the
//! per-vertex D_L and, when none are asked, kHtmlHistogramBins histogram bins).
CompareOptions with_outputs(CompareOptions options, const CompareOutputs& o);

//! Writes the maps, the sample cloud and the HTML report of \p c (made with
//! with_outputs()) named in \p o, and returns the lines that name them for
//! the text report. \p original_name / \p processed_name name the inputs in
//! the files' comments. Not the JSON (write_json_file()).
std::string write_outputs(const Comparison& c, const LoadedMesh& original, const LoadedMesh& processed,
                          const CompareOutputs& o, const std::string& original_name, const std::string& processed_name);

//! What `meshdiff profile` asks: the options of the measure chosen and the outputs.
struct ProfileRequest
{
    ProfileOptions
        profile{};  //!< levels, global, radii, curvature (the sigma measure; levels and global also Corsini's)
    RoughnessMeasure measure = RoughnessMeasure::Sigma;
    bool corsini_unbiased = false;  //!< CorsiniOptions::unbiased
    std::string json;               //!< the JSON report; "-": standard output; empty: none
    std::string vertex_data;        //!< the normalised mesh with H and D per vertex (PLY); empty: none
    double color_range = 0.0;       //!< the H colour range [-R, R] of vertex_data; 0: robust_symmetric_range(H)
    bool exact = false;             //!< also the profile of the exact H stored in the input, and the error of H
    std::string exact_property = "exact_H";  //!< the PLY vertex property holding it
    std::string html;     //!< the HTML report (html.h profile_html()); empty: none (sigma measure only)
    std::string command;  //!< the command line (or call) the HTML report shows
    std::size_t html_face_budget = kDefaultHtmlFaceBudget;  //!< as CompareOutputs::html_face_budget
};

//! The rules of \p r: validate() of its profile options; corsini_unbiased
//! only with the Corsini measure, which takes no radii, vertex data, exact
//! profile, HTML report or colour range; color_range finite and >= 0;
//! exact_property not empty; html not "-"; html_face_budget as in
//! CompareOutputs; no output is one of \p inputs, nor another output.
//! \throw OptionError naming the field.
void validate(const ProfileRequest& r, const std::vector<std::string>& inputs);

//! The JSON and text reports of a profile.
struct ProfileReport
{
    nlohmann::json json;
    std::string text;
};

//! The profile \p r asks for of \p mesh (the sigma profile with its exact
//! twin, or Corsini's), its reports, and the vertex data file if asked for
//! and the HTML report if asked for (written here; the JSON is not:
//! write_json_file()). The mesh's topology
//! report runs beside the profile, on a thread of its own unless OpenMP is
//! limited to one thread.
//! \throw OptionError as validate(); InvalidArgumentError if the exact
//!        property is not in the input.
ProfileReport profile_report(const LoadedMesh& mesh, const ProfileRequest& r);

//! Writes \p j (2-space indented, with a final newline; bytes that are not
//! UTF-8 as U+FFFD) to \p target atomically (output_file.h), or to standard
//! output for "-".
//! \throw IoError if the file cannot be written.
void write_json_file(const std::string& target, const nlohmann::json& j);

}  // namespace meshdiff
