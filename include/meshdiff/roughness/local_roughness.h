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
//!
//! So local_L is 0 for a perfect copy, and as the other mesh loses all
//! detail at the scale of the level (H'(cp) flat over N_L(i)) it approaches
//! this mesh's own area-weighted sigma_L. The first form of this measure
//! (issue 29) compared D_L(i) with the other mesh's D'_L at cp(i), computed
//! on the other mesh's own rings: as a mesh is decimated those span ever
//! larger patches, the two D become uncorrelated and the RMS, near
//! sqrt(sigma_L^2 + sigma'_L^2), falls when sigma'_L falls (README, "Ranking
//! decimations"). Both terms now live on the same neighbourhoods, which also
//! makes the difference linear in F.
//!
//! A comparison pools over the vertices of the original against the
//! processed surface (compare.h): the original is the dense, reference
//! sampling, and the per-vertex values form a map on the original of where
//! detail was lost (> 0 where the original's D_L was positive) or added.
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
    std::size_t vertices = 0;       //!< vertices pooled over (of the first mesh)
    double trim = 0.0;              //!< the share left out of each RMS, as used
    std::vector<std::size_t> used;  //!< vertices with both values, aligned with levels
    //! With keep_vertex_data: F(i) - mean of F over N_L(i) per level (aligned
    //! with levels) and vertex i of the first mesh, NaN where undefined.
    std::vector<std::vector<double>> vertex;
};

//! The local roughness difference of the vertices of \p mesh against the
//! surface of \p other, at the levels, radii and global level present in
//! both profiles. Both profiles must carry their per-vertex H
//! (ProfileOptions::keep_vertex_data); \p other_index is the closest-point
//! index of \p other. \p trim: the share of the vertices with the largest
//! |difference| left out of each RMS (trimmed_rms()), in [0, kMaxTrim].
//! Deterministic at any thread count.
//! \throw InvalidArgumentError if a profile has no per-vertex H or a mesh
//!        does not match its profile.
LocalRoughnessDistance local_roughness_distance(const Mesh& mesh, const RoughnessProfile& profile, const Mesh& other,
                                                const RoughnessProfile& other_profile,
                                                const ClosestPointIndex& other_index, double trim = 0.0,
                                                bool keep_vertex_data = false);

//! Barycentric coordinates of \p p (a point of the triangle's plane) in
//! triangle (a, b, c); for a degenerate triangle, 1 at the corner nearest p.
Vec3 barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace meshdiff
