//! \file normalize.h
//! \brief Unit-sphere scale normalisation of the paper's section 4 (METHOD.md
//! section 2): c = mean vertex position, s = mean |x_i - c|, x' = (x - c) / s,
//! so that the mean distance of the vertices to their centroid is 1.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/enum_names.h"

#include <array>

namespace meshdiff {

//! How a profile scales its mesh before measuring curvature.
enum class NormalizeMethod
{
    Paper,     //!< the paper's: vertex centroid, s = mean vertex distance to it
    Area,      //!< area-weighted centroid, s = sqrt(area / 4 pi) (a unit sphere keeps s = 1)
    Original,  //!< in a comparison: both meshes in the original's frame (the paper's c and s of the original)
};

template <>
struct EnumNames<NormalizeMethod>
{
    static constexpr const char* what = "normalisation";
    static constexpr std::array<EnumName<NormalizeMethod>, 3> names{
        {{NormalizeMethod::Paper, "paper"}, {NormalizeMethod::Area, "area"}, {NormalizeMethod::Original, "original"}}};
};

struct Normalization
{
    NormalizeMethod method = NormalizeMethod::Paper;  //!< how c and s were chosen
    Vec3 center = Vec3::Zero();                       //!< c, the unweighted vertex centroid (input units)
    double scale = 1.0;                               //!< s, the mean distance of the vertices to c (input units)
};

//! Computes c and s of \p mesh (all its vertices).
//! \throw InvalidMeshError if the mesh has no vertices or all of them coincide (s = 0).
Normalization unit_normalization(const Mesh& mesh);

//! The area normalisation: c = the area-weighted centroid of the faces, s =
//! sqrt(total area / 4 pi). Scaling by it does not drift under decimation,
//! which keeps the area while it moves the vertex centroid distance.
//! \throw InvalidMeshError if the mesh has no face of positive area.
Normalization area_normalization(const Mesh& mesh);

//! Returns a copy of \p mesh with x' = (x - c) / s.
Mesh apply_normalization(const Mesh& mesh, const Normalization& n);

}  // namespace meshdiff
