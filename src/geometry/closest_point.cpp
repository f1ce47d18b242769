#include "meshdiff/geometry/closest_point.h"

#include "meshdiff/error.h"

#include "core/stage_progress.h"
#include "geometry/bvh_build.h"
#include "geometry/point_triangle_kernels.h"
#include "geometry/point_triangle_x4.h"
#include "geometry/query_block.h"
#include "geometry/simd.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>

#if MESHDIFF_HAVE_AVX512_KERNELS
#include <immintrin.h>
#endif

namespace meshdiff {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNoFace = std::numeric_limits<std::uint32_t>::max();
using detail::Obb;
using detail::Tri;
using detail::WideNode;

inline Vec3 tri_point(const Vec3& p, const Tri& t)
{
    return t.thin ? detail::thin_triangle_point(p, t.a, t.b, t.c) : detail::triangle_point(p, t.a, t.b, t.c);
}

inline double obb_distance2(const Obb& b, const Vec3& p)
{
    const double dx = p.x() - b.centre[0], dy = p.y() - b.centre[1], dz = p.z() - b.centre[2];
    double d2 = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
        const double s = b.axis[k][0] * dx + b.axis[k][1] * dy + b.axis[k][2] * dz;
        const double e = std::max(std::abs(s) - b.half[k], 0.0);
        d2 += e * e;
    }
    return d2;
}

inline double box_distance2(const double* lo, const double* hi, const Vec3& p)
{
    const double ex = std::max(std::max(lo[0] - p.x(), p.x() - hi[0]), 0.0);
    const double ey = std::max(std::max(lo[1] - p.y(), p.y() - hi[1]), 0.0);
    const double ez = std::max(std::max(lo[2] - p.z(), p.z() - hi[2]), 0.0);
    return ex * ex + ey * ey + ez * ez;
}

// The squared distances from p to the boxes of the 4 slots of a wide node
// (+inf for an unused slot), the 4 at once. The float boxes contain the
// binary nodes' boxes and are read exactly as doubles, so these bounds are
// at most those of the exact boxes (rounding is monotonic).
inline void slot_distances2_scalar(const WideNode& n, const Vec3& p, double d2[4])
{
    for (std::size_t s = 0; s < 4; ++s) {
        const double ex = std::max(std::max(double(n.lo[0][s]) - p.x(), p.x() - double(n.hi[0][s])), 0.0);
        const double ey = std::max(std::max(double(n.lo[1][s]) - p.y(), p.y() - double(n.hi[1][s])), 0.0);
        const double ez = std::max(std::max(double(n.lo[2][s]) - p.z(), p.z() - double(n.hi[2][s])), 0.0);
        d2[s] = ex * ex + ey * ey + ez * ez;
    }
}

#if MESHDIFF_HAVE_AVX512_KERNELS
// The same in AVX2 registers (a lane per slot; not FMA), returning the mask
// of the slots with d2 * keep <= best.
__attribute__((target("avx2"))) inline unsigned slot_distances2_avx2(const WideNode& n, const Vec3& p, double keep,
                                                                     double best, double d2[4])
{
    const __m256d zero = _mm256_setzero_pd();
    __m256d e[3];
    for (std::size_t a = 0; a < 3; ++a) {
        const __m256d q = _mm256_set1_pd(p[Eigen::Index(a)]);
        const __m256d lo = _mm256_cvtps_pd(_mm_load_ps(n.lo[a].data()));
        const __m256d hi = _mm256_cvtps_pd(_mm_load_ps(n.hi[a].data()));
        e[a] = _mm256_max_pd(_mm256_max_pd(_mm256_sub_pd(lo, q), _mm256_sub_pd(q, hi)), zero);
    }
    const __m256d sum =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(e[0], e[0]), _mm256_mul_pd(e[1], e[1])), _mm256_mul_pd(e[2], e[2]));
    _mm256_storeu_pd(d2, sum);
    return unsigned(
        _mm256_movemask_pd(_mm256_cmp_pd(_mm256_mul_pd(sum, _mm256_set1_pd(keep)), _mm256_set1_pd(best), _CMP_LE_OQ)));
}
#endif

// The closures of the query are inlined into it, so that they are compiled
// for its target (AVX2 or the baseline).
#define MESHDIFF_INLINE __attribute__((always_inline))

// Queries per parallel block (fixed: results do not depend on threads).
constexpr std::size_t kBlock = detail::kQueryBlock;

