#include "meshdiff/roughness/neighborhood.h"

#include "meshdiff/error.h"

#include "core/release.h"
#include "roughness/disk_means_batches.h"

#include "core/stage_progress.h"
#include "geometry/simd.h"
#include "roughness/morton.h"

#ifndef MESHDIFF_BFS_WORDS
#define MESHDIFF_BFS_WORDS 2
#endif

#include <fmt/format.h>

#include <omp.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <tuple>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if MESHDIFF_HAVE_AVX512_KERNELS
#include <immintrin.h>
#endif

namespace meshdiff {

std::vector<int> ring_distances(const Adjacency& adj, std::size_t source, int max_level)
{
    std::vector<int> dist(adj.size(), -1);
    if (source >= adj.size()) throw InvalidArgumentError("ring_distances: source out of range");
    std::deque<std::uint32_t> queue{std::uint32_t(source)};
    dist[source] = 0;
    while (!queue.empty()) {
        const auto v = queue.front();
        queue.pop_front();
        if (dist[v] == max_level) continue;
        for (auto it = adj.begin(v); it != adj.end(v); ++it)
            if (dist[*it] < 0) {
                dist[*it] = dist[v] + 1;
                queue.push_back(*it);
            }
    }
    return dist;
}

namespace {

using detail::clustered_order;

// Bit-parallel BFS from W * 64 centres at a time. Per vertex: the centres
// that have reached it (seen), that reach it at the level being built (next)
// and that reached it at the last level (frontier), interleaved so that one
// cache line serves a neighbour test.
template <int W>
struct Marks
{
    std::uint64_t seen[W];
    std::uint64_t next[W];
};

#if MESHDIFF_HAVE_AVX512_KERNELS
// Entry k: bit k. Row j (entries 8 j .. 8 j + 7) selects, lane by lane, the
// bits of a mask word's byte j: the centres that register of sums holds.
struct LaneBits
{
    alignas(64) std::uint64_t bit[64];
};
constexpr LaneBits make_lane_bits()
{
    LaneBits t{};
    for (int k = 0; k < 64; ++k) t.bit[k] = std::uint64_t(1) << k;
    return t;
}
constexpr LaneBits kLaneBits = make_lane_bits();
#endif

template <int W>
struct BatchBfs
{
    static constexpr std::size_t kBatch = 64 * W;
    const Adjacency& adj;
    const std::vector<double>& values;
    // A second set of values summed over the same rings (null: none): their
    // sums and counts of defined values only (disk_means_batches()).
    const double* const values2;
    const bool all_defined;
    const bool word_sums;  // see kWordSumDegree
    const int lmax;
    const bool avx512 = detail::use_avx512();
    std::vector<Marks<W>> marks;
    // The frontier: the vertices reached at the last level (flist) and the
    // centres that reached each (ffront, parallel to flist).
    std::vector<std::uint32_t> flist, nlist, touched;
    std::vector<std::array<std::uint64_t, W>> ffront, nfront;
    std::vector<double> sum;           // [level][kBatch], level 1..lmax
    std::vector<std::uint32_t> count;  // defined values
    std::vector<std::uint32_t> size;   // all vertices
    // Per level and word: the values of the vertices that every centre of the
    // word reached first at that level (word_sums only), added to each of
    // those centres' sums after the level's own values.
    std::vector<double> wsum;
    std::vector<std::uint32_t> wcount, wsize;
    // The second values' sums and counts, as sum and count (values2 only).
    std::vector<double> sum2, wsum2;
    std::vector<std::uint32_t> count2, wcount2;

