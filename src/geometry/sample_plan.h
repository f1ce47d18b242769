// The samples of sample_surface() (meshdiff/geometry/sampling.h) in two steps: the
// counts per vertex, edge and face are decided first (plan_samples()), then
// SampleMaker makes the samples of any range of sample indices, so that a
// caller can take the samples a range at a time (the surface distance does,
// in bounded memory) and get exactly the samples of sample_surface().
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/topology.h"
#include "meshdiff/geometry/sampling.h"

#include "core/release.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace meshdiff::detail {

struct SamplePlan
{
    //! The counts, target and densities; no samples (points, kind, element empty).
    SurfaceSamples counts;
    std::vector<std::uint32_t> vertices;  //!< the vertex samples' vertices, in sample order
    std::vector<Edge> edges;              //!< the unique edges (with edge samples on)
    // The offsets are 32-bit: a plan has at most a mesh's vertices (below
    // 2^31) and kMaxSamples more samples (plan_samples() checks it).
    std::vector<std::uint32_t> edge_offset;  //!< first sample of each edge, then the end (edges + 1)
    std::vector<std::uint32_t> face_order;   //!< lattice order k of each face (SimilarTriangles)
    std::vector<std::uint32_t> face_offset;  //!< first sample of each face, then the end (faces + 1; or empty)
    FaceSampling scheme = FaceSampling::SimilarTriangles;
    std::uint64_t seed = 1;

    std::size_t size() const { return counts.n_vertex + counts.n_edge + counts.n_face; }
    //! Frees the vertex and edge lists: only face samples can be made after.
    void drop_vertices_and_edges()
    {
        detail::release(vertices);
        detail::release(edges);
        detail::release(edge_offset);
    }
    //! The samples before \p made are made and will not be made again: the
    //! memory pages of the vertex and edge lists wholly before them are given
    //! back (discard_front(); the lists are read only for the samples being
    //! made, the offsets kept whole). \p made only grows between calls.
    void discard_made(std::size_t made)
    {
        const std::size_t v = std::min(made, vertices.size());
        discard_front(vertices.data(), vertices.data() + v, vertices_done_);
        if (edges.empty()) return;
        // The edges whose samples all lie before `made`.
        const auto e =
            std::size_t(std::upper_bound(edge_offset.begin() + 1, edge_offset.end(), made) - (edge_offset.begin() + 1));
        discard_front(edges.data(), edges.data() + std::min(e, edges.size()), edges_done_);
    }

private:
    std::size_t vertices_done_ = 0, edges_done_ = 0;  // discard_made()'s progress, in bytes
};

//! The counts of sample_surface(mesh, options), options and mesh valid
//! (checks for cancellation in between, as sample_surface() does).
SamplePlan plan_samples(const MeshData& data, const SamplingOptions& options);

//! Makes the samples of a plan, a range of sample indices at a time. The
//! MonteCarlo points come from one random stream drawn in sample order:
//! ranges taken in increasing order cost no more than one pass.
class SampleMaker
{
public:
    SampleMaker(const Mesh& mesh, const SamplePlan& plan);
    //! Samples [begin, end) (end <= plan.size()) into points, kind and
    //! element [0, end - begin), bit for bit those of sample_surface().
    void make(std::size_t begin, std::size_t end, Vec3* points, SampleKind* kind, std::uint32_t* element);

private:
    const Mesh& mesh_;
    const SamplePlan& plan_;
    std::mt19937_64 rng_;
    std::size_t drawn_ = 0;  // the face sample (sample index) the random stream is at
};

}  // namespace meshdiff::detail
