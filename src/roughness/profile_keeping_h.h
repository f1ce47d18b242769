//! \file profile_keeping_h.h (detail)
//! \brief A roughness profile that keeps H per vertex but not D: what the
//! local roughness difference needs of a comparison's two profiles.
#pragma once

#include "meshdiff/roughness/roughness.h"

#include "roughness/level_stream.h"

#include <functional>
#include <optional>

namespace meshdiff::detail {

//! Given the normalised mesh and its H (before the rings), a second set of
//! values to fold over the same ring search, at the profile's levels
//! (fold_levels()), or none.
using SecondFoldHook = std::function<std::optional<SecondFold>(const Mesh& unit, const std::vector<double>& H)>;

//! roughness_profile(mesh, options, frame), keeping RoughnessProfile::H when
//! \p keep_H (D and the rest per vertex only with options.keep_vertex_data).
//! With \p second, what it returns is folded in the profile's ring search
//! (the profile's own numbers are the same to the last bit either way).
RoughnessProfile roughness_profile_keeping_H(const Mesh& mesh, const ProfileOptions& options,
                                             const Normalization& frame, bool keep_H,
                                             const SecondFoldHook& second = {});

}  // namespace meshdiff::detail
