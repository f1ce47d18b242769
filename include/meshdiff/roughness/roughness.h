//! \file roughness.h
//! \brief The multi-level roughness profile of Kushunapally, Razdan & Bridges,
//! "Roughness as a Shape Measure", CAD&A 4(1-4), 2007, eqs. 7-9 (METHOD.md
//! sections 2-5).
//!
//! The mesh is scaled so that the mean distance of its vertices to their
//! centroid is 1 (normalize.h); H is estimated per vertex (curvature.h);
//! D_L(i) = H(i) - mean of H over N_L(i) (neighborhood.h; the centre is
//! excluded); sigma_L = sqrt(mean over i of D_L(i)^2). The global level uses
//! all other vertices of the mesh: D_G(i) = H(i) - mean of H(j), j != i.
//! Vertices with undefined H are excluded from every mean and from the RMS;
//! a vertex whose N_L holds no vertex with defined H has no D_L (counted).
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/progress.h"
#include "meshdiff/geometry/normalize.h"
#include "meshdiff/roughness/curvature.h"

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace meshdiff {

//! Levels 1..20, the default of the paper's plots.
std::vector<int> default_levels();

//! The most levels one profile takes (each keeps a value per vertex), and the
//! largest level.
constexpr std::size_t kMaxLevels = 200;
constexpr int kMaxLevel = 100'000;

//! A level where more than this share of the vertices with curvature have no
//! neighbourhood warns (sigma then speaks for the others only).
constexpr double kSparseNeighbourhoodShare = 0.1;

//! The largest share ProfileOptions::trim may leave out.
constexpr double kMaxTrim = 0.25;

//! Most bootstrap resamples ProfileOptions::bootstrap takes (the work is
//! resamples x vertices per level).
constexpr std::size_t kMaxBootstrap = 10'000;

//! Coverage of the bootstrap interval of sigma: the 2.5th and 97.5th
//! percentiles of the resampled sigmas.
constexpr double kBootstrapConfidence = 0.95;

struct ProfileOptions
{
    std::vector<int> levels = default_levels();  //!< ring levels, each >= 1, in the order reported
    //! The scaling before curvature (normalize.h): the paper's by default.
    //! Original is for comparisons only (compare.h); roughness_profile()
    //! refuses it without a frame.
    NormalizeMethod normalize = NormalizeMethod::Paper;
    bool global = true;               //!< also compute the global level
    CurvatureOptions curvature{};     //!< estimator of H
    bool keep_vertex_data = false;    //!< keep H and D per vertex in the result
    double outlier_fraction = 0.001;  //!< share of vertices in the top-|D| diagnostic
    //! Trimmed sigma: the share of the vertices with the largest |D| left out
    //! of sigma at every level (ceil(trim x count) of them), so that a few
    //! bad vertices cannot decide it; in [0, kMaxTrim]. 0 (the default): the
    //! paper's sigma over all vertices. The local roughness difference of a
    //! comparison is trimmed by the same share.
    double trim = 0.0;
    //! Metric levels (metric_levels.h, METHOD.md section 5a): radii on the
    //! normalised mesh, each finite and > 0, in the order reported. Empty by
    //! default (default_radii() is what `--radii default` asks for).
    std::vector<double> radii{};
    //! Bootstrap interval of sigma at every level: this many resamples of the
    //! vertices used (with replacement; the trim and the area weights of
    //! metric levels applied to each), the interval between the 2.5th and
    //! 97.5th percentiles of their sigmas (LevelRoughness::sigma_interval).
    //! It shows how much of a difference between two sigmas the sampling of
    //! the surface by its vertices alone could make. 0 (the default): none;
    //! at most kMaxBootstrap.
    std::size_t bootstrap = 0;
    //! Seed of the resamples: the same seed, the same interval, at any thread count.
    std::uint64_t bootstrap_seed = 1;
    //! The paper's exact method (Kushunapally et al. 2007): the
    //! Goldfeather-Interrante cubic fit without row weights, the paper's
    //! normalisation and sigma over all vertices. Set it with
    //! paper_profile_options(); validate() refuses another estimator, a row
    //! weighting, another normalisation or a trim beside it. Levels, radii,
    //! the global level and the bootstrap stay free.
    bool paper = false;
    //! Reports the stages (curvature, rings, metric levels) and stops the
    //! computation with Cancelled when it says so (progress.h); not owned.
    //! nullptr: the Progress of the calling thread's ProgressScope, if any.
    Progress* progress = nullptr;
};

//! sigma and its counts at one level.
struct LevelRoughness
{
    int level = 0;                    //!< ring level; 0 for the global level and for metric levels
    double radius = 0.0;              //!< radius of a metric level; 0 for ring levels and the global level
    double sigma = 0.0;               //!< RMS of D over the vertices used (0 if none)
    std::size_t vertices_used = 0;    //!< vertices with a defined D
    std::size_t no_neighborhood = 0;  //!< vertices with defined H but no defined H in N_L
    //! Share of sigma^2 contributed by the outlier_fraction of vertices with
    //! the largest |D| (at least one vertex). Near outlier_fraction for a
    //! well-spread roughness; above 0.5 means a few vertices dominate sigma.
    double top_share = 0.0;
    std::vector<std::uint32_t> worst_vertices;  //!< the ids of those vertices, largest |D| first (at most 10)
    std::size_t trimmed = 0;                    //!< vertices left out of sigma by ProfileOptions::trim
    //! With ProfileOptions::bootstrap: the kBootstrapConfidence interval of
    //! sigma over the resamples (lo, hi); unset without it or without data.
    std::optional<std::pair<double, double>> sigma_interval;
};

struct RoughnessProfile
{
    Normalization normalization;                           //!< c and s of the unit-sphere scaling
    std::size_t vertices = 0;                              //!< vertices of the mesh
    CurvatureOptions curvature_options{};                  //!< as used
    std::size_t curvature_undefined = 0;                   //!< vertices with undefined H
    std::size_t curvature_widened = 0;                     //!< fits widened to the 2-ring
    std::size_t curvature_normal_rows_dropped = 0;         //!< CurvatureField::normal_rows_dropped
    std::size_t curvature_fallback = 0;                    //!< cubic fits that fell back to the quadric
    std::size_t curvature_steep = 0;                       //!< CurvatureField::steep (jet fits)
    std::size_t curvature_capped = 0;                      //!< 2-ring neighbourhoods capped (CurvatureField::capped)
    std::vector<std::uint32_t> curvature_capped_vertices;  //!< the lowest ids of those (at most 10)
    double outlier_fraction = 0.001;                       //!< ProfileOptions::outlier_fraction as used (top_share)
    double trim = 0.0;                                     //!< ProfileOptions::trim as used
    std::size_t bootstrap = 0;                             //!< ProfileOptions::bootstrap as used
    std::uint64_t bootstrap_seed = 1;                      //!< ProfileOptions::bootstrap_seed as used
    std::vector<LevelRoughness> levels;                    //!< in the order of ProfileOptions::levels
    bool has_global = false;
    LevelRoughness global;  //!< level 0
    //! Metric levels, in the order of ProfileOptions::radii: area-weighted
    //! sigma_r (LevelRoughness::radius set, level 0). Empty unless asked for.
    std::vector<LevelRoughness> radii;

    //! Per vertex, only with keep_vertex_data: H on the normalised mesh, and D
    //! for each level (NaN where undefined), D_global last if has_global.
    std::vector<double> H;
    std::vector<std::vector<double>> D;
    std::vector<double> D_global;
    std::vector<std::vector<double>> D_radii;  //!< D_r per metric level, in the order of radii
};

//! \throw OptionError naming the field for a level outside 1..kMaxLevel, more
//!        than kMaxLevels levels, a radius outside (0, kMaxRadius] or more
//!        than kMaxRadii (check_radii()), no level at all (no ring level, no
//!        radius, no global), an unknown curvature method or weighting, or an
//!        outlier_fraction outside (0, 1].
void validate(const ProfileOptions& options);

//! \p base with the paper's exact method (ProfileOptions::paper): paper set,
//! the goldfeather fit, no row weighting, the paper's normalisation, no trim;
//! every other field as in \p base. The front ends' `--paper` / `paper=True`
//! start from it, so a flag given beside it that contradicts it is refused
//! by validate().
ProfileOptions paper_profile_options(ProfileOptions base = {});

//! The roughness profile of \p mesh (any position and scale: it is
//! normalised first).
//! \throw OptionError as validate().
//! \throw InvalidMeshError for a mesh without extent.
RoughnessProfile roughness_profile(const Mesh& mesh, const ProfileOptions& options = {});

//! The roughness profile of \p mesh scaled by \p frame (c and s given, e.g.
//! the original's in a comparison) instead of its own normalisation.
//! \throw OptionError as validate().
RoughnessProfile roughness_profile(const Mesh& mesh, const ProfileOptions& options, const Normalization& frame);

//! The normalisation of \p mesh that \p method asks for (Paper or Area).
//! \throw OptionError("profile.normalize") for Original, which needs the
//!        original's frame (a comparison).
//! \throw InvalidMeshError for a mesh without extent (or area).
Normalization normalization_of(const Mesh& mesh, NormalizeMethod method);

//! The profile of \p mesh with H given per vertex (in the mesh's own units,
//! NaN = undefined) instead of estimated: for example the exact H of an
//! analytic surface, to set the true profile beside the estimated one. H is
//! scaled by s to the normalised mesh. options.curvature is ignored.
//! \throw InvalidArgumentError if H has the wrong size.
RoughnessProfile roughness_profile_from_curvature(const Mesh& mesh, const std::vector<double>& H,
                                                  const ProfileOptions& options = {});

//! A profile computed from an exact H beside an estimated one.
struct ExactProfile
{
    RoughnessProfile profile;  //!< the profile of the exact H (with vertex data: H on the normalised mesh)
    CurvatureError h_error;    //!< the error of the estimated H against the exact one, on the normalised mesh
    //! The same error over the interior vertices and over the boundary ones
    //! (boundary_vertex_mask(): on a boundary or non-manifold edge) apart:
    //! fits are one-sided at the boundary and converge more slowly there.
    CurvatureError h_error_interior;
    CurvatureError h_error_boundary;
};

//! The profile of \p mesh from \p exact_H (roughness_profile_from_curvature()
//! with vertex data kept) and the error of \p estimated's H against it.
//! \throw InvalidArgumentError if \p estimated was computed without
//!        keep_vertex_data or \p exact_H has the wrong size.
ExactProfile exact_profile(const Mesh& mesh, const std::vector<double>& exact_H, const ProfileOptions& options,
                           const RoughnessProfile& estimated);

//! The bootstrap interval of the (trimmed, weighted) RMS of \p D over its
//! defined values: \p resamples resamples with replacement, each drawn from
//! its own splitmix64 stream of \p seed (so the result is the same at any
//! thread count), the trim and \p weights applied to each; the 2.5th and
//! 97.5th percentiles of their RMS (nearest rank). Unset without resamples or
//! without a defined value. Exposed for tests.
std::optional<std::pair<double, double>> bootstrap_interval(const std::vector<double>& D, double trim,
                                                            std::size_t resamples, std::uint64_t seed,
                                                            const std::vector<double>* weights = nullptr);

//! sigma of one level computed from D values (NaN skipped), with the counts
//! and the outlier diagnostic. Exposed for tests and for other D sources.
LevelRoughness level_roughness(int level, const std::vector<double>& D, double outlier_fraction = 0.001);

//! The RMS of the values of \p D (NaN skipped) without the ceil(trim x count)
//! of largest magnitude, weighted by \p weights when given (then
//! sqrt(sum w D^2 / sum w) over the vertices kept); NaN if none is kept.
//! \param dropped set to the number left out
double trimmed_rms(const std::vector<double>& D, double trim, const std::vector<double>* weights = nullptr,
                   std::size_t* dropped = nullptr);

}  // namespace meshdiff
