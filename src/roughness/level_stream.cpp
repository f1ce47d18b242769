#include "roughness/level_stream.h"

#include "meshdiff/error.h"

#include <omp.h>
#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <optional>

namespace meshdiff::detail {

namespace {

// x ranks before y: larger |D| first, ties by id (the order of level_roughness() and trimmed_rms()).
bool before(const RankedD& x, const RankedD& y)
{
    return x.a != y.a ? x.a > y.a : x.id < y.id;
}

// Keeps the first \p m of \p v in rank, in rank order: a selection, then a
// sort of those (a partial sort's heap was 2-3 times slower for a head of
// 50,000 of 100,000). before() is a total order (ids differ): the same head.
void rank_first(std::vector<RankedD>& v, std::size_t m)
{
    if (m < v.size()) {
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(m), v.end(), before);
        v.resize(m);
    }
    std::sort(v.begin(), v.end(), before);
}

}  // namespace

std::size_t head_for(double fraction, std::size_t m)
{
    return std::size_t(std::ceil(fraction * double(m)));
}

LevelStream::LevelStream(std::size_t n_levels, std::size_t n_batches, std::size_t capacity,
                         const std::vector<double>& values, const std::vector<double>* weights, bool second)
    : n_levels_(n_levels),
      n_batches_(n_batches),
      capacity_(std::max<std::size_t>(capacity, 10)),
      values_(values),
      weights_(weights),
      second_(second),
      parts_(n_levels * n_batches),
      seen_(n_batches, 0),
      heads_(std::size_t(std::max(1, omp_get_max_threads())), std::vector<Head>(n_levels))
{}

void LevelStream::offer(Head& head, double a, std::uint32_t id) const
{
    // Equal to the floor still may rank before a kept one (a lower id).
    if (a < head.floor) return;
    head.items.push_back({a, id});
    if (head.items.size() < capacity_ + capacity_ / 2 + 16) return;
    auto first = [](const Candidate& x, const Candidate& y) { return x.a != y.a ? x.a > y.a : x.id < y.id; };
    std::nth_element(head.items.begin(), head.items.begin() + std::ptrdiff_t(capacity_ - 1), head.items.end(), first);
    head.items.resize(capacity_);
    head.floor = head.items.back().a;  // the capacity-th in rank
}

void LevelStream::add(const DiskMeansBatch& batch)
{
    // Out of range only by a caller's mistake; the batch is then left out
    // and sums() reports it (no throw on a worker thread).
    const double* const means = second_ ? batch.mean2 : batch.mean;
    if (batch.index >= n_batches_ || std::size_t(batch.worker) >= heads_.size() || !means) return;
    // Centre by centre, its levels inside: each level's sums take the
    // centres in the same order as a loop over one level would (so the same
    // bits), but the levels' compensated additions, each waiting on the last
    // of its level, interleave.
    Part* const parts = &parts_[batch.index * n_levels_];
    Head* const heads = heads_[std::size_t(batch.worker)].data();
    std::fill(parts, parts + n_levels_, Part{});
    for (std::size_t k = 0; k < batch.count; ++k) {
        const std::uint32_t c = batch.centres[k];
        const double value = values_[c];
        const double w = weights_ ? (*weights_)[c] : 1.0;
        for (std::size_t li = 0; li < n_levels_; ++li) {
            const double d = value - means[li * batch.stride + k];
            if (std::isnan(d)) continue;
            Part& p = parts[li];
            p.total.add(w * d * d);
            p.wtotal.add(w);
            ++p.used;
            offer(heads[li], std::abs(d), c);
        }
    }
    seen_[batch.index] = 1;
}

LevelSums LevelStream::sums(std::size_t li) const
{
    if (std::find(seen_.begin(), seen_.end(), char(0)) != seen_.end())
        throw InvalidArgumentError("level statistics: a batch of ring means was not folded in");
    LevelSums s;
    for (std::size_t b = 0; b < n_batches_; ++b) {  // batch order: the same at any thread count
        const Part& p = parts_[b * n_levels_ + li];
        s.total.add(p.total.s);
        s.total.add(p.total.c);
        s.wtotal.add(p.wtotal.s);
        s.wtotal.add(p.wtotal.c);
        s.used += p.used;
    }
    std::size_t candidates = 0;
    for (const auto& worker : heads_) candidates += worker[li].items.size();
    s.head.reserve(candidates);  // not grown by doubling (a fresh block and a copy each time)
    for (const auto& worker : heads_)
        for (const Candidate& x : worker[li].items) s.head.push_back({x.a, x.id, weights_ ? (*weights_)[x.id] : 1.0});
    rank_first(s.head, capacity_);
    return s;
}

std::vector<RankedD> ranked_head(const std::vector<double>& D, const std::vector<double>* weights, std::size_t capacity)
{
    std::vector<RankedD> head;
    for (std::size_t i = 0; i < D.size(); ++i)
        if (!std::isnan(D[i])) head.push_back({std::abs(D[i]), std::uint32_t(i), weights ? (*weights)[i] : 1.0});
    rank_first(head, capacity);  // a selection, linear, then a sort of the head
    return head;
}

namespace {

// One set of values folded by fold_levels(): its stream, and D where stored.
struct Channel
{
    const std::vector<double>& values;
    const std::vector<double>* weights;
    bool store;
    std::size_t n_levels, head = 10, limit = 0;
    std::unique_ptr<LevelStream> stream;
    std::vector<std::vector<double>> D;