// An entry of the searches' stacks: a wide node or a leaf, with its bound.
struct Entry
{
    std::uint32_t ref;    // wide node, or the leaf's first triangle
    std::uint32_t count;  // leaf: triangles; wide node: 0 (hull search: see hull_query)
    double d2;
};

// Pushes the slots of \p node in the bitmask \p live, at squared distances
// \p d2, onto \p stack (\p top entries): the farthest first, so that the
// nearest is popped first.
MESHDIFF_INLINE inline void push_farthest_first(const WideNode& node, unsigned live, const double* d2, Entry* stack,
                                                std::size_t& top)
{
    if (live == 0) return;
    if ((live & (live - 1u)) == 0) {
        const auto s = unsigned(__builtin_ctz(live));
        stack[top++] = {node.child[s], node.count[s], d2[s]};
        return;
    }
    unsigned order[4];
    unsigned m = 0;
    for (; live != 0; live &= live - 1u) {
        const auto s = unsigned(__builtin_ctz(live));
        // Insertion by decreasing distance.
        unsigned j = m++;
        while (j > 0 && d2[order[j - 1]] < d2[s]) {
            order[j] = order[j - 1];
            --j;
        }
        order[j] = s;
    }
    for (unsigned j = 0; j < m; ++j) {
        const unsigned s = order[j];
        stack[top++] = {node.child[s], node.count[s], d2[s]};
    }
}

}  // namespace

struct ClosestPointIndex::Impl : detail::Bvh
{
    // The oriented box of slot `bit` (< 4) or half `bit` - 4 of node n (its
    // bit of obb_mask is set).
    const Obb& obb(const WideNode& n, unsigned bit) const
    {
        return obbs[n.obb_first + unsigned(__builtin_popcount(unsigned(n.obb_mask) & ((1u << bit) - 1u)))];
    }
    // A lower bound of the distance^2 from p to any triangle: the root's box,
    // or its oriented box if that is farther.
    double root_distance2(const Vec3& p) const
    {
        const double d2 = box_distance2(root_lo.data(), root_hi.data(), p);
        if (root_obb == kNoFace) return d2;
        return std::max(d2, obb_distance2(obbs[root_obb], p));
    }
    // Lexicographic minimum of (squared distance, face) over all triangles;
    // `hint` (a position in `tris`, or kNoFace) only changes the search order:
    // the search starts in the hint's leaf and climbs towards the root.
    // `region`, if given: the Voronoi region of the closest point's triangle
    // it lies in (detail::kRegionA ..., geometry/point_triangle_x4.h), or
    // kRegionUnknown where that triangle was not given to the four-lane kernel.
    ClosestPoint query(const Vec3& p, std::uint32_t hint, std::uint32_t* hit, unsigned* region = nullptr) const
    {
#if MESHDIFF_HAVE_AVX512_KERNELS
        if (detail::use_avx2()) return query_avx2(p, hint, hit, region);
#endif
        return search<false>(p, hint, hit, region);
    }
#if MESHDIFF_HAVE_AVX512_KERNELS
    // The query compiled for AVX2 (not FMA: the same roundings), the box
    // tests and the leaves' triangles four at once.
    __attribute__((target("avx2"))) ClosestPoint query_avx2(const Vec3& p, std::uint32_t hint, std::uint32_t* hit,
                                                            unsigned* region) const
    {
        return search<true>(p, hint, hit, region);
    }
#endif
    template <bool kAvx2>
    __attribute__((always_inline)) inline ClosestPoint search(const Vec3& p, std::uint32_t hint, std::uint32_t* hit,
                                                              unsigned* region) const;
    // Smallest over triangles of the largest squared distance from the corners
    // c to the triangle, stopping at the first value <= good2.
    double hull_query(const std::array<Vec3, 3>& c, double good2, std::uint32_t* face) const;
};

