//! \file neighborhood.h
//! \brief Ring neighbourhoods over mesh edges (METHOD.md section 5).
//!
//! N_L(i) = { j != i : graph distance(i, j) <= L }, distances counted in edges
//! of the mesh (vertex_adjacency()). The centre vertex is excluded.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/mesh_data.h"
#include "meshdiff/core/topology.h"

#include <cstdint>
#include <vector>

namespace meshdiff {

//! Graph distance from \p source to every vertex within \p max_level edges
//! (-1 beyond, or unreachable). A plain breadth-first search: the reference
//! against which disk_means() is tested, and handy for single vertices.
std::vector<int> ring_distances(const Adjacency& adjacency, std::size_t source, int max_level);

//! Result of disk_means(): for each requested level k (in the order given) and
//! vertex i, mean[k][i] = mean of values[j] over the j in N_L(i) whose value
//! is defined (not NaN). NaN where there is none, or where values[i] itself is
//! NaN (such vertices are skipped as centres).
struct DiskMeans
{
    std::vector<int> levels;
    std::vector<std::vector<double>> mean;
    //! |N_L(i)| (all vertices, defined or not); filled only when asked for,
    //! and only for centres with a defined value.
    std::vector<std::vector<std::uint32_t>> size;
};

//! Computes disk means for all vertices and all \p levels at once, by
//! bit-parallel breadth-first search from 128 spatially close centres at a
//! time (64 x MESHDIFF_BFS_WORDS, 2 by default; compact graph patches seeded
//! in Morton order), up to the largest
//! level. Parallel over batches with OpenMP; the result does not depend on the
//! thread count (each centre's sums are accumulated in a fixed order).
//! Around a hub (a mesh with a vertex of valence above 1024), a vertex that
//! all 64 centres of a mask word reach first at the same level adds its value
//! once to the word's sum instead of once per centre (the sum is then added to
//! each centre's): otherwise a hub of valence d costs d^2 / 2 additions (a fan
//! of 100,000 triangles: 5e9). Only the rounding of those sums changes, and
//! only on such meshes.
//! \param mesh       supplies the positions for the batch order
//! \param levels     each >= 1, any order, duplicates allowed
//! \param with_sizes also fill DiskMeans::size
//! \throw InvalidArgumentError for a level < 1 or mismatched sizes.
DiskMeans disk_means(const Mesh& mesh, const Adjacency& adjacency, const std::vector<double>& values,
                     const std::vector<int>& levels, bool with_sizes = false);
//! The same from \p data, the derived data of the mesh (its bounding box).
DiskMeans disk_means(const MeshData& data, const Adjacency& adjacency, const std::vector<double>& values,
                     const std::vector<int>& levels, bool with_sizes = false);

//! The global level's means: at each vertex with a defined value, the mean
//! over all OTHER vertices with a defined value (a long double sum, O(n));
//! NaN where the value is NaN or fewer than two values are defined. The one
//! home of the leave-one-out mean of METHOD.md's global level, for the profile
//! and the local roughness difference alike.
std::vector<double> global_means(const std::vector<double>& values);

}  // namespace meshdiff
