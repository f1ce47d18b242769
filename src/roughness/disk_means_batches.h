//! \file disk_means_batches.h (detail)
//! \brief The ring means of disk_means() batch by batch, for a caller that
//! folds them into statistics instead of storing levels x n means (a
//! roughness profile of 1M vertices at 20 levels: 160 MB it does not need).
#pragma once

#include "meshdiff/core/mesh_data.h"
#include "meshdiff/core/topology.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace meshdiff::detail {

//! One batch of centres and their means: mean[li * stride + k] is the mean of
//! the values over N_L(centres[k]) at the li-th requested level (NaN where no
//! value is defined there); size[li * stride + k] likewise |N_L| (only when
//! asked for, otherwise null). Every centre has a defined value.
struct DiskMeansBatch
{
    std::size_t index = 0;  //!< the batch's number: batches are fixed by the mesh, not by the threads
    int worker = 0;         //!< the OpenMP thread running it (< omp_get_max_threads())
    const std::uint32_t* centres = nullptr;
    std::size_t count = 0;
    const double* mean = nullptr;
    //! The second values' means likewise (over the vertices where they are
    //! defined), when asked for; a centre's may be NaN.
    const double* mean2 = nullptr;
    const std::uint32_t* size = nullptr;
    std::size_t stride = 0;
};

//! How many batches disk_means_batches() will make for \p values (those with a
//! defined value, cut into batches of 128).
std::size_t disk_mean_batch_count(const std::vector<double>& values);

//! disk_means() handing each batch to \p sink (called on the worker threads,
//! concurrently; each batch once) instead of storing the means. The means are
//! those of disk_means() to the last bit.
//!
//! With \p second, the rings are searched once for two sets of values: the
//! batches also carry the means of \p second over the same rings (mean2).
//! The centres are those of \p values; where \p second is defined at the
//! same vertices, its means are those of its own disk_means() to the last bit
//! (the same batches, the same additions in the same order), otherwise they
//! differ from them in the rounding only (a centre's batch mates fix the
//! order of its additions).
void disk_means_batches(const MeshData& data, const Adjacency& adjacency, const std::vector<double>& values,
                        const std::vector<double>* second, const std::vector<int>& levels, bool with_sizes,
                        const std::function<void(const DiskMeansBatch&)>& sink);

}  // namespace meshdiff::detail