    BatchBfs(const Adjacency& a, const std::vector<double>& v, const std::vector<double>* v2, bool defined, bool words,
             int max_level)
        : adj(a), values(v), values2(v2 ? v2->data() : nullptr), all_defined(defined), word_sums(words), lmax(max_level)
    {
        const std::size_t n = adj.size();
        marks.assign(n, Marks<W>{});
        sum.resize(std::size_t(lmax + 1) * kBatch);
        count.resize(std::size_t(lmax + 1) * kBatch);
        size.resize(std::size_t(lmax + 1) * kBatch);
        wsum.resize(std::size_t(lmax + 1) * W);
        wcount.resize(std::size_t(lmax + 1) * W);
        wsize.resize(std::size_t(lmax + 1) * W);
        if (values2) {
            sum2.resize(sum.size());
            count2.resize(count.size());
            wsum2.resize(wsum.size());
            wcount2.resize(wcount.size());
        }
    }

    // The sums, counts and sizes of \p level, after sizing the next frontier
    // for the \p n_new vertices that settle().
    std::tuple<double*, std::uint32_t*, std::uint32_t*> level_sums(int level, std::size_t n_new)
    {
        flist.resize(n_new);
        nfront.resize(n_new);
        const std::size_t at = std::size_t(level) * kBatch;
        return {&sum[at], &count[at], &size[at]};
    }

    // Settles the vertices that expand() listed for \p level: their new
    // centres become seen and their frontier, and each adds its value to the
    // sums of those centres (in the list's order; within a vertex, in bit
    // order), or once to a word's sum where the whole word reached it.
    template <bool AllDefined, bool WordSums, bool Two>
    void settle(int level, std::size_t n_new, const std::array<std::uint64_t, W>& live)
    {
#if MESHDIFF_HAVE_AVX512_KERNELS
        if constexpr (W == 2 && !WordSums)
            if (avx512) {
                settle_avx512<AllDefined>(level, n_new);
                if constexpr (Two) add_second_avx512(level, n_new);
                return;
            }
#endif
        const auto [lsum, lcount, lsize] = level_sums(level, n_new);
        const std::size_t at2 = std::size_t(level) * kBatch;
        double* const lsum2 = Two ? &sum2[at2] : nullptr;
        std::uint32_t* const lcount2 = Two ? &count2[at2] : nullptr;
        const std::uint32_t* const nl = nlist.data();
        Marks<W>* const mk = marks.data();
        const double* const vals = values.data();
        for (std::size_t q = 0; q < n_new; ++q) {
            const auto v = nl[q];
            flist[q] = v;
            Marks<W>& m = mk[v];
            std::uint64_t seen_any = 0;
            std::uint64_t bits[W];
            for (int w = 0; w < W; ++w) {
                seen_any |= m.seen[w];
                bits[w] = m.next[w];
                m.next[w] = 0;
                m.seen[w] |= bits[w];
                nfront[q][std::size_t(w)] = bits[w];
            }
            if (!seen_any) touched.push_back(v);
            const double val = vals[v];
            const double val2 = Two ? values2[v] : 0.0;
            for (int w = 0; w < W; ++w) {
                if constexpr (WordSums)
                    if (bits[w] == live[std::size_t(w)] && bits[w] != 0) {
                        // All centres of the word at once (around a hub): once per word.
                        const std::size_t at = std::size_t(level) * W + std::size_t(w);
                        ++wsize[at];
                        if (AllDefined || !std::isnan(val)) {
                            wsum[at] += val;
                            ++wcount[at];
                        }
                        if (Two && !std::isnan(val2)) {
                            wsum2[at] += val2;
                            ++wcount2[at];
                        }
                        continue;
                    }
                add_word<AllDefined>(bits[w], val, lsum + 64 * w, lcount + 64 * w, lsize + 64 * w);
                if constexpr (Two) add_defined(bits[w], val2, lsum2 + 64 * w, lcount2 + 64 * w);
            }
        }
    }

#if MESHDIFF_HAVE_AVX512_KERNELS
    // val added to the 128 sums held in acc (16 registers of 8) where the
    // bits of the broadcast mask words w0 and w1 are set, in register order.
    static inline __attribute__((always_inline, target("avx512f,avx512bw"))) void add_under_masks(__m512d* acc,
                                                                                                  __m512d val,
                                                                                                  __m512i w0,
                                                                                                  __m512i w1)
    {
#pragma GCC unroll 8
        for (int j = 0; j < 8; ++j) {
            const __m512i bit = _mm512_load_si512(reinterpret_cast<const __m512i*>(kLaneBits.bit + 8 * j));
            acc[j] = _mm512_mask_add_pd(acc[j], _mm512_test_epi64_mask(w0, bit), acc[j], val);
            acc[8 + j] = _mm512_mask_add_pd(acc[8 + j], _mm512_test_epi64_mask(w1, bit), acc[8 + j], val);
        }
    }