template <bool kAvx2>
inline ClosestPoint ClosestPointIndex::Impl::search(const Vec3& p, std::uint32_t hint, std::uint32_t* hit,
                                                    unsigned* region) const
{
    double best_d2 = kInf;
    std::uint32_t best_face = kNoFace;
    std::uint32_t best_pos = kNoFace;
    Vec3 best_point = Vec3::Zero();
    // The best's region: lane best_lane of the kernel's masks best_masks
    // (best_lane 4: not from the kernel).
    unsigned best_masks = 0, best_lane = 4;
    auto offer = [&](double d2, std::uint32_t pos, std::uint32_t face, const Vec3& q) MESHDIFF_INLINE {
        if (d2 < best_d2 || (d2 == best_d2 && face < best_face)) {
            best_d2 = d2;
            best_face = face;
            best_pos = pos;
            best_point = q;
            return true;
        }
        return false;
    };
    auto consider = [&](std::uint32_t pos) MESHDIFF_INLINE {
        const Tri t = tris[pos];
        const Vec3 q = tri_point(p, t);
        if (offer((p - q).squaredNorm(), pos, t.face, q)) best_lane = 4;
    };
    // A leaf's triangles: with AVX2, up to four at once (bitwise the same
    // values, geometry/point_triangle_x4.h); thin ones one by one.
    constexpr bool x4 = kAvx2;
    auto consider_leaf = [&](std::uint32_t first, std::uint32_t count) MESHDIFF_INLINE {
        if (!x4 || count < 2) {
            for (std::uint32_t i = 0; i < count; ++i) consider(first + i);
            return;
        }
        // Lanes past the leaf's last triangle repeat it.
        const detail::LeafTriangles::Corners* c = &tris.corners[first];
        std::uint32_t face[4];
        unsigned thin = 0;
        for (std::uint32_t k = 0; k < 4; ++k) {
            const std::uint32_t word = c[std::min(k, count - 1)].face_thin;
            face[k] = detail::LeafTriangles::face_of(word);
            thin |= unsigned(detail::LeafTriangles::thin_of(word)) << k;
        }
        double d2[4], qx[4], qy[4], qz[4];
        const unsigned masks =
            detail::closest_points_indexed_x4(p.data(), tris.points.data(), c->v.data(), count, d2, qx, qy, qz);
        if (thin == 0 && !std::isnan((d2[0] + d2[1]) + (d2[2] + d2[3]))) {
            // The lanes' lexicographic minimum of (d2, face), without
            // branches, offered alone: the offers keep the minimum, which
            // does not depend on their order (no NaN: the order is total).
            // Ties go to the lower lane, so a repeated lane is never taken.
            auto below = [&](unsigned i, unsigned j) MESHDIFF_INLINE {
                return bool((d2[i] < d2[j]) | ((d2[i] == d2[j]) & (face[i] < face[j])));
            };
            const unsigned w01 = unsigned(below(1, 0));
            const unsigned w23 = 2u + unsigned(below(3, 2));
            const unsigned w = below(w23, w01) ? w23 : w01;
            if (offer(d2[w], first + w, face[w], Vec3(qx[w], qy[w], qz[w]))) {
                best_masks = masks;
                best_lane = w;
            }
            return;
        }
        for (std::uint32_t i = 0; i < count; ++i) {
            if (thin & (1u << i)) {
                consider(first + i);
            } else if (offer(d2[i], first + i, face[i], Vec3(qx[i], qy[i], qz[i]))) {
                best_masks = masks;
                best_lane = i;
            }
        }
    };

    // A node is skipped only if its box is farther than the best so far by a
    // margin above rounding, so that ties and near-ties are still examined.
    // The answer, a lexicographic minimum, does not depend on the order in
    // which the triangles are offered.
    constexpr double keep = 1.0 - 1e-12;
    std::array<Entry, 256> stack;
    std::size_t top = 0;
    // Pushes the slots of wide node w but `skip`, the farthest first so that
    // the nearest is visited first.
    auto push_slots = [&](std::uint32_t w, unsigned skip) MESHDIFF_INLINE {
        const WideNode& node = nodes[w];
        double d2[4];
        // The slots to visit: used, not `skip`, not pruned.
        unsigned live = 0;
#if MESHDIFF_HAVE_AVX512_KERNELS
        if constexpr (kAvx2) {
            live = slot_distances2_avx2(node, p, keep, best_d2, d2);
        } else
#endif
        {
            slot_distances2_scalar(node, p, d2);
            for (unsigned s = 0; s < 4; ++s) live |= unsigned(d2[s] * keep <= best_d2) << s;
        }
        if (node.obb_mask & 0xFu) {
            for (unsigned s = 0; s < node.slots; ++s) {
                if (node.obb_mask & (1u << s)) {
                    d2[s] = std::max(d2[s], obb_distance2(obb(node, s), p));
                    if (!(d2[s] * keep <= best_d2)) live &= ~(1u << s);
                }
            }
        }
        live &= ((1u << node.slots) - 1u) & ~(1u << skip);
        push_farthest_first(node, live, d2, stack.data(), top);
    };
    // Branch and bound over the entries on the stack.
    auto run = [&]() MESHDIFF_INLINE {
        while (top > 0) {
            const Entry e = stack[--top];
            if (e.d2 * keep > best_d2) continue;
            if (e.count > 0)
                consider_leaf(e.ref, e.count);
            else
                push_slots(e.ref, 4);
        }
    };

    if (nodes.empty()) {
        consider_leaf(0, root_count);
    } else if (hint == kNoFace) {
        stack[top++] = {0, 0, root_distance2(p)};
        run();
    } else {
        // Start in the hint's leaf and climb to the root, searching the other
        // slots at each level: every triangle is below exactly one of them.
        std::uint32_t w = leaf_of[hint] / 4;
        unsigned slot = leaf_of[hint] % 4;
        consider_leaf(nodes[w].child[slot], nodes[w].count[slot]);
        for (;;) {
            push_slots(w, slot);
            run();
            if (w == 0) break;
            slot = parent_of[w] % 4;
            w = parent_of[w] / 4;
        }
    }
    if (hit) *hit = best_pos;
    if (region) *region = best_lane < 4 ? detail::lane_region(best_masks, best_lane) : detail::kRegionUnknown;
    ClosestPoint r;
    r.distance = std::sqrt(best_d2);
    r.point = best_point;
    r.face = best_face;
    return r;
}

