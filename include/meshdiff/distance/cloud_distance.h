//! \file cloud_distance.h
//! \brief Surface distances when one or both inputs are point clouds (a file
//! with vertices and no faces, read by read_mesh_or_cloud()); METHOD.md
//! section 6, "Point clouds".
//!
//! A point cloud is a Mesh with points and no faces. Forward is A -> B, as in
//! surface_distance.h: the samples of A, each with its distance to B.
//! - A cloud on the sampled side: the samples are its points, every one once
//!   (SampleKind::OnPoint, element = the point's index; the sampling options
//!   do not apply to it), in file order.
//! - A mesh on the sampled side: sampled as in surface_distance.h (vertices,
//!   edges, faces). An unset target is Metro's 10 x max(#faces A, #faces B)
//!   with every point of a cloud counted as a face: 10 x max(#faces of the
//!   mesh, #points of the cloud), so that a mesh is sampled at least as
//!   densely as the cloud it is measured against.
//! - The distance to a mesh is the exact point-to-triangle distance
//!   (closest_point.h): "point-to-surface" from a cloud (CloudCompare's
//!   cloud-to-mesh distance). The distance to a cloud is the distance to its
//!   nearest point (a k-d tree, nanoflann, exact search): "surface-to-point"
//!   from a mesh, "point-to-point" from a cloud (cloud-to-cloud).
//!
//! Hausdorff. With a cloud on the sampled side the maximum over its points is
//! the exact one-sided Hausdorff distance of the cloud (a finite set): it is
//! reported as certified with lower = upper = the maximum (no subdivision).
//! With a mesh sampled against a cloud the maximum over the samples is a
//! sampled lower bound (not certified; the certification of hausdorff.h needs
//! triangles on the target side).
//!
//! Summary metrics. A cloud direction has no areas: its "area-weighted"
//! statistics weight every point equally (the plain mean over the points, as
//! CloudCompare and Open3D report cloud distances, and as the F-score of
//! Tanks and Temples counts points); n_face and area are 0, area_fraction 1.
//! A mesh direction keeps its area weights. Chamfer, F-score and PSNR are then
//! formed as in surface_distance.h.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/distance/distance_kind.h"
#include "meshdiff/distance/hausdorff.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/geometry/sampling.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace meshdiff {

//! The kind of the direction that samples a cloud (\p from_cloud) or a mesh,
//! against a cloud (\p to_cloud) or a mesh.
DistanceKind distance_kind(bool from_cloud, bool to_cloud);

//! A k-d tree over points (nanoflann) for exact nearest-neighbour distances.
//! Keeps its own copy of the points. Queries are const and thread-safe.
class PointCloudIndex
{
public:
    //! \throw InvalidMeshError if \p points is empty or a coordinate is not finite.
    explicit PointCloudIndex(const std::vector<Vec3>& points);
    ~PointCloudIndex();
    PointCloudIndex(PointCloudIndex&&) noexcept;
    PointCloudIndex& operator=(PointCloudIndex&&) noexcept;
    PointCloudIndex(const PointCloudIndex&) = delete;
    PointCloudIndex& operator=(const PointCloudIndex&) = delete;

    struct Nearest
    {
        std::uint32_t index = 0;  //!< a nearest point (any of them on ties)
        double distance = 0.0;    //!< (q - points[index]).norm()
    };
    //! A nearest point of \p q.
    Nearest nearest(const Vec3& q) const;
    //! The nearest-point distance of every query, in parallel (OpenMP); the
    //! values do not depend on the thread count.
    std::vector<double> distances(const std::vector<Vec3>& queries) const;
    std::size_t size() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

//! The samples of a cloud: every point once, in order, kind OnPoint, element
//! the point's index (n_vertex = n_edge = n_face = 0, target = the size).
SurfaceSamples cloud_samples(const Mesh& cloud);

//! surface_distance() where \p a, \p b or both may be point clouds (no faces);
//! the same options and result fields, with the conventions of the file
//! comment. For a cloud direction, DistanceStats::n_point counts its points.
//! With options.vertex_distances, original_vertex_distance
//! (processed_vertex_distance) holds per vertex (point) of A (B) its distance
//! to the other side, as the direction measures it. With options.hausdorff, a cloud-sampled direction
//! gets its exact maximum as a certified interval [max, max] (location.face:
//! the point's index; location.closest_face: the face of a mesh target, or the
//! index of the nearest point of a cloud target); a mesh sampled against a
//! cloud gets none (sampled only).
//! \throw InvalidArgumentError for invalid options, or if the options give no
//!        sample on a mesh side.
//! \throw InvalidMeshError if a mesh is invalid, or a cloud is empty or has a
//!        non-finite coordinate.
SurfaceDistance cloud_surface_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options = {});

//! Deprecated, removed in 0.3: cloud_surface_distance(a, b, DistanceOptions),
//! with the arguments of the deprecated surface_distance() overload
//! (surface_distance.h). The results are the same bit for bit.
SurfaceDistance cloud_surface_distance(const Mesh& a, const Mesh& b, const SamplingOptions& options,
                                       bool vertex_distances = false,
                                       const std::optional<HausdorffOptions>& certify = std::nullopt,
                                       const SummaryOptions& summary = {}, SampledDirection* forward_samples = nullptr,
                                       SampledDirection* backward_samples = nullptr);

}  // namespace meshdiff