    // settle<AllDefined, false>() for W == 2 with AVX-512: the level's 128
    // sums stay in 16 registers of 8 doubles, and each listed vertex adds its
    // value to all 16 under the masks of its new centres' bits (none where the
    // value is NaN). The same additions in the same order as add_word() (per
    // centre: the list's order), so the same sums to the last bit; no branch
    // on the bits. The counts (and the sizes) are kept in bytes, one 64-byte
    // register per mask word, and added to the level's every 255 vertices.
    template <bool AllDefined>
    __attribute__((target("avx512f,avx512bw"))) void settle_avx512(int level, std::size_t n_new)
    {
        const auto [lsum, lcount, lsize] = level_sums(level, n_new);
        const std::uint32_t* const nl = nlist.data();
        Marks<W>* const mk = marks.data();
        const double* const vals = values.data();
        __m512d acc[16];
#pragma GCC unroll 16
        for (int j = 0; j < 16; ++j) acc[j] = _mm512_loadu_pd(lsum + 8 * j);
        __m512i cnt0 = _mm512_setzero_si512(), cnt1 = _mm512_setzero_si512();
        __m512i siz0 = _mm512_setzero_si512(), siz1 = _mm512_setzero_si512();
        for (std::size_t q0 = 0; q0 < n_new; q0 += 255) {
            const std::size_t q1 = std::min(n_new, q0 + 255);
            for (std::size_t q = q0; q < q1; ++q) {
                const auto v = nl[q];
                flist[q] = v;
                Marks<W>& m = mk[v];
                const std::uint64_t b0 = m.next[0], b1 = m.next[1];
                if (!(m.seen[0] | m.seen[1])) touched.push_back(v);
                m.next[0] = 0;
                m.next[1] = 0;
                m.seen[0] |= b0;
                m.seen[1] |= b1;
                nfront[q][0] = b0;
                nfront[q][1] = b1;
                const double x = vals[v];
                // The centres that add x: all new ones, or none where x is NaN.
                const std::uint64_t keep = AllDefined ? ~std::uint64_t(0) : std::uint64_t(0) - !std::isnan(x);
                const __m512d val = _mm512_set1_pd(x);
                const __m512i w0 = _mm512_set1_epi64(std::int64_t(b0 & keep));
                const __m512i w1 = _mm512_set1_epi64(std::int64_t(b1 & keep));
                add_under_masks(acc, val, w0, w1);
                cnt0 = _mm512_sub_epi8(cnt0, _mm512_movm_epi8(_cvtu64_mask64(b0 & keep)));
                cnt1 = _mm512_sub_epi8(cnt1, _mm512_movm_epi8(_cvtu64_mask64(b1 & keep)));
                if constexpr (!AllDefined) {
                    siz0 = _mm512_sub_epi8(siz0, _mm512_movm_epi8(_cvtu64_mask64(b0)));
                    siz1 = _mm512_sub_epi8(siz1, _mm512_movm_epi8(_cvtu64_mask64(b1)));
                }
            }
            alignas(64) std::uint8_t c[256];
            _mm512_store_si512(reinterpret_cast<__m512i*>(c), cnt0);
            _mm512_store_si512(reinterpret_cast<__m512i*>(c + 64), cnt1);
            for (int b = 0; b < 128; ++b) lcount[b] += c[b];
            cnt0 = _mm512_setzero_si512();
            cnt1 = _mm512_setzero_si512();
            if constexpr (!AllDefined) {
                _mm512_store_si512(reinterpret_cast<__m512i*>(c + 128), siz0);
                _mm512_store_si512(reinterpret_cast<__m512i*>(c + 192), siz1);
                for (int b = 0; b < 128; ++b) lsize[b] += c[128 + b];
                siz0 = _mm512_setzero_si512();
                siz1 = _mm512_setzero_si512();
            }
        }
#pragma GCC unroll 16
        for (int j = 0; j < 16; ++j) _mm512_storeu_pd(lsum + 8 * j, acc[j]);
    }