double ClosestPointIndex::Impl::hull_query(const std::array<Vec3, 3>& c, double good2, std::uint32_t* face) const
{
    double best = kInf;
    std::uint32_t best_face = kNoFace;
    // With a target (good2 > 0) only a value <= good2 is of interest: a node
    // or a triangle that cannot reach it is skipped. Without one (good2 <=
    // 0), the minimum is searched.
    const double cut = good2 > 0.0 ? good2 : kInf;
    // The search walks the binary tree the wide nodes were made from, in its
    // order and with its exact boxes (the first value found depends on both):
    // an entry is a wide node (count 0: its binary node), the left or right
    // half of one (count kHalf + h: the binary child whose children are two
    // slots), or a leaf (count kLeaf + its triangles).
    constexpr std::uint32_t kHalf = 1, kLeaf = 8;
    // A node's bound: no triangle below it is closer to corner i than its
    // box, so the largest of the three box distances bounds the value of
    // every triangle below it from below.
    auto bound = [&](const double* lo, const double* hi, const Obb* o) {
        double v[3];
        for (std::size_t i = 0; i < 3; ++i) {
            v[i] = box_distance2(lo, hi, c[i]);
            if (o) v[i] = std::max(v[i], obb_distance2(*o, c[i]));
        }
        return std::max({v[0], v[1], v[2]});
    };
    // The entry of slot s of wide node n, with its binary node's exact box:
    // a wide node's, or a leaf's, the box of its triangles' corners (as the
    // build made it).
    auto slot_box = [&](const WideNode& n, unsigned s, double lo[3], double hi[3]) {
        if (n.count[s] == 0) {
            const std::array<double, 6>& b = exact_box[n.child[s]];
            for (std::size_t a = 0; a < 3; ++a) {
                lo[a] = b[a];
                hi[a] = b[3 + a];
            }
            return;
        }
        for (std::size_t a = 0; a < 3; ++a) {
            lo[a] = kInf;
            hi[a] = -kInf;
        }
        for (std::uint32_t i = n.child[s]; i < n.child[s] + n.count[s]; ++i) {
            const Tri t = tris[i];
            for (const Vec3* q : {&t.a, &t.b, &t.c}) {
                for (std::size_t a = 0; a < 3; ++a) {
                    lo[a] = std::min(lo[a], (*q)[Eigen::Index(a)]);
                    hi[a] = std::max(hi[a], (*q)[Eigen::Index(a)]);
                }
            }
        }
    };
    auto slot_entry = [&](const WideNode& n, unsigned s) {
        double lo[3], hi[3];
        slot_box(n, s, lo, hi);
        const Obb* o = n.obb_mask & (1u << s) ? &obb(n, s) : nullptr;
        return Entry{n.child[s], n.count[s] == 0 ? 0u : kLeaf + n.count[s], bound(lo, hi, o)};
    };
    // The entry of half h of wide node w: a leaf's slot, or the binary node
    // over two slots, whose box is the union of theirs.
    auto half_entry = [&](std::uint32_t w, unsigned h) {
        const WideNode& n = nodes[w];
        const unsigned s0 = h == 0 ? 0u : n.split;
        const unsigned width = h == 0 ? n.split : unsigned(n.slots - n.split);
        if (width == 1) return slot_entry(n, s0);
        double lo[3], hi[3], lo1[3], hi1[3];
        slot_box(n, s0, lo, hi);
        slot_box(n, s0 + 1, lo1, hi1);
        for (std::size_t a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], lo1[a]);
            hi[a] = std::max(hi[a], hi1[a]);
        }
        const Obb* o = n.obb_mask & (1u << (4 + h)) ? &obb(n, 4 + h) : nullptr;
        return Entry{w, kHalf + h, bound(lo, hi, o)};
    };
    std::array<Entry, 128> stack;
    std::size_t top = 0;
    {
        const Obb* o = root_obb == kNoFace ? nullptr : &obbs[root_obb];
        const double d2 = bound(root_lo.data(), root_hi.data(), o);
        stack[top++] = nodes.empty() ? Entry{0, kLeaf + root_count, d2} : Entry{0, 0, d2};
    }
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.d2 >= best || e.d2 > cut) continue;
        if (e.count >= kLeaf) {
            for (std::uint32_t i = 0; i < e.count - kLeaf; ++i) {
                const Tri t = tris[e.ref + i];
                double v = 0.0;
                for (const Vec3& q : c) {
                    v = std::max(v, (q - tri_point(q, t)).squaredNorm());
                    if (v >= best || v > cut) break;
                }
                if (v < best && v <= cut) {
                    best = v;
                    best_face = t.face;
                    if (best <= good2) {
                        if (face) *face = best_face;
                        return best;
                    }
                }
            }
            continue;
        }
        Entry l, r;
        if (e.count == 0) {
            l = half_entry(e.ref, 0);
            r = half_entry(e.ref, 1);
        } else {
            const WideNode& n = nodes[e.ref];
            const unsigned s0 = e.count == kHalf ? 0u : n.split;
            l = slot_entry(n, s0);
            r = slot_entry(n, s0 + 1);
        }
        const Entry& near = l.d2 <= r.d2 ? l : r;
        const Entry& far = l.d2 <= r.d2 ? r : l;
        if (far.d2 < best && far.d2 <= cut) stack[top++] = far;
        if (near.d2 < best && near.d2 <= cut) stack[top++] = near;
    }
    if (face) *face = best_face;
    return best;
}

