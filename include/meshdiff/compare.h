//! \file compare.h
//! \brief The comparison of an original and a processed mesh that
//! `meshdiff ORIGINAL PROCESSED` reports: both roughness profiles, the
//! per-level roughness distance (roughness_distance.h) and the Metro-style
//! surface distance (surface_distance.h), with the facts of both meshes. The
//! JSON (schema "meshdiff.compare/2") and text forms are in meshdiff/report/.
#pragma once

#include "meshdiff/core/progress.h"
#include "meshdiff/distance/cloud_distance.h"
#include "meshdiff/distance/hausdorff.h"
#include "meshdiff/distance/same_connectivity.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/geometry/sampling.h"
#include "meshdiff/io/facts.h"
#include "meshdiff/io/io.h"
#include "meshdiff/roughness/corsini.h"
#include "meshdiff/roughness/local_roughness.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/roughness/roughness_distance.h"

#include <optional>
#include <string>
#include <vector>

namespace meshdiff {

struct CompareOptions
{
    ProfileOptions profile{};  //!< levels, global, curvature estimator (same for both meshes)
    double k = 1e-4;           //!< the constant of eq. 10 (an assumption; see METHOD.md 6)
    bool roughness = true;     //!< compute the profiles and their distance
    //! The roughness of the roughness half: the paper's sigma_L profiles
    //! (default), or Corsini et al.'s dihedral-angle roughness (corsini.h) at
    //! profile.levels and globally, and its score R(M, M'); profile.radii must
    //! then be empty and the curvature options are not used.
    RoughnessMeasure measure = RoughnessMeasure::Sigma;
    bool corsini_unbiased = false;  //!< CorsiniOptions::unbiased
    //! With the sigma measure, also the local roughness difference
    //! (local_roughness.h): per ring level and globally, the detail of the
    //! change of H on the processed mesh's own rings, pooled over its
    //! vertices as an RMS (H of the original carried to them at the closest
    //! point); per radius, the same on the original's balls over its vertices.
    bool local = true;
    //! The share of the vertices with the largest |difference| left out of
    //! each local RMS, in [0, kMaxTrim]: a few vertices (open
    //! boundaries, sharp CAD edges, curvature outliers) otherwise decide it.
    //! The default is the decimation study's (reference/README.md): with 0.05
    //! the local RMS grew with decimation on 9 of 12 series at level 1, with 0
    //! on 2.
    double local_trim = 0.05;
    bool distance = true;        //!< compute the surface distance
    SamplingOptions sampling{};  //!< surface sampling (Metro defaults)
    //! Certify both one-sided Hausdorff distances (hausdorff.h) with these
    //! options, the lower bounds seeded with the sampled maxima; std::nullopt
    //! keeps the sampled maximum only (`--hausdorff sampled`).
    std::optional<HausdorffOptions> hausdorff = HausdorffOptions{};
    //! Also the exact distance of every vertex of the processed mesh to the
    //! original surface and of the original to the processed one
    //! (Comparison::processed_vertex_distance, original_vertex_distance), for
    //! distance maps; it reuses the indexes of the surface distance.
    bool vertex_distances = false;
    //! F-score thresholds and histogram bins of the surface distance (the
    //! area-weighted means, Chamfer and PSNR are always computed).
    SummaryOptions summary{};
    //! Keep the samples of both directions and their distances
    //! (Comparison::forward_samples, backward_samples; about 50 bytes per
    //! sample and direction), e.g. for sample_cloud.h.
    bool keep_samples = false;
    //! Reports every stage (curvature, rings, metric levels, index, sampling,
    //! distances, certification) and stops the comparison with Cancelled when
    //! it says so (progress.h); not owned, used only during the call.
    //! nullptr: the Progress of the calling thread's ProgressScope, if any.
    Progress* progress = nullptr;
    //! Indexes of the original and of the processed mesh that the caller
    //! built and keeps (DistanceOptions::index_a, index_b), e.g. to compare
    //! one original with many processed meshes: the surface distance and the
    //! local roughness difference query them instead of building their own.
    //! Each must index that very mesh and outlive the call; the results are
    //! the same bit for bit. nullptr (the default): built per call (the
    //! original's once, for the local difference and the distances).
    const ClosestPointIndex* index_original = nullptr;
    const ClosestPointIndex* index_processed = nullptr;
};

//! The result of compare_meshes(). With CompareOptions::vertex_distances, the
//! VertexDistances (surface_distance.h): per vertex of the processed mesh its
//! exact distance to the original surface (processed_vertex_distance), of
//! the original to the processed one (original_vertex_distance), and the
//! signed ones (positive outside the other surface) where the other mesh can
//! be signed against; else empty.
struct Comparison : VertexDistances
{
    MeshFacts original;
    MeshFacts processed;
    CompareOptions options;
    std::optional<RoughnessProfile> original_profile;
    std::optional<RoughnessProfile> processed_profile;
    std::optional<RoughnessDistance> roughness;
    //! With CompareOptions::local (sigma measure): the local roughness
    //! difference (ring levels and global over the processed mesh's
    //! vertices, radii over the original's); per-vertex maps of the ring
    //! levels, on the processed mesh, kept with vertex_distances.
    std::optional<LocalRoughnessDistance> local_roughness;
    //! With RoughnessMeasure::Corsini, instead of the three above.
    std::optional<CorsiniProfile> original_corsini;
    std::optional<CorsiniProfile> processed_corsini;
    std::optional<CorsiniDistance> corsini;
    //! The surface distance; its VertexDistances and kept samples are moved
    //! to the comparison's own.
    std::optional<SurfaceDistance> distance;
    //! Displacement and normal deviation when both meshes have the same
    //! connectivity (same_connectivity.h); else std::nullopt and the reason.
    std::optional<SameConnectivity> same_connectivity;
    std::string same_connectivity_unavailable;
    //! With CompareOptions::keep_samples: the samples of the original
    //! (forward) and of the processed mesh (backward) and their distances.
    SampledDirection forward_samples;
    SampledDirection backward_samples;
    //! Why the roughness half asked for was skipped (an input is a point
    //! cloud: roughness needs faces on both sides); empty otherwise.
    std::string roughness_unavailable;
};

//! The rules of CompareOptions, each refusal an OptionError naming the field
//! (error.h, options.h): not both halves off; k finite and > 0; a known
//! measure; corsini_unbiased only with the Corsini measure, which takes no
//! radii; and validate() of the profile, sampling, Hausdorff and summary
//! options.
void validate(const CompareOptions& options);

//! Runs the halves asked for in \p options.
//! Either input may be a point cloud (a mesh without faces, as
//! read_mesh_or_cloud() returns it): the surface distance is then
//! cloud_surface_distance(); the roughness half, the same-connectivity metrics
//! need faces on both sides and are skipped with the reason
//! (Comparison::roughness_unavailable, same_connectivity_unavailable). The
//! facts of a cloud are its point count and bounding box (area 0, no topology).
//! \throw OptionError for bad options (validate()); InvalidArgumentError for
//!        a cloud with distance off (nothing left to compare).
Comparison compare_meshes(const LoadedMesh& original, const LoadedMesh& processed, const CompareOptions& options = {});

}  // namespace meshdiff
