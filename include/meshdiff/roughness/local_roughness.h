//! \file local_roughness.h
//! \brief The local roughness difference of two profiles: the detail at
//! level L of the change of mean curvature, on one mesh's own neighbourhoods.
//!
//! The other mesh's H' is carried to every vertex i of this mesh: H'(cp(i)),
//! cp(i) the closest point of the other surface to i, H' interpolated
//! linearly over the triangle holding it. The change of H there is
//!
//!   F(i) = H(i) - H'(cp(i)),
//!
//! and this mesh's own level-L operator is applied to F, as the profile
//! applies it to H (roughness.h, metric_levels.h):
//!
//!   D_L(i) - D~'_L(i) = F(i) - mean of F over N_L(i),
//!   local_L = sqrt( sum over i of A_i (F(i) - mean_{N_L(i)} F)^2 / sum A_i ),
//!
//! where D~'_L(i) = H'(cp(i)) - mean over N_L(i) of H'(cp(j)) is the other
//! mesh's detail read on this mesh's rings, A_i this mesh's vertex areas
//! (vertex_areas(), on its normalised mesh) and the sums run over the
//! vertices with a defined F and a neighbour with one (trimmed by
//! trimmed_rms()). N_L is the ring level L of this mesh (neighborhood.h), the
//! global level uses all other vertices, a metric level the ball of radius r
//! on this mesh's normalised mesh with area-weighted means (metric_levels.h).
//! Both terms live on the same neighbourhoods, so the difference is linear
//! in F and 0 for a perfect copy.
//!
//! A comparison (compare.h) takes "this mesh" as follows:
//! - **Ring levels and the global level: the processed mesh** (its vertices,
//!   its L-rings, its areas), against the original surface. Level L means
//!   each mesh's own L-ring, as in the profiles and eq. 10; a decimated
//!   mesh's L-ring spans a larger patch, so the original's detail inside it,
//!   which the coarse mesh cannot carry, grows with the decimation. This is
//!   the form that ranks decimations: on the 20 series of the decimation
//!   study (README, "Ranking decimations") it grows strictly at levels 1, 2
//!   and 5 on all 20 (the original's rings: 16, 15 and 18; the larger of the
//!   two: 20, 20, 18).
//! - **Metric levels (radii): the original** (its vertices and balls),
//!   against the processed surface: a radius is the same patch on both
//!   meshes, the original samples it densest, and a decimated mesh's small
//!   balls hold too few vertices (the processed mesh's balls: 14, 17 and 18 of
//!   20 at r = 0.05, 0.1, 0.2; the original's: 17, 18, 19).
//! On the original's rings the measure saturates: once all detail at the
//! level's scale is lost it approaches the original's own sigma_L, and the
//! processed mesh's curvature noise read on those rings then shrinks as the
//! mesh coarsens (the form of 2026-12-05). The first form (issue 29)
//! compared D_L(i) with the other mesh's D'_L at cp(i) computed on its own
//! rings, which become uncorrelated and fall with sigma'_L.
//!
//! Unlike eq. 10, which sees only |sigma'_L - sigma_L|, this measure cannot
//! let two changes cancel (coarser rings raising sigma while lost detail
//! lowers it). H is in the units of each profile's normalised mesh (with
//! CompareOptions::normalize = Original both are the original's).
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/roughness/roughness.h"

#include <cstddef>
#include <vector>

namespace meshdiff {

struct LocalRoughnessDistance
{
    std::vector<int> levels;        //!< ring levels present in both profiles, in the first profile's order
    std::vector<double> rms;        //!< local_L aligned with levels (NaN: no vertex with data)
    std::vector<double> radii;      //!< metric levels present in both profiles
    std::vector<double> rms_radii;  //!< local_r aligned with radii (NaN: no data)
    bool has_global = false;        //!< both profiles have the global level
    double global = 0.0;            //!< local_G (NaN: no data)
    std::size_t vertices = 0;       //!< vertices pooled over at the levels and globally (of the first mesh)
    //! Vertices pooled over at the radii: the first mesh's here (0 when
    //! LocalRoughnessParts::radii is off); a comparison's radii come from the
    //! original (compare.h), 0 without radii.
    std::size_t vertices_radii = 0;
    double trim = 0.0;              //!< the share left out of each RMS, as used
    std::vector<std::size_t> used;  //!< vertices with both values, aligned with levels
    //! With keep_vertex_data: F(i) - mean of F over N_L(i) per level (aligned
    //! with levels) and vertex i of the first mesh, NaN where undefined.
    std::vector<std::vector<double>> vertex;
};

//! Which parts local_roughness_distance() computes.
struct LocalRoughnessParts
{
    bool levels = true;  //!< the ring levels present in both profiles
    bool global = true;  //!< the global level, if both profiles have it
    bool radii = true;   //!< the metric levels present in both profiles
};

//! The local roughness difference of the vertices of \p mesh against the
//! surface of \p other, at the levels, radii and global level present in
//! both profiles (those of \p parts). Both profiles must carry their per-vertex H
//! (ProfileOptions::keep_vertex_data); \p other_index is the closest-point
//! index of \p other. \p trim: the share of the vertices with the largest
//! |difference| left out of each RMS (trimmed_rms()), in [0, kMaxTrim].
//! Deterministic at any thread count.
//! \throw InvalidArgumentError if a profile has no per-vertex H or a mesh
//!        does not match its profile.
LocalRoughnessDistance local_roughness_distance(const Mesh& mesh, const RoughnessProfile& profile, const Mesh& other,
                                                const RoughnessProfile& other_profile,
                                                const ClosestPointIndex& other_index, double trim = 0.0,
                                                bool keep_vertex_data = false, LocalRoughnessParts parts = {});

//! Barycentric coordinates of \p p (a point of the triangle's plane) in
//! triangle (a, b, c); for a degenerate triangle, 1 at the corner nearest p.
Vec3 barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace meshdiff