ClosestPointIndex::ClosestPointIndex(const Mesh& mesh) : impl_(std::make_unique<Impl>())
{
    validate(mesh, "ClosestPointIndex");
    detail::build_bvh(mesh, *impl_);
}

ClosestPointIndex::ClosestPointIndex(const MeshData& data) : impl_(std::make_unique<Impl>())
{
    data.validate("ClosestPointIndex");
    detail::build_bvh(data.mesh(), *impl_);
}

ClosestPointIndex::~ClosestPointIndex() = default;
ClosestPointIndex::ClosestPointIndex(ClosestPointIndex&&) noexcept = default;
ClosestPointIndex& ClosestPointIndex::operator=(ClosestPointIndex&&) noexcept = default;

ClosestPoint ClosestPointIndex::closest_point(const Vec3& p) const
{
    return impl_->query(p, kNoFace, nullptr);
}

ClosestPoint ClosestPointIndex::closest_point(const Vec3& p, std::uint32_t near_face) const
{
    const std::uint32_t hint = near_face < impl_->position_of.size() ? impl_->position_of[near_face] : kNoFace;
    return impl_->query(p, hint, nullptr);
}

namespace {
// Runs f(i, hint) -> hit over fixed blocks of queries in parallel; within a
// block, each query is seeded with the previous query's triangle. `beside`,
// if given, is run once by one of the threads before it takes blocks (the
// others take blocks meanwhile: the team is not oversubscribed); an exception
// it throws is rethrown once the blocks are done. `order`, if given (a
// permutation of 0 .. n - 1), is the order of the queries: block b runs
// queries order[b * kBlock] ..., so that the blocks follow it.
template <class F>
void for_blocks(std::size_t n, F&& f, const std::function<void()>& beside = {}, const std::uint32_t* order = nullptr)
{
    const auto n_blocks = std::int64_t((n + kBlock - 1) / kBlock);
    detail::StageProgress stage("distances", n);
    std::exception_ptr failed;
#pragma omp parallel
    {
        if (beside) {
#pragma omp single nowait
            {
                try {
                    beside();
                } catch (...) {
                    failed = std::current_exception();
                }
            }
        }
#pragma omp for schedule(dynamic, 1)
        for (std::int64_t b = 0; b < n_blocks; ++b) {
            const std::size_t end = std::min(n, std::size_t(b + 1) * kBlock);
            if (!stage.tick(end - std::size_t(b) * kBlock)) continue;
            std::uint32_t hint = kNoFace;
            if (order)
                for (std::size_t j = std::size_t(b) * kBlock; j < end; ++j) hint = f(std::size_t(order[j]), hint);
            else
                for (std::size_t i = std::size_t(b) * kBlock; i < end; ++i) hint = f(i, hint);
        }
    }
    if (failed) std::rethrow_exception(failed);
    stage.finish();
}
}  // namespace

