//! \file report/json.h
//! \brief The JSON reports of meshdiff (presentation layer, target
//! meshdiff::report): schemas "meshdiff.profile/1", "meshdiff.compare/2",
//! "meshdiff.smoothing/1" and the batch lines, built from the plain structs the
//! library returns. No computing file includes this header. JSON never holds
//! NaN or Inf: undefined numbers are null and are explained by a count or a
//! flag beside them.
#pragma once

#include "meshdiff/compare.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/io/facts.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/roughness/roughness_distance.h"
#include "meshdiff/studies/smoothing_record.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace meshdiff {

//! A JSON number, or null when \p x is not finite.
nlohmann::json number_or_null(double x);

//! The "mesh" object: path, topology counts, reading report, area, bbox.
nlohmann::json mesh_json(const MeshFacts& facts);

//! The warnings as an array of their texts.
nlohmann::json warnings_json(const std::vector<Warning>& warnings);

//! The "meshdiff.profile/1" object: schema, mesh, curvature, levels, sigma,
//! sigma_global, per-level details, warnings.
nlohmann::json profile_json(const MeshFacts& facts, const RoughnessProfile& profile);

//! The "exact" object of a profile report: the profile of the exact H read
//! from the vertex property \p property, beside \p estimated.
nlohmann::json exact_profile_json(const RoughnessProfile& estimated, const ExactProfile& exact,
                                  const std::string& property);

//! The roughness_distance object of "meshdiff.compare/2".
nlohmann::json roughness_distance_json(const RoughnessDistance& d);

//! The "local" block of roughness_distance: the local roughness difference
//! per level (null where no vertex has data).
nlohmann::json local_roughness_json(const LocalRoughnessDistance& d);

//! The "corsini" block of a profile or of one side of a comparison: the
//! roughness per level, global and multi-scale, with counts and definition.
nlohmann::json corsini_json(const CorsiniProfile& profile);

//! `meshdiff profile --measure corsini` (schema "meshdiff.corsini/1").
nlohmann::json corsini_profile_json(const MeshFacts& facts, const CorsiniProfile& profile);

//! The comparison score R(M, M') per level, global and multi-scale.
nlohmann::json corsini_distance_json(const CorsiniDistance& d);
//! One direction's distance statistics (absolute, and relative to \p diagonal),
//! its area-weighted statistics (null without face samples) and histogram
//! (only when computed).
nlohmann::json distance_stats_json(const DistanceStats& s, double diagonal);

//! The same_connectivity object of "meshdiff.compare/2" (distances also
//! relative to \p diagonal, the original's).
nlohmann::json same_connectivity_json(const SameConnectivity& s, double diagonal);

//! The surface_distance object of "meshdiff.compare/2": both directions (with
//! their certified Hausdorff distances when computed, else null), the
//! symmetric Hausdorff distance as an interval (`hausdorff`: method
//! "certified", or "sampled" with a null upper bound), the sampled maximum
//! (`sampled_hausdorff`), the diagonals and the sampling \p options as requested.
nlohmann::json surface_distance_json(const SurfaceDistance& d, const SamplingOptions& options);

//! The "meshdiff.compare/2" object.
nlohmann::json comparison_json(const Comparison& c);

//! The "meshdiff.smoothing/1" object of a smoothing of the file \p input
//! written to \p output.
nlohmann::json smoothing_json(const SmoothingRecord& record, const SmoothingOptions& options,
                              const RecordOptions& record_options, const std::string& input, const std::string& output);

//! One line of `meshdiff batch` for a pair that was compared.
nlohmann::json batch_ok_json(const std::string& id, const std::string& original, const std::string& processed,
                             const Comparison& c);
//! The same with the comparison already as its "meshdiff.compare/2" object
//! (from a child process).
nlohmann::json batch_ok_json(const std::string& id, const std::string& original, const std::string& processed,
                             nlohmann::json result);
//! One line of `meshdiff batch` for a pair that failed with \p error (exit
//! code \p exit_code of the tool).
nlohmann::json batch_error_json(const std::string& id, const std::string& original, const std::string& processed,
                                const std::string& error, int exit_code);

}  // namespace meshdiff
