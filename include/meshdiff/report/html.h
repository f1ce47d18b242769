//! \file html.h
//! \brief The HTML report of a comparison: one self-contained page (three.js
//! and its OrbitControls, the page's script and style and every datum
//! inlined; no network request) with the summary of both meshes and of the
//! distances, the roughness profiles and d_L, the distance histograms, and a
//! 3D view of both meshes coloured by their per-vertex distance to the other
//! (the colour ramp of the PLY distance maps, colormap.h) or by the roughness
//! D_L of any computed level, with the point where the certified Hausdorff
//! distance is attained marked. The full JSON report is embedded in a
//! `<script type="application/json" id="meshdiff-report">` element.
#pragma once

#include "meshdiff/compare.h"
#include "meshdiff/core/mesh.h"
#include "meshdiff/report/vertex_maps.h"
#include "meshdiff/roughness/roughness.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace meshdiff {

//! The most faces of one mesh the page draws by default; a larger mesh is
//! drawn reduced (reduce_for_display()), and the page says so. Its numbers
//! are always those of the full meshes.
constexpr std::size_t kDefaultHtmlFaceBudget = 250'000;
//! The smallest face budget accepted.
constexpr std::size_t kMinHtmlFaceBudget = 1000;

//! The default distance colour range of the page: [0, this percentile of both
//! meshes' vertex distances] (vertex_maps.h distance_color_range()).
constexpr double kDefaultHtmlPercentile = kDefaultColorPercentile;

struct HtmlOptions
{
    std::string command;  //!< the command line (or call) that made the report, shown in the page
    //! The range of the distance colours (the PLY maps' ramp, blue to red);
    //! unset: [0, the 99th percentile of both meshes' vertex distances], so
    //! that a few worst vertices do not turn every other one blue.
    std::optional<std::pair<double, double>> color_range;
    std::string color_rule;  //!< how color_range was chosen, shown with the colour bar (empty: "given")
    std::size_t face_budget = kDefaultHtmlFaceBudget;  //!< most faces drawn per mesh (>= 1000)
};

//! A mesh as the page draws it, with per-vertex values carried along.
struct DisplayMesh
{
    std::vector<float> positions;             //!< x y z per vertex
    std::vector<std::uint32_t> indices;       //!< 3 per face
    std::vector<std::vector<double>> values;  //!< per field, one value per vertex (NaN: none)
    std::size_t full_vertices = 0, full_faces = 0;
    bool reduced = false;  //!< by vertex clustering, to the face budget
};

//! \p mesh with \p values (one array per field, each of the mesh's vertex
//! count) as drawn: itself if it has at most \p face_budget faces; else
//! reduced by vertex clustering on a uniform grid, coarsened until at most
//! \p face_budget faces are left: a cluster is drawn at its vertices' mean
//! and carries, per field, the value of largest magnitude of its vertices (so
//! that a worst spot stays visible); faces that collapse are dropped.
//! Deterministic.
DisplayMesh reduce_for_display(const Mesh& mesh, const std::vector<const std::vector<double>*>& values,
                               std::size_t face_budget);

//! The page for the comparison \p c of \p original and \p processed (the
//! meshes it was made from), whose JSON report is \p report
//! (comparison_json(c)). Per-vertex distances are drawn when \p c has them
//! (CompareOptions::vertex_distances), roughness D_L when its profiles kept
//! their vertex data (ProfileOptions::keep_vertex_data).
//! \throw InvalidArgumentError for a face budget below 1000 or a colour range
//!        that is not finite MIN < MAX.
std::string comparison_html(const Comparison& c, const Mesh& original, const Mesh& processed,
                            const nlohmann::json& report, const HtmlOptions& options = {});

//! The page of the roughness profile \p profile of \p mesh (read from \p path)
//! whose JSON report is \p report (profile_json()): the mesh's facts, sigma
//! per level, and the mesh in 3D coloured by H (blue-white-red, as the
//! vertex data map) or by D_L at any level when the profile kept its vertex
//! data (ProfileOptions::keep_vertex_data). Here HtmlOptions::color_range,
//! if set, is the H range [-R, R] (its second value R); unset, it is
//! robust_symmetric_range(H), as the vertex data map's.
//! \throw InvalidArgumentError as comparison_html().
std::string profile_html(const RoughnessProfile& profile, const Mesh& mesh, const std::string& path,
                         const nlohmann::json& report, const HtmlOptions& options = {});

//! Options of batch_summary_html().
struct SummaryHtmlOptions
{
    std::string command;  //!< the command line that made the page, shown in it
    //! The roughness levels whose d_L and local RMS get a column; empty: 1, 2
    //! and 5 (those the records hold; else their first three levels). The
    //! global level gets its columns whenever a record has it.
    std::vector<int> levels;
    //! The folder the page is written to: a record's per-pair page ("html",
    //! relative to the working directory) is linked relative to it when both
    //! lie on one file system tree, else by its absolute path. Empty: the
    //! working directory.
    std::string page_dir;
};

//! The summary page of a batch (meshdiff batch-summary --html): \p records is
//! an array of batch records (the JSON lines of meshdiff batch, merged: one
//! per pair; a pair without one is {"id": ID, "status": "missing"}). One
//! self-contained page (no network request, no library) with a table of every
//! pair (status and error, the certified Hausdorff upper bound absolute and
//! relative, forward/backward mean and RMS, d_L and the local roughness RMS at
//! the chosen levels, a link to the pair's page when its record names one),
//! sortable by any column (numbers numerically, empty cells last), a plot of
//! each measure over the pairs, the command and version, and the records in a
//! `<script type="application/json" id="meshdiff-summary">` element.
//! \throw InvalidArgumentError if \p records is not an array of objects.
std::string batch_summary_html(const nlohmann::json& records, const SummaryHtmlOptions& options = {});

//! Writes \p page to \p path atomically (output_file.h).
//! \throw IoError naming the file if it cannot be written.
void write_html_file(const std::string& path, const std::string& page);

}  // namespace meshdiff