const detail::Bvh& detail::bvh_of(const ClosestPointIndex& index)
{
    return *index.impl_;
}

std::vector<ClosestPoint> ClosestPointIndex::closest_points(const std::vector<Vec3>& queries) const
{
    std::vector<ClosestPoint> out(queries.size());
    const Impl& impl = *impl_;
    for_blocks(queries.size(), [&](std::size_t i, std::uint32_t hint) {
        std::uint32_t hit = kNoFace;
        out[i] = impl.query(queries[i], hint, &hit);
        return hit;
    });
    return out;
}

std::vector<double> ClosestPointIndex::distances(const std::vector<Vec3>& queries) const
{
    std::vector<double> out(queries.size());
    distances(queries.data(), queries.size(), out.data());
    return out;
}

void ClosestPointIndex::distances(const Vec3* queries, std::size_t n, double* out) const
{
    const Impl& impl = *impl_;
    for_blocks(n, [&](std::size_t i, std::uint32_t hint) {
        std::uint32_t hit = kNoFace;
        out[i] = impl.query(queries[i], hint, &hit).distance;
        return hit;
    });
}

void ClosestPointIndex::distances(const Vec3* queries, std::size_t n, double* out,
                                  const std::function<void(std::size_t, const ClosestPoint&)>& visit) const
{
    const Impl& impl = *impl_;
    for_blocks(n, [&](std::size_t i, std::uint32_t hint) {
        std::uint32_t hit = kNoFace;
        const ClosestPoint c = impl.query(queries[i], hint, &hit);
        out[i] = c.distance;
        visit(i, c);
        return hit;
    });
}

void detail::distances_with_regions(
    const ClosestPointIndex& index, const Vec3* queries, std::size_t n, double* out,
    const std::function<void(std::size_t, const ClosestPoint&, unsigned, std::uint32_t)>& visit,
    const std::function<void()>& beside, const std::uint32_t* order)
{
    const ClosestPointIndex::Impl& impl = *index.impl_;
    if (!visit) {
        for_blocks(
            n,
            [&](std::size_t i, std::uint32_t hint) {
                std::uint32_t hit = kNoFace;
                out[i] = impl.query(queries[i], hint, &hit).distance;
                return hit;
            },
            beside, order);
        return;
    }
    for_blocks(
        n,
        [&](std::size_t i, std::uint32_t hint) {
            std::uint32_t hit = kNoFace;
            unsigned region = kRegionUnknown;
            const ClosestPoint c = impl.query(queries[i], hint, &hit, &region);
            out[i] = c.distance;
            visit(i, c, region, hit);
            return hit;
        },
        beside, order);
}

double ClosestPointIndex::hull_distance_bound(const std::array<Vec3, 3>& corners, double good_enough,
                                              std::uint32_t* face) const
{
    if (impl_->tris.empty()) {
        if (face) *face = kNoFace;
        return kInf;
    }
    const double good2 = good_enough > 0.0 ? good_enough * good_enough : (good_enough == 0.0 ? 0.0 : -1.0);
    return std::sqrt(impl_->hull_query(corners, good2, face));
}

std::size_t ClosestPointIndex::n_faces() const
{
    return impl_->tris.size();
}

BoundingBox ClosestPointIndex::bounds() const
{
    BoundingBox b;
    b.min = Vec3(impl_->root_lo[0], impl_->root_lo[1], impl_->root_lo[2]);
    b.max = Vec3(impl_->root_hi[0], impl_->root_hi[1], impl_->root_hi[2]);
    return b;
}

std::size_t ClosestPointIndex::memory_bytes() const
{
    return impl_->tris.memory_bytes() + impl_->nodes.capacity() * sizeof(WideNode) +
           impl_->exact_box.capacity() * sizeof(std::array<double, 6>) + impl_->obbs.capacity() * sizeof(Obb) +
           (impl_->parent_of.capacity() + impl_->leaf_of.capacity() + impl_->position_of.capacity()) *
               sizeof(std::uint32_t);
}

}  // namespace meshdiff