    // The second values' sums and counts of the vertices settle_avx512() just
    // listed (flist, with their new centres in nfront): the additions of
    // add_defined(), in the same order, as settle_avx512() makes its own.
    __attribute__((target("avx512f,avx512bw"))) void add_second_avx512(int level, std::size_t n_new)
    {
        const std::size_t at = std::size_t(level) * kBatch;
        double* const lsum = &sum2[at];
        std::uint32_t* const lcount = &count2[at];
        const std::uint32_t* const fl = flist.data();
        __m512d acc[16];
#pragma GCC unroll 16
        for (int j = 0; j < 16; ++j) acc[j] = _mm512_loadu_pd(lsum + 8 * j);
        __m512i cnt0 = _mm512_setzero_si512(), cnt1 = _mm512_setzero_si512();
        for (std::size_t q0 = 0; q0 < n_new; q0 += 255) {
            const std::size_t q1 = std::min(n_new, q0 + 255);
            for (std::size_t q = q0; q < q1; ++q) {
                const double x = values2[fl[q]];
                const std::uint64_t keep = std::uint64_t(0) - !std::isnan(x);
                const std::uint64_t b0 = nfront[q][0] & keep, b1 = nfront[q][1] & keep;
                const __m512d val = _mm512_set1_pd(x);
                const __m512i w0 = _mm512_set1_epi64(std::int64_t(b0));
                const __m512i w1 = _mm512_set1_epi64(std::int64_t(b1));
                add_under_masks(acc, val, w0, w1);
                cnt0 = _mm512_sub_epi8(cnt0, _mm512_movm_epi8(_cvtu64_mask64(b0)));
                cnt1 = _mm512_sub_epi8(cnt1, _mm512_movm_epi8(_cvtu64_mask64(b1)));
            }
            alignas(64) std::uint8_t c[128];
            _mm512_store_si512(reinterpret_cast<__m512i*>(c), cnt0);
            _mm512_store_si512(reinterpret_cast<__m512i*>(c + 64), cnt1);
            for (int b = 0; b < 128; ++b) lcount[b] += c[b];
            cnt0 = _mm512_setzero_si512();
            cnt1 = _mm512_setzero_si512();
        }
#pragma GCC unroll 16
        for (int j = 0; j < 16; ++j) _mm512_storeu_pd(lsum + 8 * j, acc[j]);
    }
#endif

    // Adds val to the sums and 1 to the counts of the centres whose bits are
    // set in x, in bit order, unless val is NaN (the second values).
    static inline __attribute__((always_inline)) void add_defined(std::uint64_t x, double val, double* ws,
                                                                  std::uint32_t* wc)
    {
        if (std::isnan(val)) return;
        while (x) {
            const std::size_t b = std::size_t(__builtin_ctzll(x)) & 63;
            x &= x - 1;
            ws[b] += val;
            ++wc[b];
        }
    }

    // Adds val to the sums (and 1 to the counts) of the centres whose bits
    // are set in x, in bit order; without AllDefined, a NaN val counts only in
    // the sizes.
    template <bool AllDefined>
    static inline __attribute__((always_inline)) void add_word(std::uint64_t x, double val, double* ws,
                                                               std::uint32_t* wc, std::uint32_t* wz)
    {
        if constexpr (AllDefined) {
            // count == size: one counter per centre suffices.
            while (x) {
                const std::size_t b = std::size_t(__builtin_ctzll(x)) & 63;
                x &= x - 1;
                ws[b] += val;
                ++wc[b];
            }
        } else {
            const bool defined = !std::isnan(val);
            while (x) {
                const std::size_t b = std::size_t(__builtin_ctzll(x)) & 63;
                x &= x - 1;
                ++wz[b];
                if (defined) {
                    ws[b] += val;
                    ++wc[b];
                }
            }
        }
    }

