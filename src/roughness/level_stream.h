//! \file level_stream.h (detail)
//! \brief The statistics of D_L = values - ring mean folded batch by batch
//! (disk_means_batches()), without the levels x n vector of D: the count, the
//! (weighted) sum of squares and the ranked head of |D| that sigma, its trim,
//! the top share and the worst vertices need (issue 30, lever 5).
//!
//! Deterministic at any thread count: a batch's sums go to its own slot and are
//! added in batch order (compensated), and the head is the first vertices in
//! one total order (|D| descending, id ascending), the same however the
//! batches were shared out. Against the stored path (level_roughness(),
//! trimmed_rms()), which adds in vertex order, only the rounding of the sums
//! differs: the compensated sums are the closer to the exact ones.
#pragma once

#include "meshdiff/roughness/roughness.h"

#include "core/compensated_sum.h"
#include "roughness/disk_means_batches.h"

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <vector>

namespace meshdiff::detail {

//! One vertex of a level's head: |D|, its id and its weight.
struct RankedD
{
    double a = 0.0;
    std::uint32_t id = 0;
    double w = 1.0;
};

//! What a level's statistics need, once every batch is in.
struct LevelSums
{
    std::size_t used = 0;   //!< vertices with a defined D
    CompensatedSum total;   //!< sum of w D^2
    CompensatedSum wtotal;  //!< sum of w
    //! The vertices of largest |D| (ties by id), ranked, at most the capacity.
    std::vector<RankedD> head;
};

//! Folds the batches of disk_means_batches() into LevelSums per level:
//! D = values[c] - mean for each centre c with a defined mean, weighted by
//! weights[c] (1 without weights).
class LevelStream
{
public:
    //! \param capacity the length of the head kept per level (at least 10)
    //! With \p second, the means are the batches' mean2 (disk_means_batches()).
    LevelStream(std::size_t n_levels, std::size_t n_batches, std::size_t capacity, const std::vector<double>& values,
                const std::vector<double>* weights = nullptr, bool second = false);
    //! Called on the worker threads, each batch once.
    void add(const DiskMeansBatch& batch);
    //! Level li's sums (after every batch).
    LevelSums sums(std::size_t li) const;

private:
    struct Part
    {
        CompensatedSum total, wtotal;
        std::size_t used = 0;
    };
    std::size_t n_levels_, n_batches_, capacity_;
    const std::vector<double>& values_;
    const std::vector<double>* weights_;
    bool second_;
    // A worker's candidates for a level's head: every |D| at or above the
    // floor, cut back to the capacity (nth_element) when they reach 3/2 of
    // it, which raises the floor. An offer below the floor costs one
    // comparison (a heap cost 1.1 s of a 1M local difference's 2.7 s with
    // its 5 % trim, 50,000 vertices a level).
    struct Candidate
    {
        double a;
        std::uint32_t id;
    };
    struct Head
    {
        std::vector<Candidate> items;
        double floor = 0.0;
    };
    void offer(Head& head, double a, std::uint32_t id) const;
    std::vector<Part> parts_;               // [batch][level]
    std::vector<char> seen_;                // [batch]: folded in
    std::vector<std::vector<Head>> heads_;  // [worker][level]
};

//! The head's length a level needs for \p fraction of up to \p m vertices
//! (ceil(fraction x m)), and the capacity for a profile's options over \p m
//! centres: the 10 worst, the top share's and the trim's.
std::size_t head_for(double fraction, std::size_t m);

//! The longest head folded per level and worker for a mesh of \p n vertices
//! (n / 16, at least 4096); a longer one is ranked from the stored D.
inline std::size_t head_limit(std::size_t n)
{
    return n / 16 > 4096 ? n / 16 : 4096;
}

//! The head of \p D ranked from the whole vector (no NaN), at most
//! \p capacity long: what LevelStream folds, for a head above head_limit().
std::vector<RankedD> ranked_head(const std::vector<double>& D, const std::vector<double>* weights,
                                 std::size_t capacity);

//! D_L = values[c] - (the mean of the values over N_L(c)) at each of
//! \p levels, over the centres c with a defined value, folded batch by batch
//! (weighted by \p weights, 1 without): \p level is then called per level, in
//! order, with the sums, whose head is long enough for each of \p fractions of
//! the centres (ceil(f x centres), at least 10), and with D (NaN where
//! undefined; the callee may move it), empty unless \p store. D is also stored
//! when the head is longer than head_limit(), and ranked from; either way the
//! sums are the same to the last bit.
//!
//! With \p second, its values are folded over the same rings in the same
//! search (disk_means_batches() with two sets of values), as fold_levels()
//! would fold them alone, at the same levels; its callback is called after
//! the first's, level by level. The centres are those of \p values: where
//! the second values are defined at the same vertices, their sums are those
//! of their own fold to the last bit; otherwise (fewer defined) they differ
//! in the rounding only.
struct SecondFold
{
    const std::vector<double>& values;
    const std::vector<double>* weights = nullptr;
    std::vector<double> fractions;
    bool store = false;
    std::function<void(std::size_t li, const LevelSums& sums, std::vector<double>& D)> level;
};
void fold_levels(const MeshData& data, const Adjacency& adjacency, const std::vector<double>& values,
                 const std::vector<double>* weights, const std::vector<int>& levels,
                 std::initializer_list<double> fractions, bool store,
                 const std::function<void(std::size_t li, const LevelSums& sums, std::vector<double>& D)>& level,
                 const SecondFold* second = nullptr);

//! sigma, top share and worst vertices from \p s as level_roughness() does,
//! then the trim as trimmed_rms() (unweighted when \p weighted is false).
LevelRoughness streamed_level_roughness(int level, const LevelSums& s, double outlier_fraction, double trim);

//! trimmed_rms() from the sums: the weighted RMS without the ceil(trim x used)
//! largest |D| (NaN without weight left); their number into \p dropped.
double streamed_trimmed_rms(const LevelSums& s, double trim, std::size_t* dropped = nullptr);

}  // namespace meshdiff::detail
