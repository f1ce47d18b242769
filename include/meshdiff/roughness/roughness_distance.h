//! \file roughness_distance.h
//! \brief Per-level roughness distance between two profiles: the paper's
//! eq. 10 in the corrected form of Corsini et al. (METHOD.md section 6),
//!   d_L = ln( |sigma_L(M) - sigma_L(M')| / sigma_L(M) + k ) - ln(k),
//! with the signed relative change (sigma_L(M') - sigma_L(M)) / sigma_L(M).
//!
//! d_L = 0 when the two sigmas agree and grows with the relative change; it is
//! natural-log based. Zero reference roughness (sigma_L(M) = 0), which the
//! formula leaves undefined, is defined here as follows so that no report ever
//! holds NaN or Inf: if both sigmas are 0, d_L = 0 and the change is 0; if only
//! sigma_L(M) is 0, the denominator is replaced by sigma_L(M') (so d_L =
//! ln(1 + k) - ln(k)), the relative change is reported as undefined
//! (`relative_change_defined = false`, 0 in the number), and
//! `reference_zero = true` flags the level.
//!
//! No data is no number: a level at which either profile has no vertex with
//! a defined value (LevelValue::has_data false) gets `defined = false`, and
//! the reports print null (JSON) or `-` (text) for its d_L and change.
//!
//! Every per-level measure (the sigma_L of roughness.h, Corsini's R_L of
//! corsini.h) goes through one function, level_distances(), on the
//! LevelValue lists that its profile provides.
#pragma once

#include "meshdiff/roughness/roughness.h"

#include <vector>

namespace meshdiff {

struct LevelDistance
{
    int level = 0;                        //!< ring level, 0 for global and for metric levels
    double radius = 0.0;                  //!< radius of a metric level, 0 otherwise
    double original = 0.0;                //!< the original's value (sigma_L or R_L)
    double processed = 0.0;               //!< the processed mesh's value
    bool defined = true;                  //!< false: a side has no data here; distance and change are no numbers
    bool original_data = true;            //!< the original has data at this level
    bool processed_data = true;           //!< the processed mesh has data at this level
    double distance = 0.0;                //!< d_L
    double relative_change = 0.0;         //!< (sigma' - sigma) / sigma
    bool relative_change_defined = true;  //!< false when sigma(M) = 0 < sigma(M')
    bool reference_zero = false;          //!< sigma(M) = 0
};

struct RoughnessDistance
{
    double k = 1e-4;                    //!< the constant of eq. 10
    std::vector<LevelDistance> levels;  //!< levels present in both profiles, in the original's order
    bool has_global = false;
    LevelDistance global;
    //! Metric levels present in both profiles (matched by radius, exactly),
    //! in the original's order; empty unless both profiles have radii.
    std::vector<LevelDistance> radii;
};

//! One level of a per-level roughness profile, as level_distances() reads it.
struct LevelValue
{
    int level = 0;         //!< ring level, 0 for global and for metric levels
    double radius = 0.0;   //!< radius of a metric level, 0 otherwise
    double value = 0.0;    //!< sigma_L, R_L, ...
    bool has_data = true;  //!< some vertex has a value at this level
};

//! The ring levels, the global level and the radii of a sigma profile.
std::vector<LevelValue> level_values(const std::vector<LevelRoughness>& levels);
LevelValue level_value(const LevelRoughness& level);

//! d_L and the relative change for one pair of sigmas.
//! \throw InvalidArgumentError if k <= 0 or a sigma is negative or not finite.
LevelDistance level_distance(int level, double sigma_original, double sigma_processed, double k = 1e-4);

//! d_L for one pair of levels; `defined = false` (d_L and change 0) when
//! either has no data.
//! \throw InvalidArgumentError as level_distance() for a value with data.
LevelDistance level_distance(const LevelValue& original, const LevelValue& processed, double k);

//! d_L at every level of \p original that \p processed has too (matched by
//! level number, or by radius when \p by_radius), in the original's order.
//! \throw InvalidArgumentError if k <= 0.
std::vector<LevelDistance> level_distances(const std::vector<LevelValue>& original,
                                           const std::vector<LevelValue>& processed, double k, bool by_radius = false);

//! Distances at every level present in both profiles (matched by level
//! number), and at the global level if both have it.
//! \throw InvalidArgumentError if k <= 0.
RoughnessDistance roughness_distance(const RoughnessProfile& original, const RoughnessProfile& processed,
                                     double k = 1e-4);

}  // namespace meshdiff