    // One level's expansion: offers each frontier vertex's centres to its
    // neighbours (those that have not reached them yet) and lists in nlist, in
    // the order of the offers, each vertex that gets its first new centre at
    // this level. Branch-free: the list grows by one exactly then. Returns
    // the list's length.
    std::size_t expand()
    {
        std::size_t n_new = 0;
        const std::uint32_t* const off = adj.offset.data();
        const std::uint32_t* const idx = adj.index.data();
        Marks<W>* const mk = marks.data();
        const std::size_t nf = flist.size();
        // The list is written at n_new once per offer: room for one more
        // than the frontier's edges (a list of n per worker was 8 MB of a 1M
        // mesh's two workers, mostly unused).
        std::size_t offers = 1;
        for (std::size_t q = 0; q < nf; ++q) offers += off[flist[q] + 1] - off[flist[q]];
        if (nlist.size() < offers) nlist.resize(offers + offers / 2);
        std::uint32_t* const nl = nlist.data();
#if defined(__SSE2__)
        if constexpr (W == 2) {
            // Both words at once; a vertex is new when its next mask was
            // empty and is not now (the bytes that are zero now were zero).
            const __m128i zero = _mm_setzero_si128();
            for (std::size_t q = 0; q < nf; ++q) {
                const std::uint32_t v = flist[q];
                const __m128i f = _mm_loadu_si128(reinterpret_cast<const __m128i*>(ffront[q].data()));
                for (const std::uint32_t *it = idx + off[v], *end = idx + off[v + 1]; it != end; ++it) {
                    const std::uint32_t u = *it;
                    Marks<W>& m = mk[u];
                    const __m128i seen = _mm_loadu_si128(reinterpret_cast<const __m128i*>(m.seen));
                    const __m128i old = _mm_loadu_si128(reinterpret_cast<const __m128i*>(m.next));
                    const __m128i now = _mm_or_si128(old, _mm_andnot_si128(seen, f));
                    _mm_storeu_si128(reinterpret_cast<__m128i*>(m.next), now);
                    const auto zold = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(old, zero)));
                    const auto znow = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(now, zero)));
                    nl[n_new] = u;
                    // 1 exactly when zold == 0xFFFF and znow != 0xFFFF.
                    n_new += ((zold + 1) & (0x1FFFEu - znow)) >> 16;
                }
            }
            return n_new;
        }
