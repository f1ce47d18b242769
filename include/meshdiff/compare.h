//! \file compare.h
//! \brief The comparison of an original and a processed mesh that
//! `meshdiff ORIGINAL PROCESSED` reports (schema "meshdiff.compare/1"): both
//! roughness profiles, the per-level roughness distance (roughness_distance.h)
//! and the Metro-style surface distance (surface_distance.h).
#pragma once

#include "meshdiff/io.h"
#include "meshdiff/report.h"
#include "meshdiff/roughness.h"
#include "meshdiff/roughness_distance.h"
#include "meshdiff/sampling.h"
#include "meshdiff/surface_distance.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace meshdiff {

struct CompareOptions
{
    ProfileOptions profile{};    //!< levels, global, curvature estimator (same for both meshes)
    double k = 1e-4;             //!< the constant of eq. 10 (an assumption; see METHOD.md 6)
    bool roughness = true;       //!< compute the profiles and their distance
    bool distance = true;        //!< compute the surface distance
    SamplingOptions sampling{};  //!< surface sampling (Metro defaults)
};

struct Comparison
{
    MeshFacts original;
    MeshFacts processed;
    CompareOptions options;
    std::optional<RoughnessProfile> original_profile;
    std::optional<RoughnessProfile> processed_profile;
    std::optional<RoughnessDistance> roughness;
    std::optional<SurfaceDistance> distance;
};

//! Runs the halves asked for in \p options.
//! \throw InvalidArgumentError for bad options (k <= 0, both halves off, bad sampling).
Comparison compare_meshes(const LoadedMesh& original, const LoadedMesh& processed, const CompareOptions& options = {});

//! The "meshdiff.compare/1" object.
nlohmann::json comparison_json(const Comparison& c);
//! The report for people, in Metro's order and names for the distance part.
std::string comparison_text(const Comparison& c);

//! The JSON of one direction's distance statistics (absolute, and relative to
//! \p diagonal).
nlohmann::json distance_stats_json(const DistanceStats& s, double diagonal);

}  // namespace meshdiff
