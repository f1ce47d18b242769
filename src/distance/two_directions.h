// The two-direction driver of surface_distance() and cloud_surface_distance()
// (one orchestration for meshes and point clouds), and the cloud parts of a
// direction it uses (cloud_distance.cpp).
#pragma once

#include "meshdiff/distance/cloud_distance.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/geometry/closest_point.h"

#include "distance/surface_distance_chunks.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace meshdiff::detail {

//! What a caller of two_directions() already has of the backward direction
//! (compare_meshes(): the local difference's), handed over so that it is not
//! made twice nor held beside B's index: an index of A (when it holds one;
//! DistanceOptions::index_a then unset), on which the backward direction runs
//! first, and the closest points of B's vertices on A (when of B's vertex
//! count: those of an index of A, ClosestPointIndex::closest_points()), which
//! the certification of that direction uses. Each is freed once used. The
//! results are those without, to the last bit: the two directions are
//! independent, and a closest point does not depend on the index.
struct HandedToDistance
{
    std::optional<ClosestPointIndex> index_a;
    std::vector<ClosestPoint> b_vertices_on_a;
    //! When set, called in each direction between two meshes (samples not
    //! kept) once its sample plan and pseudo-normals are made: the caller,
    //! which owns both meshes' MeshData, frees their vertex-face incidences
    //! there (detail::release_vertex_faces(); nothing reads them while the
    //! samples are queried, and the next direction derives them again).
    std::function<void()> release_incidences;
};

//! Both directions of a surface distance: checks the options and both inputs,
//! sets the default budget (10 x max(#faces A, #faces B), a cloud's points
//! counted as faces), the reference diagonal and the absolute F-score
//! thresholds, measures the forward (samples of A to B) and the backward
//! direction (samples of B to A), and forms the Hausdorff distance, the
//! diagonals, the summary metrics, the F-scores and the distance kinds. With
//! \p clouds an input without faces is a point cloud (cloud_distance.h);
//! without, every input is a mesh (validate()). The samples of the forward
//! (backward) direction are kept with \p keep_forward (\p keep_backward);
//! otherwise, between two meshes, they are made and queried \p chunk at a
//! time (a positive multiple of kQueryBlock). What the caller hands over
//! (\p handed) is used and freed (see HandedToDistance).
SurfaceDistance two_directions(const Mesh& a, const Mesh& b, const DistanceOptions& options, bool keep_forward,
                               bool keep_backward, bool clouds, std::size_t chunk = kSampleChunk,
                               HandedToDistance* handed = nullptr);

//! \p r as the deprecated positional overloads return it: the per-vertex
//! distances under their 0.2 names (a_/b_vertex_distance and the signed
//! pair), the samples moved to \p forward_samples and \p backward_samples
//! (when given).
SurfaceDistance deprecated_result(SurfaceDistance r, SampledDirection* forward_samples,
                                  SampledDirection* backward_samples);

//! Throws InvalidMeshError (\p what in the message) if \p cloud has no point
//! or a non-finite coordinate.
void check_cloud(const Mesh& cloud, const std::string& what);

//! The "area-weighted" statistics of a cloud direction: every point of weight
//! 1 (cloud_distance.h), and in \p within the shares below the absolute
//! \p thresholds.
AreaWeightedStats point_weighted_stats(const std::vector<double>& distances, const std::vector<double>& thresholds,
                                       std::vector<double>& within);

//! A direction with a point cloud on one side, its samples all kept: the
//! points of a cloud (\p from_cloud) or the samples of a mesh, each with its
//! unsigned distance to the mesh indexed by \p index or the cloud indexed by
//! \p cloud (the other null).
SampledDirection cloud_direction(const Mesh& from, bool from_cloud, const ClosestPointIndex* index,
                                 const PointCloudIndex* cloud, const SamplingOptions& options);

//! The exact one-sided Hausdorff distance of a cloud of \p n_points points (a
//! finite set) to \p to (indexed by \p index or \p cloud): the maximum of
//! \p s, as a certified interval [max, max] with its location.
CertifiedHausdorff exact_over_points(const Mesh& to, const ClosestPointIndex* index, const PointCloudIndex* cloud,
                                     const DistanceStats& s, std::size_t n_points);

}  // namespace meshdiff::detail