#endif
        for (std::size_t q = 0; q < nf; ++q) {
            const std::uint32_t v = flist[q];
            const auto f = ffront[q];
            for (const std::uint32_t *it = idx + off[v], *end = idx + off[v + 1]; it != end; ++it) {
                Marks<W>& m = mk[*it];
                std::uint64_t old_any = 0, add_any = 0;
                for (int w = 0; w < W; ++w) {
                    const std::uint64_t add = f[std::size_t(w)] & ~m.seen[w];
                    old_any |= m.next[w];
                    add_any |= add;
                    m.next[w] |= add;
                }
                nl[n_new] = *it;
                n_new += std::size_t((old_any == 0) & (add_any != 0));
            }
        }
        return n_new;
    }

    template <bool Two>
    void settle_any(int level, std::size_t n_new, const std::array<std::uint64_t, W>& live)
    {
        if (all_defined)
            word_sums ? settle<true, true, Two>(level, n_new, live) : settle<true, false, Two>(level, n_new, live);
        else
            word_sums ? settle<false, true, Two>(level, n_new, live) : settle<false, false, Two>(level, n_new, live);
    }

    // Fills sum/count/size (cumulative over levels) for centres[0..nb).
    void run(const std::uint32_t* centres, std::size_t nb)
    {
        std::fill(sum.begin(), sum.end(), 0.0);
        std::fill(count.begin(), count.end(), 0u);
        std::fill(size.begin(), size.end(), 0u);
        std::fill(wsum.begin(), wsum.end(), 0.0);
        std::fill(wcount.begin(), wcount.end(), 0u);
        std::fill(wsize.begin(), wsize.end(), 0u);
        std::fill(sum2.begin(), sum2.end(), 0.0);
        std::fill(count2.begin(), count2.end(), 0u);
        std::fill(wsum2.begin(), wsum2.end(), 0.0);
        std::fill(wcount2.begin(), wcount2.end(), 0u);
        // The centres of each word (a full word but in the last batch).
        std::array<std::uint64_t, W> live{};
        for (std::size_t k = 0; k < nb; ++k) live[k / 64] |= std::uint64_t(1) << (k % 64);
        flist.clear();
        ffront.clear();
        touched.clear();
        for (std::size_t k = 0; k < nb; ++k) {  // distinct centres
            const auto c = centres[k];
            marks[c].seen[k / 64] |= std::uint64_t(1) << (k % 64);
            std::array<std::uint64_t, W> f{};
            f[k / 64] = std::uint64_t(1) << (k % 64);
            flist.push_back(c);
            ffront.push_back(f);
            touched.push_back(c);
        }
        for (int level = 1; level <= lmax && !flist.empty(); ++level) {
            const std::size_t n_new = expand();
            if (values2)
                settle_any<true>(level, n_new, live);
            else
                settle_any<false>(level, n_new, live);
            ffront.swap(nfront);
        }
        for (auto v : touched) marks[v] = Marks<W>{};
        if (word_sums)
            for (int level = 1; level <= lmax; ++level)
                for (std::size_t k = 0; k < nb; ++k) {
                    const std::size_t at = std::size_t(level) * W + k / 64, i = std::size_t(level) * kBatch + k;
                    sum[i] += wsum[at];
                    count[i] += wcount[at];
                    size[i] += wsize[at];
                    if (values2) {
                        sum2[i] += wsum2[at];
                        count2[i] += wcount2[at];
                    }
                }
        for (int level = 2; level <= lmax; ++level)
            for (std::size_t k = 0; k < kBatch; ++k) {
                sum[std::size_t(level) * kBatch + k] += sum[std::size_t(level - 1) * kBatch + k];
                count[std::size_t(level) * kBatch + k] += count[std::size_t(level - 1) * kBatch + k];
                size[std::size_t(level) * kBatch + k] += size[std::size_t(level - 1) * kBatch + k];
                if (values2) {
                    sum2[std::size_t(level) * kBatch + k] += sum2[std::size_t(level - 1) * kBatch + k];
                    count2[std::size_t(level) * kBatch + k] += count2[std::size_t(level - 1) * kBatch + k];
                }
            }
        if (all_defined) size = count;
    }
};

constexpr int kWords = MESHDIFF_BFS_WORDS;

// Above this valence somewhere in the mesh, a vertex reached by all centres of
// a mask word at the same level adds its value once to the word's sum, not
// once to each centre's: around a hub of valence d, d vertices are reached by
// whole batches at once, d x 128 additions per batch without this, so d^2 / 2
// in all. It changes only the rounding of those sums (the order of addition),
// so it is kept off below a valence no real mesh has, whose sums stay as
// they were.
constexpr std::size_t kWordSumDegree = 1024;

}  // namespace

DiskMeans disk_means(const Mesh& mesh, const Adjacency& adj, const std::vector<double>& values,
                     const std::vector<int>& levels, bool with_sizes)
{
    return disk_means(MeshData(mesh), adj, values, levels, with_sizes);
}

