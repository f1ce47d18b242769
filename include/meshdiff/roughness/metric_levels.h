//! \file metric_levels.h
//! \brief Metric levels: neighbourhoods of a physical radius on the
//! unit-scaled mesh, with area weights (METHOD.md section 5a).
//!
//! N_r(v) = { j != v : j is joined to v by a path of mesh edges whose vertices
//! all lie in the closed ball B(p_v, r) }, on the normalised mesh. Each vertex
//! is weighted by its share of surface area, A_j = one third of the area of its
//! incident faces, so that the means and sigma_r converge as the mesh is
//! refined, where ring levels (neighborhood.h) measure a scale that shrinks
//! with the edge length.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/mesh_data.h"
#include "meshdiff/core/topology.h"
#include "meshdiff/geometry/vertex_areas.h"  // vertex_areas() was declared here until 0.2
#include "meshdiff/roughness/roughness.h"

#include <cstdint>
#include <vector>

namespace meshdiff {

//! The radii of `--radii default`: 0.0125 * 2^(k/2), k = 0..8 (0.0125 ...
//! 0.2), geometric: from the edge length of a fine scan (igea, 134K vertices)
//! to the extent of its ring level 20 (METHOD.md section 5a explains the
//! choice and its upper bound, set by the cost).
std::vector<double> default_radii();

//! The most radii one profile takes (each keeps a value per vertex), and the
//! largest radius (on the unit-scaled mesh, whose mean vertex distance to the
//! centroid is 1: far larger than any mesh).
constexpr std::size_t kMaxRadii = 64;
constexpr double kMaxRadius = 1000.0;

//! The most vertices a ball of the largest radius may hold on average: the
//! metric levels' work, about n times that, stays proportional to the mesh
//! (a radius far beyond the mesh, such as 1000, makes every ball the whole
//! mesh: n^2). The default radii hold about 1% of a closed unit-scaled mesh.
constexpr std::size_t kMaxMeanBallVertices = 100'000;

//! Estimates the mean ball size of the largest of \p radii on the unit-scaled
//! \p mesh from 64 centres spread evenly over the vertex ids (deterministic).
//! \throw OptionError("profile.radii") if it is above kMaxMeanBallVertices.
void check_ball_work(const Mesh& mesh, const Adjacency& adjacency, const std::vector<double>& radii);

//! Throws OptionError("profile.radii") unless every radius is finite, > 0 and
//! <= kMaxRadius, and there are at most kMaxRadii.
void check_radii(const std::vector<double>& radii);

//! N_r(centre) as defined above, ascending ids (the centre excluded). A plain
//! breadth-first search bounded by the ball: the single-centre, single-radius
//! form of ball_means(), checked against brute force by the tests.
//! \throw InvalidArgumentError for a bad radius or centre.
std::vector<std::uint32_t> ball_patch(const Mesh& mesh, const Adjacency& adjacency, std::size_t centre, double radius);

//! Result of ball_means(): for each requested radius k (in the order given)
//! and vertex i, mean[k][i] = sum of w_j values[j] / sum of w_j over the j in
//! N_r(i) whose value is defined (not NaN). NaN where there is none or the
//! weights sum to 0, and where values[i] is NaN (such vertices are skipped).
struct BallMeans
{
    std::vector<double> radii;
    std::vector<std::vector<double>> mean;
    //! |N_r(i)| (all vertices, defined or not); filled only when asked for,
    //! and only for centres with a defined value.
    std::vector<std::vector<std::uint32_t>> size;
};

//! Ball means for all vertices and all \p radii at once: a bit-parallel
//! search from batches of 128 centres, radius by radius in increasing order
//! (nested balls), each vertex assigned to the smallest radius whose ball
//! connects it to the centre (METHOD.md section 5a). Parallel over batches
//! with OpenMP; the result does not depend on the thread count (fixed
//! batches, each batch's sums accumulated in a fixed order).
//! \throw InvalidArgumentError for a bad radius or mismatched sizes.
BallMeans ball_means(const Mesh& mesh, const Adjacency& adjacency, const std::vector<double>& values,
                     const std::vector<double>& weights, const std::vector<double>& radii, bool with_sizes = false);
//! The same from \p data, the derived data of the mesh (its bounding box).
BallMeans ball_means(const MeshData& data, const Adjacency& adjacency, const std::vector<double>& values,
                     const std::vector<double>& weights, const std::vector<double>& radii, bool with_sizes = false);

//! Area-weighted sigma of one metric level: sqrt( sum w_i D_i^2 / sum w_i )
//! over the i with defined D (NaN skipped); 0 if none or the weights sum to 0.
//! top_share is the share of sum w_i D_i^2 from the outlier_fraction of those
//! vertices with the largest |D|; worst_vertices as in level_roughness().
//! The result has level = 0 and radius = \p radius.
//! \throw InvalidArgumentError if the sizes differ.
LevelRoughness weighted_level_roughness(double radius, const std::vector<double>& D, const std::vector<double>& weights,
                                        double outlier_fraction = 0.001);

}  // namespace meshdiff
