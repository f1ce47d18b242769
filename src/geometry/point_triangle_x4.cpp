#include "geometry/point_triangle_x4.h"

#include <algorithm>
#include <cstdint>

#if MESHDIFF_HAVE_AVX512_KERNELS
#include <immintrin.h>

// Every function here is compiled for AVX2 (not FMA: a fused multiply-add
// would round differently from the baseline build).
#define MESHDIFF_AVX2 __attribute__((target("avx2")))

namespace meshdiff::detail {

namespace {
using V = __m256d;
MESHDIFF_AVX2 inline V lanes(const double* const* s, int k)
{
    return _mm256_setr_pd(s[0][k], s[1][k], s[2][k], s[3][k]);
}
MESHDIFF_AVX2 inline V all(const double* s, int k)
{
    return _mm256_broadcast_sd(s + k);
}
MESHDIFF_AVX2 inline V sub(V x, V y)
{
    return _mm256_sub_pd(x, y);
}
MESHDIFF_AVX2 inline V add(V x, V y)
{
    return _mm256_add_pd(x, y);
}
MESHDIFF_AVX2 inline V mul(V x, V y)
{
    return _mm256_mul_pd(x, y);
}
// Eigen's Vec3 dot product: (x0 y0 + x1 y1) + x2 y2.
MESHDIFF_AVX2 inline V dot(V x0, V x1, V x2, V y0, V y1, V y2)
{
    return add(add(mul(x0, y0), mul(x1, y1)), mul(x2, y2));
}
// Ordered comparisons: false with a NaN, as the scalar ones.
MESHDIFF_AVX2 inline V le(V x, V y)
{
    return _mm256_cmp_pd(x, y, _CMP_LE_OQ);
}
MESHDIFF_AVX2 inline V ge(V x, V y)
{
    return _mm256_cmp_pd(x, y, _CMP_GE_OQ);
}
MESHDIFF_AVX2 inline V both(V x, V y)
{
    return _mm256_and_pd(x, y);
}
// y where not yet decided.
MESHDIFF_AVX2 inline V undecided(V decided, V y)
{
    return _mm256_andnot_pd(decided, y);
}
struct V3
{
    V x, y, z;
};
// r where m, else keep.
MESHDIFF_AVX2 inline void select(V3& keep, const V3& r, V m)
{
    keep.x = _mm256_blendv_pd(keep.x, r.x, m);
    keep.y = _mm256_blendv_pd(keep.y, r.y, m);
    keep.z = _mm256_blendv_pd(keep.z, r.z, m);
}
// o + t u, per component.
MESHDIFF_AVX2 inline V3 along(const V3& o, V t, const V3& u)
{
    return {add(o.x, mul(t, u.x)), add(o.y, mul(t, u.y)), add(o.z, mul(t, u.z))};
}
MESHDIFF_AVX2 inline V3 minus(const V3& u, const V3& v)
{
    return {sub(u.x, v.x), sub(u.y, v.y), sub(u.z, v.z)};
}
MESHDIFF_AVX2 inline V dot(const V3& u, const V3& v)
{
    return dot(u.x, u.y, u.z, v.x, v.y, v.z);
}
}  // namespace

namespace {
// detail::triangle_point(), lane by lane: the same expressions, the region
// tests in the same order (a lane takes the first region whose test holds).
MESHDIFF_AVX2 inline __attribute__((always_inline)) unsigned kernel(const V3& p, const V3& a, const V3& b, const V3& c,
                                                                    double d2[4], double qx[4], double qy[4],
                                                                    double qz[4])
{
    const V zero = _mm256_setzero_pd();

    const V3 ab = minus(b, a), ac = minus(c, a), ap = minus(p, a);
    const V d1 = dot(ab, ap), d2_ = dot(ac, ap);
    const V3 bp = minus(p, b);
    const V d3 = dot(ab, bp), d4 = dot(ac, bp);
    const V vc = sub(mul(d1, d4), mul(d3, d2_));
    const V3 cp = minus(p, c);
    const V d5 = dot(ab, cp), d6 = dot(ac, cp);
    const V vb = sub(mul(d5, d2_), mul(d1, d6));
    const V va = sub(mul(d3, d6), mul(d5, d4));
    const V e43 = sub(d4, d3), e56 = sub(d5, d6);

    const V in_a = both(le(d1, zero), le(d2_, zero));
    V decided = in_a;
    const V in_b = undecided(decided, both(ge(d3, zero), le(d4, d3)));
    decided = _mm256_or_pd(decided, in_b);
    const V in_ab = undecided(decided, both(both(le(vc, zero), ge(d1, zero)), le(d3, zero)));
    decided = _mm256_or_pd(decided, in_ab);
    const V in_c = undecided(decided, both(ge(d6, zero), le(d5, d6)));
    decided = _mm256_or_pd(decided, in_c);
    const V in_ac = undecided(decided, both(both(le(vb, zero), ge(d2_, zero)), le(d6, zero)));
    decided = _mm256_or_pd(decided, in_ac);
    const V in_bc = undecided(decided, both(both(le(va, zero), ge(e43, zero)), ge(e56, zero)));

    // The face region (the rest): p - (n.ap / n.n) n, n = ab x ac.
    const V3 n{sub(mul(ab.y, ac.z), mul(ab.z, ac.y)), sub(mul(ab.z, ac.x), mul(ab.x, ac.z)),
               sub(mul(ab.x, ac.y), mul(ab.y, ac.x))};
    const V s = _mm256_div_pd(dot(n, ap), dot(n, n));
    V3 q{sub(p.x, mul(s, n.x)), sub(p.y, mul(s, n.y)), sub(p.z, mul(s, n.z))};
    select(q, along(a, _mm256_div_pd(d1, sub(d1, d3)), ab), in_ab);
    select(q, along(a, _mm256_div_pd(d2_, sub(d2_, d6)), ac), in_ac);
    select(q, along(b, _mm256_div_pd(e43, add(e43, e56)), minus(c, b)), in_bc);
    select(q, a, in_a);
    select(q, b, in_b);
    select(q, c, in_c);
    const V3 d = minus(p, q);
    _mm256_storeu_pd(d2, dot(d, d));
    _mm256_storeu_pd(qx, q.x);
    _mm256_storeu_pd(qy, q.y);
    _mm256_storeu_pd(qz, q.z);
    return unsigned(_mm256_movemask_pd(in_a)) | unsigned(_mm256_movemask_pd(in_b)) << (4 * kRegionB) |
           unsigned(_mm256_movemask_pd(in_ab)) << (4 * kRegionAB) |
           unsigned(_mm256_movemask_pd(in_c)) << (4 * kRegionC) |
           unsigned(_mm256_movemask_pd(in_ac)) << (4 * kRegionAC) |
           unsigned(_mm256_movemask_pd(in_bc)) << (4 * kRegionBC);
}

MESHDIFF_AVX2 inline V3 gathered(const double* const* s)
{
    return {lanes(s, 0), lanes(s, 1), lanes(s, 2)};
}
MESHDIFF_AVX2 inline V3 broadcast(const double* s)
{
    return {all(s, 0), all(s, 1), all(s, 2)};
}
// The x, y, z of a point and a zero (the fourth double is not read).
MESHDIFF_AVX2 inline V point_xyz(const Vec3& v)
{
    return _mm256_maskload_pd(v.data(), _mm256_setr_epi64x(-1, -1, -1, 0));
}
// Four points (x, y, z, 0) transposed into the lanes of x, y and z.
MESHDIFF_AVX2 inline V3 transposed(V p0, V p1, V p2, V p3)
{
    const V lo01 = _mm256_unpacklo_pd(p0, p1), hi01 = _mm256_unpackhi_pd(p0, p1);  // x0 x1 z0 z1, y0 y1 0 0
    const V lo23 = _mm256_unpacklo_pd(p2, p3), hi23 = _mm256_unpackhi_pd(p2, p3);
    return {_mm256_permute2f128_pd(lo01, lo23, 0x20), _mm256_permute2f128_pd(hi01, hi23, 0x20),
            _mm256_permute2f128_pd(lo01, lo23, 0x31)};
}
}  // namespace

MESHDIFF_AVX2 unsigned closest_points_x4(const PairsX4& in, double d2[4], double qx[4], double qy[4], double qz[4],
                                         SharedX4 shared)
{
    switch (shared) {
        case SharedX4::kTriangle:
            return kernel(gathered(in.p), broadcast(in.a[0]), broadcast(in.b[0]), broadcast(in.c[0]), d2, qx, qy, qz);
        case SharedX4::kNothing:
            break;
    }
    return kernel(gathered(in.p), gathered(in.a), gathered(in.b), gathered(in.c), d2, qx, qy, qz);
}

MESHDIFF_AVX2 unsigned closest_points_indexed_x4(const double* p, const Vec3* points, const std::uint32_t* corners,
                                                 unsigned count, double d2[4], double qx[4], double qy[4], double qz[4])
{
    const std::uint32_t* t[4];
    for (unsigned k = 0; k < 4; ++k) t[k] = corners + 4 * std::min(k, count - 1);
    V3 abc[3];
    for (unsigned i = 0; i < 3; ++i)
        abc[i] = transposed(point_xyz(points[t[0][i]]), point_xyz(points[t[1][i]]), point_xyz(points[t[2][i]]),
                            point_xyz(points[t[3][i]]));
    return kernel(broadcast(p), abc[0], abc[1], abc[2], d2, qx, qy, qz);
}

}  // namespace meshdiff::detail

#else
namespace meshdiff::detail {
unsigned closest_points_x4(const PairsX4&, double*, double*, double*, double*, SharedX4)
{
    return 0;
}
unsigned closest_points_indexed_x4(const double*, const Vec3*, const std::uint32_t*, unsigned, double*, double*,
                                   double*, double*)
{
    return 0;
}
}  // namespace meshdiff::detail
#endif