DiskMeans disk_means(const MeshData& data, const Adjacency& adj, const std::vector<double>& values,
                     const std::vector<int>& levels, bool with_sizes)
{
    const std::size_t n = adj.size();
    if (values.size() != n || data.mesh().n_vertices() != n)
        throw InvalidArgumentError("disk_means: values, adjacency and mesh sizes differ");
    DiskMeans out;
    out.levels = levels;
    out.mean.assign(levels.size(), std::vector<double>(n, std::numeric_limits<double>::quiet_NaN()));
    if (with_sizes) out.size.assign(levels.size(), std::vector<std::uint32_t>(n, 0));
    detail::disk_means_batches(data, adj, values, nullptr, levels, with_sizes, [&](const detail::DiskMeansBatch& b) {
        for (std::size_t li = 0; li < levels.size(); ++li)
            for (std::size_t k = 0; k < b.count; ++k) {
                const auto c = b.centres[k];
                out.mean[li][c] = b.mean[li * b.stride + k];
                if (with_sizes) out.size[li][c] = b.size[li * b.stride + k];
            }
    });
    return out;
}

std::size_t detail::disk_mean_batch_count(const std::vector<double>& values)
{
    const auto defined =
        std::size_t(std::count_if(values.begin(), values.end(), [](double v) { return !std::isnan(v); }));
    return (defined + BatchBfs<kWords>::kBatch - 1) / BatchBfs<kWords>::kBatch;
}

void detail::disk_means_batches(const MeshData& data, const Adjacency& adj, const std::vector<double>& values,
                                const std::vector<double>* second, const std::vector<int>& levels, bool with_sizes,
                                const std::function<void(const DiskMeansBatch&)>& sink)
{
    const Mesh& mesh = data.mesh();
    const std::size_t n = adj.size();
    if (values.size() != n || mesh.n_vertices() != n || (second && second->size() != n))
        throw InvalidArgumentError("disk_means: values, adjacency and mesh sizes differ");
    for (int l : levels)
        if (l < 1) throw InvalidArgumentError(fmt::format("disk_means: level {} is < 1", l));
    if (levels.empty() || n == 0) return;
    const int lmax = *std::max_element(levels.begin(), levels.end());

    // Centres with a defined value, in Morton order, cut into batches of kBatch (64 x kWords).
    std::vector<std::uint32_t> centres;
    centres.reserve(n);
    std::vector<std::uint32_t> morton = detail::morton_order(mesh, data.box());
    for (auto v : clustered_order(morton, adj, values, BatchBfs<kWords>::kBatch)) centres.push_back(v);
    const std::size_t n_batches = (centres.size() + BatchBfs<kWords>::kBatch - 1) / BatchBfs<kWords>::kBatch;
    const bool all_defined = centres.size() == n;
    bool word_sums = false;
    for (std::size_t v = 0; v < n && !word_sums; ++v) word_sums = adj.degree(v) > kWordSumDegree;

    // On a mesh whose vertex order scatters neighbours in memory (a shuffled
    // or badly re-indexed file), the search runs on a copy of the graph
    // renumbered in Morton order, so that nearby vertices share cache lines
    // (on igea shuffled, the ring search's time halves). Each vertex keeps its
    // neighbours in their order and the centres their batches, so the search
    // visits the same vertices in the same order as on the input: the sums are
    // the same to the last bit. Only where more than 1/8 of the neighbours are
    // far apart in the input order and twice as many as in the Morton order (a
    // scan's or a grid's order is kept: the copy does not pay there).
    constexpr std::uint32_t kFar = 4096;  // neighbours farther apart in the order than this: far
    auto far_neighbours = [&](const std::uint32_t* rank) {
        std::size_t far = 0;
        for (std::size_t v = 0; v < n; ++v) {
            const std::uint32_t a = rank ? rank[v] : std::uint32_t(v);
            for (const std::uint32_t* it = adj.begin(v); it != adj.end(v); ++it) {
                const std::uint32_t b = rank ? rank[*it] : *it;
                far += (a > b ? a - b : b - a) > kFar;
            }
        }
        return far;
    };
    const std::size_t far_input = far_neighbours(nullptr);
    std::vector<std::uint32_t> rank;
    bool renumber = false;
    if (far_input > adj.index.size() / 8) {
        rank.resize(n);
        for (std::size_t i = 0; i < n; ++i) rank[morton[i]] = std::uint32_t(i);
        renumber = far_input > 2 * far_neighbours(rank.data());
    }
    Adjacency padj;
    std::vector<double> pvalues, pvalues2;
    std::vector<std::uint32_t> pcentres;
    if (renumber) {
        padj.offset.resize(n + 1, 0);
        padj.index.resize(adj.index.size());
        pvalues.resize(n);
        if (second) pvalues2.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t o = morton[i];
            pvalues[i] = values[o];
            if (second) pvalues2[i] = (*second)[o];
            padj.offset[i + 1] = padj.offset[i] + std::uint32_t(adj.degree(o));
            std::uint32_t* to = padj.index.data() + padj.offset[i];
            for (const std::uint32_t* it = adj.begin(o); it != adj.end(o); ++it) *to++ = rank[*it];
        }
        pcentres.resize(centres.size());
        for (std::size_t i = 0; i < centres.size(); ++i) pcentres[i] = rank[centres[i]];
    }
    // The orders are not read by the search: freed before its workspaces are
    // made (8 MB a 1M mesh).
    detail::release(morton);
    detail::release(rank);
    const Adjacency& sadj = renumber ? padj : adj;
    const std::vector<double>& svalues = renumber ? pvalues : values;
    const std::vector<double>* svalues2 = second && renumber ? &pvalues2 : second;
    const std::vector<std::uint32_t>& scentres = renumber ? pcentres : centres;

    detail::StageProgress stage("rings", n_batches);
