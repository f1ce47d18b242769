//! \file corsini.h
//! \brief The multi-scale dihedral-angle roughness of Corsini, Drelie Gelasca,
//! Ebrahimi and Barni ("Watermarked 3-D mesh quality assessment", IEEE TMM
//! 9(2), 2007; WIAMIS 2005), the comparator of the paper's Fig. 1e,f, and its
//! comparison score R(M, M'). METHOD.md section 6a pins the definition and
//! marks which parts are assumptions (the primary text was not available).
//!
//! - Dihedral angle of an edge shared by exactly two non-degenerate faces:
//!   theta_e = the angle between their unit normals, in [0, pi] radians (0 on
//!   a plane). Boundary edges, edges of more than two faces and edges beside a
//!   degenerate face have none.
//! - Scale (ring level) L >= 1 of vertex v: the edges whose two ends both lie
//!   within graph distance L of v (for L = 1: the spokes and the rim of v's
//!   fan). R_L(v) = variance of theta_e over those edges that have an angle.
//! - Roughness of the mesh at scale L: R_L(M) = sum_v A_v R_L(v) / sum_v A_v
//!   over the vertices with an R_L(v) (A_v = one third of the incident face
//!   areas, metric_levels.h vertex_areas()). Global level: the variance of
//!   theta_e over all edges of the mesh (every vertex's neighbourhood is the
//!   whole mesh). Multi-scale roughness: the mean of R_L(M) over the requested
//!   levels.
//!
//! Unit: rad^2. Depends on angles only, so it is invariant to translation,
//! rotation and uniform scaling; no normalisation is applied.
//!
//! Cost: one breadth-first search per vertex to the largest level, visiting
//! each edge of the disk once (about 4,000 edges per vertex at level 20 on a
//! mesh of valence 6; OpenMP over vertices, the result independent of the
//! thread count). Known limit: where the disks cover most of the mesh (a small
//! mesh, or the fan of a vertex of very high valence) the cost is vertices x
//! edges.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/enum_names.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/roughness/roughness_distance.h"

#include <cstddef>
#include <vector>

namespace meshdiff {

//! Which roughness a profile or a comparison reports.
enum class RoughnessMeasure
{
    Sigma,   //!< the paper's curvature-deviation profile sigma_L (roughness.h)
    Corsini  //!< Corsini et al.'s dihedral-angle roughness (this file)
};

template <>
struct EnumNames<RoughnessMeasure>
{
    static constexpr const char* what = "roughness measure";
    static constexpr std::array<EnumName<RoughnessMeasure>, 2> names{
        {{RoughnessMeasure::Sigma, "sigma"}, {RoughnessMeasure::Corsini, "corsini"}}};
};

struct CorsiniOptions
{
    std::vector<int> levels = default_levels();  //!< ring scales, each >= 1, in the order reported
    bool global = true;                          //!< also the global level
    //! Variance with the divisor n - 1 (sample variance) instead of n
    //! (population variance, the default); a neighbourhood of one edge then
    //! has no R_L(v). See METHOD.md section 6a.
    bool unbiased = false;
    bool keep_vertex_data = false;  //!< keep R_L(v) per vertex in the result
};

//! \throw OptionError naming the field for a level outside 1..kMaxLevel, more
//!        than kMaxLevels levels, or no level at all.
void validate(const CorsiniOptions& options);

//! The roughness at one scale.
struct CorsiniLevel
{
    int level = 0;                    //!< ring level; 0 for the global level
    double roughness = 0.0;           //!< R_L(M) in rad^2 (0 if no vertex has an R_L(v))
    std::size_t vertices_used = 0;    //!< vertices with an R_L(v) (and weight A_v > 0)
    std::size_t no_neighborhood = 0;  //!< vertices without an R_L(v): no angle in their neighbourhood
    double mean_edges = 0.0;          //!< mean number of angles in the neighbourhoods used
};

struct CorsiniProfile
{
    CorsiniOptions options{};          //!< as used (levels, global, unbiased)
    std::size_t vertices = 0;          //!< vertices of the mesh
    std::size_t edges = 0;             //!< unique edges of the mesh
    std::size_t dihedral_edges = 0;    //!< edges with a dihedral angle
    double mean_dihedral = 0.0;        //!< mean theta_e over those (rad)
    double max_dihedral = 0.0;         //!< largest theta_e (rad)
    std::vector<CorsiniLevel> levels;  //!< in the order of CorsiniOptions::levels
    bool has_global = false;
    CorsiniLevel global;      //!< level 0
    double multiscale = 0.0;  //!< mean of R_L(M) over levels (0 without levels)
    //! With keep_vertex_data: R_L(v) per level and vertex (NaN where none), in
    //! the order of levels.
    std::vector<std::vector<double>> R;
};

//! The dihedral angle of every unique edge (unique_edges() order), NaN where
//! an edge has none (boundary, non-manifold, beside a degenerate face).
std::vector<double> dihedral_angles(const Mesh& mesh);

//! Corsini et al.'s roughness of \p mesh at each requested scale.
//! \throw InvalidArgumentError for a level < 1 or no level at all (no ring
//!        level and no global).
CorsiniProfile corsini_profile(const Mesh& mesh, const CorsiniOptions& options = {});

//! The comparison score R(M, M') = ln(|R(M') - R(M)| / R(M) + k) - ln(k) of
//! Corsini et al. (the same form as eq. 10, roughness_distance.h, with the
//! same conventions for R(M) = 0), per scale, global and for the multi-scale
//! roughness (Corsini's single score).
struct CorsiniDistance
{
    double k = 1e-4;
    std::vector<LevelDistance> levels;  //!< levels present in both profiles, in the original's order
    bool has_global = false;
    LevelDistance global;
    bool has_multiscale = false;  //!< both profiles have ring levels, and the same ones
    LevelDistance multiscale;     //!< R(M, M') of the multi-scale roughness
};

//! \throw InvalidArgumentError if k <= 0 or not finite.
CorsiniDistance corsini_distance(const CorsiniProfile& original, const CorsiniProfile& processed, double k = 1e-4);

}  // namespace meshdiff
