//! \file report.h
//! \brief Text and JSON reports of mesh facts and roughness profiles
//! (schema "meshdiff.profile/1"). JSON never holds NaN or Inf: undefined
//! numbers are null and are explained by a count or a flag beside them.
#pragma once

#include "meshdiff/io.h"
#include "meshdiff/mesh.h"
#include "meshdiff/roughness.h"
#include "meshdiff/roughness_distance.h"
#include "meshdiff/topology.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace meshdiff {

//! Everything the reports say about one input mesh.
struct MeshFacts
{
    InputReport input;
    TopologyReport topology;
    BoundingBox box;
    double area = 0.0;
};

MeshFacts mesh_facts(const LoadedMesh& loaded);

//! Human-readable warnings about the mesh and the profile (defects that limit
//! what the numbers mean, outlier-dominated levels).
std::vector<std::string> profile_warnings(const MeshFacts& facts, const RoughnessProfile* profile);

nlohmann::json mesh_json(const MeshFacts& facts);
//! The "meshdiff.profile/1" object: schema, mesh, curvature, levels, sigma,
//! sigma_global, per-level details, warnings.
nlohmann::json profile_json(const MeshFacts& facts, const RoughnessProfile& profile);
std::string profile_text(const MeshFacts& facts, const RoughnessProfile& profile);

//! The roughness_distance object of "meshdiff.compare/1".
nlohmann::json roughness_distance_json(const RoughnessDistance& d);

//! A JSON number, or null when \p x is not finite.
nlohmann::json number_or_null(double x);

}  // namespace meshdiff