#pragma omp parallel
    {
        BatchBfs<kWords> bfs(sadj, svalues, svalues2, all_defined, word_sums, lmax);
        constexpr std::size_t kBatch = BatchBfs<kWords>::kBatch;
        std::vector<double> mean(levels.size() * kBatch), mean2(second ? levels.size() * kBatch : 0);
        std::vector<std::uint32_t> size(with_sizes ? levels.size() * kBatch : 0);
        DiskMeansBatch batch;
        batch.worker = omp_get_thread_num();
        batch.mean = mean.data();
        batch.mean2 = second ? mean2.data() : nullptr;
        batch.size = with_sizes ? size.data() : nullptr;
        batch.stride = kBatch;
#pragma omp for schedule(dynamic, 2)
        for (std::ptrdiff_t ib = 0; ib < std::ptrdiff_t(n_batches); ++ib) {
            if (!stage.tick()) continue;
            const std::size_t first = std::size_t(ib) * kBatch;
            const std::size_t nb = std::min<std::size_t>(kBatch, centres.size() - first);
            bfs.run(scentres.data() + first, nb);
            for (std::size_t li = 0; li < levels.size(); ++li) {
                const std::size_t base = std::size_t(levels[li]) * kBatch;
                for (std::size_t k = 0; k < nb; ++k) {
                    const auto cnt = bfs.count[base + k];
                    mean[li * kBatch + k] =
                        cnt > 0 ? bfs.sum[base + k] / double(cnt) : std::numeric_limits<double>::quiet_NaN();
                    if (with_sizes) size[li * kBatch + k] = bfs.size[base + k];
                    if (second) {
                        const auto cnt2 = bfs.count2[base + k];
                        mean2[li * kBatch + k] =
                            cnt2 > 0 ? bfs.sum2[base + k] / double(cnt2) : std::numeric_limits<double>::quiet_NaN();
                    }
                }
            }
            batch.index = std::size_t(ib);
            batch.centres = centres.data() + first;
            batch.count = nb;
            sink(batch);
        }
    }
    stage.finish();
}

std::vector<double> global_means(const std::vector<double>& values)
{
    long double sum = 0.0L;
    std::size_t m = 0;
    for (double v : values)
        if (!std::isnan(v)) {
            sum += v;
            ++m;
        }
    std::vector<double> mean(values.size(), std::numeric_limits<double>::quiet_NaN());
    if (m >= 2)
        for (std::size_t i = 0; i < values.size(); ++i)
            if (!std::isnan(values[i])) mean[i] = double((sum - values[i]) / (long double)(m - 1));
    return mean;
}

}  // namespace meshdiff
