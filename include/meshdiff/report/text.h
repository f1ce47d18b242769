//! \file report/text.h
//! \brief The text reports of meshdiff for people (presentation layer, target
//! meshdiff::report), built from the plain structs the library returns. The
//! comparison keeps Metro's order and names for the distance part.
#pragma once

#include "meshdiff/compare.h"
#include "meshdiff/io/facts.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/studies/noise.h"
#include "meshdiff/studies/shapes.h"
#include "meshdiff/studies/smoothing.h"

#include <optional>
#include <string>

namespace meshdiff {

//! The profile report of one mesh.
std::string profile_text(const MeshFacts& facts, const RoughnessProfile& profile);

//! The Corsini roughness report of one mesh (profile --measure corsini).
std::string corsini_profile_text(const MeshFacts& facts, const CorsiniProfile& profile);

//! The table of an exact profile beside the estimated one (profile --exact).
std::string exact_profile_text(const RoughnessProfile& estimated, const ExactProfile& exact,
                               const std::string& property);

//! The comparison report.
std::string comparison_text(const Comparison& c);

//! The summary lines of a smoothing written to \p output.
std::string smoothing_text(const std::string& output, const SmoothingOptions& options, std::size_t vertices,
                           const SmoothingReport& report);

//! A warning for stderr when explicit flow steps exceeded the stability bound
//! (naming \p input), or nothing.
std::optional<std::string> smoothing_warning(const std::string& input, const SmoothingOptions& options,
                                             const SmoothingReport& report);

//! What add_noise() did, in words: "uniform [-0.5, 0.5) x mean edge length 0.0123".
std::string noise_description(const NoiseOptions& options, const NoiseReport& report);

//! The PLY header comment of a noisy mesh made from \p input (one line).
std::string noise_comment(const std::string& input, const NoiseOptions& options, const NoiseReport& report);

//! The summary line of a noisy mesh written to \p output.
std::string noise_text(const std::string& output, const NoiseOptions& options, const NoiseReport& report);

//! The summary line of a generated shape written to \p output.
std::string shape_text(const std::string& output, const Shape& shape, const std::string& description);

}  // namespace meshdiff