    Channel(const std::vector<double>& v, const std::vector<double>* w, const std::vector<double>& fractions, bool keep,
            std::size_t levels, std::size_t n_batches, bool second)
        : values(v), weights(w), store(keep), n_levels(levels)
    {
        const std::size_t n = values.size();
        const auto centres =
            std::size_t(std::count_if(values.begin(), values.end(), [](double x) { return !std::isnan(x); }));
        for (const double f : fractions)
            if (f > 0.0) head = std::max(head, head_for(f, centres));
        // No levels x n vector of D unless it is asked for, or the head is
        // large beside the mesh (it is then ranked from D, not folded per worker).
        limit = head_limit(n);
        stream = std::make_unique<LevelStream>(n_levels, n_batches, std::min(head, limit), values, weights, second);
        D.resize(store || head > limit ? n_levels : 0);
        for (auto& d : D) d.assign(n, std::numeric_limits<double>::quiet_NaN());
    }

    void add(const DiskMeansBatch& b, const double* mean)
    {
        stream->add(b);
        for (std::size_t li = 0; li < D.size(); ++li)
            for (std::size_t k = 0; k < b.count; ++k)
                D[li][b.centres[k]] = values[b.centres[k]] - mean[li * b.stride + k];  // NaN propagates
    }

    // Each level's sums and ranked head at once, in parallel (a head of 5 %
    // of a 1M mesh's vertices is ranked in 10 ms per level); the callback
    // then sees them in level order.
    void finish(const std::function<void(std::size_t li, const LevelSums& sums, std::vector<double>& D)>& level)
    {
        std::vector<LevelSums> sums(n_levels);
        std::vector<std::exception_ptr> failed(n_levels);  // nothing may leave an OpenMP loop by a throw
#pragma omp parallel for schedule(dynamic, 1)
        for (std::ptrdiff_t li = 0; li < std::ptrdiff_t(n_levels); ++li) {
            const auto l = std::size_t(li);
            try {
                sums[l] = stream->sums(l);
                if (head > limit) sums[l].head = ranked_head(D[l], weights, head);
            } catch (...) {
                failed[l] = std::current_exception();
            }
        }
        for (const std::exception_ptr& e : failed)
            if (e) std::rethrow_exception(e);
        std::vector<double> none;
        for (std::size_t li = 0; li < n_levels; ++li) {
            level(li, sums[li], store ? D[li] : none);
            sums[li] = LevelSums();
        }
    }
};

}  // namespace

void fold_levels(const MeshData& data, const Adjacency& adjacency, const std::vector<double>& values,
                 const std::vector<double>* weights, const std::vector<int>& levels,
                 std::initializer_list<double> fractions, bool store,
                 const std::function<void(std::size_t li, const LevelSums& sums, std::vector<double>& D)>& level,
                 const SecondFold* second)
{
    if (levels.empty()) return;
    const std::size_t n_levels = levels.size(), n_batches = disk_mean_batch_count(values);
    Channel first(values, weights, std::vector<double>(fractions), store, n_levels, n_batches, false);
    std::optional<Channel> other;
    if (second) {
        other.emplace(second->values, second->weights, second->fractions, second->store, n_levels, n_batches, true);
    }
    disk_means_batches(data, adjacency, values, second ? &second->values : nullptr, levels, false,
                       [&](const DiskMeansBatch& b) {
                           first.add(b, b.mean);
                           if (other) other->add(b, b.mean2);
                       });
    first.finish(level);
    if (other) other->finish(second->level);
}

double streamed_trimmed_rms(const LevelSums& s, double trim, std::size_t* dropped)
{
    const std::size_t m = s.used;
    const std::size_t k = std::min(m, head_for(trim, m));
    if (dropped) *dropped = k;
    if (k > s.head.size()) throw InvalidArgumentError("level statistics: the trim reaches beyond the ranked head");
    if (k == m) return std::numeric_limits<double>::quiet_NaN();
    // The kept sums: the totals less the dropped head, compensated (the
    // rounding stays that of the sums, not of their difference).
    CompensatedSum kept = s.total, wkept = s.wtotal;
    for (std::size_t j = 0; j < k; ++j) {
        const RankedD& x = s.head[j];
        kept.add(-(x.w * x.a * x.a));
        wkept.add(-x.w);
    }
    const double t = std::max(0.0, kept.value()), w = wkept.value();
    return w > 0.0 ? std::sqrt(t / w) : std::numeric_limits<double>::quiet_NaN();
}

LevelRoughness streamed_level_roughness(int level, const LevelSums& s, double outlier_fraction, double trim)
{
    LevelRoughness r;
    r.level = level;
    r.vertices_used = s.used;
    if (s.used == 0) return r;
    const double total = s.total.value();
    r.sigma = std::sqrt(total / double(s.used));
    if (total > 0.0) {
        const std::size_t k = std::max<std::size_t>(1, head_for(outlier_fraction, s.used));
        if (k > s.head.size()) throw InvalidArgumentError("level statistics: the top share reaches beyond the head");
        CompensatedSum top;
        for (std::size_t j = 0; j < k; ++j) top.add(s.head[j].a * s.head[j].a);
        r.top_share = top.value() / total;
    }
    const std::size_t worst = std::min<std::size_t>(10, s.head.size());
    for (std::size_t j = 0; j < worst; ++j) r.worst_vertices.push_back(s.head[j].id);
    if (trim > 0.0) {
        const double t = streamed_trimmed_rms(s, trim, &r.trimmed);
        r.sigma = std::isnan(t) ? 0.0 : t;
    }
    return r;
}

}  // namespace meshdiff::detail
