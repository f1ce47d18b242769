//! \file normalize.h
//! \brief Unit-sphere scale normalisation of the paper's section 4 (METHOD.md
//! section 2): c = mean vertex position, s = mean |x_i - c|, x' = (x - c) / s,
//! so that the mean distance of the vertices to their centroid is 1.
#pragma once

#include "meshdiff/core/mesh.h"

namespace meshdiff {

struct Normalization
{
    Vec3 center = Vec3::Zero();  //!< c, the unweighted vertex centroid (input units)
    double scale = 1.0;          //!< s, the mean distance of the vertices to c (input units)
};

//! Computes c and s of \p mesh (all its vertices).
//! \throw InvalidMeshError if the mesh has no vertices or all of them coincide (s = 0).
Normalization unit_normalization(const Mesh& mesh);

//! Returns a copy of \p mesh with x' = (x - c) / s.
Mesh apply_normalization(const Mesh& mesh, const Normalization& n);

}  // namespace meshdiff
