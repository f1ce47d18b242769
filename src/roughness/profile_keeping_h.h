//! \file profile_keeping_h.h (detail)
//! \brief A roughness profile that keeps H per vertex but not D: what the
//! local roughness difference needs of a comparison's two profiles.
#pragma once

#include "meshdiff/roughness/roughness.h"

namespace meshdiff::detail {

//! roughness_profile(mesh, options, frame), keeping RoughnessProfile::H when
//! \p keep_H (D and the rest per vertex only with options.keep_vertex_data).
RoughnessProfile roughness_profile_keeping_H(const Mesh& mesh, const ProfileOptions& options,
                                             const Normalization& frame, bool keep_H);

}  // namespace meshdiff::detail
