//! \file roughness/normal_equations.h
//! \brief The small least-squares solve of the curvature fits (curvature.cpp)
//! by equilibrated normal equations, for well-conditioned systems only
//! (issue 30, lever 1).
//!
//! min |M x - b| for M of C columns (7 or 9) and a few dozen rows: the columns
//! scaled to unit norm (S = diag(1 / |M_j|)), the C x C Gram matrix
//! (M S)^T (M S) = L L^T by Cholesky, x = S (L L^T)^-1 S M^T b, then one step of
//! iterative refinement with the residual b - M x computed from M itself.
//!
//! It declines (returns false; the caller then solves by its column-pivoting
//! QR, exactly as before) unless two bounds hold, both from
//! sigma_min(M S) >= 1 / |L^-1|_F (L^-1 is computed):
//! - accuracy: the condition number of M S, at most sqrt(C) |L^-1|_F, is below
//!   kNormalEquationsMaxCondition (core/tolerances.h). The normal equations
//!   square it: the first solution's relative error is of the order of
//!   kappa^2 u <= 1e-8 (u = 1.1e-16), and the refinement step multiplies that
//!   error by about kappa^2 u again, down to the level of the QR's own
//!   rounding (kappa u);
//! - rank: the caller's QR would find full rank, with a margin. The QR counts
//!   a pivot |R_ii| as nonzero when it exceeds rank_threshold times its largest
//!   pivot; every |R_ii| >= sigma_min(M) >= min_j |M_j| / |L^-1|_F, and the
//!   largest pivot is at most max_j |M_j|. So when
//!   |L^-1|_F max_j |M_j| / min_j |M_j| <= kNormalEquationsRankMargin / rank_threshold
//!   the QR's rank is C by a factor 1 / kNormalEquationsRankMargin beyond its
//!   own rounding, and the fit's rank decisions (the degree-2 and quadric
//!   fallbacks) are the QR's, unchanged: a system near rank deficiency always
//!   goes to the QR.
//! Plain loops in a fixed order (no reduction whose order depends on the
//! alignment of a buffer): the result depends on M and b alone, never on the
//! thread or the buffer that holds them.
#pragma once

#include "meshdiff/core/tolerances.h"

#include "geometry/simd.h"

#include <Eigen/Core>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace meshdiff::detail {

#if defined(__x86_64__)
//! The Gram matrix's lower triangle and M^T b of solve_by_normal_equations()
//! with AVX2: for each row, in row order, the same products added to the same
//! sums as the scalar loop (a row j of G at once: m[j] times m[0..j]), so the
//! same sums to the last bit (multiplications and additions, no fused ones).
template <int C, class MatrixType, class VectorType>
__attribute__((target("avx2"))) void gram_avx2(const MatrixType& M, const VectorType& b,
                                               std::array<std::array<double, C>, C>& G, std::array<double, C>& c)
{
    constexpr int P = (C + 3) / 4 * 4;
    alignas(32) double g[C][P] = {};
    alignas(32) double cc[P] = {};
    for (Eigen::Index i = 0; i < M.rows(); ++i) {
        // The row in registers, made from its entries (not stored and loaded
        // back: a load of four separate stores waits for them), zero beyond C.
        __m256d m[P / 4];
        for (int q = 0; q < P; q += 4)
            m[q / 4] = _mm256_set_pd(q + 3 < C ? M(i, q + 3) : 0.0, q + 2 < C ? M(i, q + 2) : 0.0,
                                     q + 1 < C ? M(i, q + 1) : 0.0, M(i, q));
        const __m256d bi = _mm256_set1_pd(b(i));
        for (int q = 0; q < P; q += 4)
            _mm256_store_pd(cc + q, _mm256_add_pd(_mm256_load_pd(cc + q), _mm256_mul_pd(m[q / 4], bi)));
        for (int j = 0; j < C; ++j) {
            const __m256d mj = _mm256_set1_pd(M(i, j));
            for (int q = 0; q <= j; q += 4)
                _mm256_store_pd(g[j] + q, _mm256_add_pd(_mm256_load_pd(g[j] + q), _mm256_mul_pd(mj, m[q / 4])));
        }
    }
    for (int j = 0; j < C; ++j) {
        c[j] = cc[j];
        for (int k = 0; k <= j; ++k) G[j][k] = g[j][k];
    }
}
#endif

//! The lower triangle of M^T M into G and M^T b into c (both zero on entry),
//! row by row in row order: with AVX2 by gram_avx2(), else by plain loops,
//! the same sums to the last bit.
template <int C, class MatrixType, class VectorType>
void gram(const MatrixType& M, const VectorType& b, std::array<std::array<double, C>, C>& G, std::array<double, C>& c)
{
#if defined(__x86_64__)
    if (use_avx2()) {
        gram_avx2<C>(M, b, G, c);
        return;
    }
#endif
    for (Eigen::Index i = 0; i < M.rows(); ++i) {
        std::array<double, C> m;
        for (int j = 0; j < C; ++j) m[j] = M(i, j);
        const double bi = b(i);
        for (int j = 0; j < C; ++j) {
            c[j] += m[j] * bi;
            for (int k = 0; k <= j; ++k) G[j][k] += m[j] * m[k];
        }
    }
}

//! The right-hand side of the refinement step, M^T (b - M x), into rc (zero
//! on entry): the residual from M (the rows independent of each other, so
//! first all of them), then M^T residual in row order.
template <int C, class MatrixType, class VectorType>
void refinement_rhs(const MatrixType& M, const VectorType& b, const std::array<double, C>& x, std::array<double, C>& rc)
{
    const Eigen::Index rows = M.rows();
    constexpr Eigen::Index kRowsOnStack = 256;
    std::array<double, kRowsOnStack> residual_on_stack;
    std::vector<double> residual_on_heap;
    double* res = residual_on_stack.data();
    if (rows > kRowsOnStack) {
        residual_on_heap.resize(std::size_t(rows));
        res = residual_on_heap.data();
    }
    for (Eigen::Index i = 0; i < rows; ++i) {
        double r = b(i);
        for (int j = 0; j < C; ++j) r -= M(i, j) * x[j];
        res[i] = r;
    }
    for (Eigen::Index i = 0; i < rows; ++i)
        for (int j = 0; j < C; ++j) rc[j] += M(i, j) * res[i];
}

//! Solves min |M x - b| (M: rows x C, rows >= C) into x, or returns false when
//! the system is not certainly well conditioned (see the file comment).
template <int C, class MatrixType, class VectorType>
bool solve_by_normal_equations(const Eigen::MatrixBase<MatrixType>& M, const Eigen::MatrixBase<VectorType>& b,
                               double rank_threshold, std::array<double, C>& x)
{
    const Eigen::Index rows = M.rows();
    if (M.cols() != C || rows < C) return false;
    // Lower triangle of M^T M and M^T b.
    std::array<std::array<double, C>, C> G{};
    std::array<double, C> c{};
    gram<C>(M, b, G, c);
    // Equilibration: column norms d_j, scale s_j = 1 / d_j.
    std::array<double, C> s;
    double d_min = 0.0, d_max = 0.0;
    for (int j = 0; j < C; ++j) {
        if (!(G[j][j] > 0.0) || !std::isfinite(G[j][j])) return false;
        const double d = std::sqrt(G[j][j]);
        s[j] = 1.0 / d;
        d_min = j == 0 ? d : std::min(d_min, d);
        d_max = std::max(d_max, d);
    }
    // Cholesky of the scaled Gram matrix (unit diagonal), L in place, and the
    // reciprocals of its diagonal, rd[j] = 1 / L[j][j]: every division by a
    // diagonal entry below is a multiplication by its reciprocal (a chain of
    // divisions waits about 13 cycles a link; a multiplication 3 or 4).
    std::array<std::array<double, C>, C> L{};
    std::array<double, C> rd;
    for (int j = 0; j < C; ++j) {
        double djj = 1.0;
        for (int k = 0; k < j; ++k) djj -= L[j][k] * L[j][k];
        if (!(djj > 0.0)) return false;
        L[j][j] = std::sqrt(djj);
        rd[j] = 1.0 / L[j][j];
        for (int i = j + 1; i < C; ++i) {
            double v = G[i][j] * s[i] * s[j];
            for (int k = 0; k < j; ++k) v -= L[i][k] * L[j][k];
            L[i][j] = v * rd[j];
        }
    }
    // |L^-1|_F^2 from the lower-triangular inverse, inv[j][i] = (L^-1)_ij:
    // each entry by forward substitution down its column j, but the columns
    // interleaved row by row, so that the steps of a row do not wait on each
    // other; the sum then in column order.
    std::array<std::array<double, C>, C> inv;
    for (int j = 0; j < C; ++j) inv[j][j] = rd[j];
    for (int i = 1; i < C; ++i)
        for (int j = 0; j < i; ++j) {
            double v = 0.0;
            for (int k = j; k < i; ++k) v -= L[i][k] * inv[j][k];
            inv[j][i] = v * rd[i];
        }
    double inv_norm2 = 0.0;
    for (int j = 0; j < C; ++j)
        for (int i = j; i < C; ++i) inv_norm2 += inv[j][i] * inv[j][i];
    if (!(double(C) * inv_norm2 <= kNormalEquationsMaxCondition * kNormalEquationsMaxCondition)) return false;
    const double rank_bound = kNormalEquationsRankMargin / rank_threshold * d_min / d_max;
    if (!(inv_norm2 <= rank_bound * rank_bound)) return false;

    // x = S (L L^T)^-1 S rhs for a right-hand side rhs = M^T b (or M^T residual).
    auto solve = [&](const std::array<double, C>& rhs, std::array<double, C>& out) {
        std::array<double, C> y;
        for (int i = 0; i < C; ++i) {
            double v = rhs[i] * s[i];
            for (int k = 0; k < i; ++k) v -= L[i][k] * y[k];
            y[i] = v * rd[i];
        }
        for (int i = C - 1; i >= 0; --i) {
            double v = y[i];
            for (int k = i + 1; k < C; ++k) v -= L[k][i] * y[k];
            y[i] = v * rd[i];
        }
        for (int i = 0; i < C; ++i) out[i] = y[i] * s[i];
    };
    solve(c, x);
    // One refinement step.
    std::array<double, C> rc{};
    refinement_rhs<C>(M, b, x, rc);
    std::array<double, C> dx;
    solve(rc, dx);
    for (int j = 0; j < C; ++j) x[j] += dx[j];
    return true;
}

#if defined(__x86_64__)
//! Four systems' factors for solve_by_normal_equations_x4(), lane l of each
//! entry being system l's.
template <int C>
struct NormalEquationsX4
{
    alignas(32) double G[C][C][4];  //!< in: the Gram matrices' lower triangles (gram())
    alignas(32) double c[C][4];     //!< in: M^T b
    alignas(32) double s[C][4];
    alignas(32) double L[C][C][4];
    alignas(32) double rd[C][4];
    alignas(32) double x[C][4];  //!< out: the first solution
};

//! out = S (L L^T)^-1 S rhs on the four lanes of f's factors, as the scalar
//! solve does it.
template <int C>
__attribute__((target("avx2"))) void solve_x4(const NormalEquationsX4<C>& f, const double (&rhs)[C][4],
                                              double (&out)[C][4])
{
    using V = __m256d;
    V y[C];
    for (int i = 0; i < C; ++i) {
        V v = _mm256_mul_pd(_mm256_load_pd(rhs[i]), _mm256_load_pd(f.s[i]));
        for (int k = 0; k < i; ++k) v = _mm256_sub_pd(v, _mm256_mul_pd(_mm256_load_pd(f.L[i][k]), y[k]));
        y[i] = _mm256_mul_pd(v, _mm256_load_pd(f.rd[i]));
    }
    for (int i = C - 1; i >= 0; --i) {
        V v = y[i];
        for (int k = i + 1; k < C; ++k) v = _mm256_sub_pd(v, _mm256_mul_pd(_mm256_load_pd(f.L[k][i]), y[k]));
        y[i] = _mm256_mul_pd(v, _mm256_load_pd(f.rd[i]));
    }
    for (int i = 0; i < C; ++i) _mm256_store_pd(out[i], _mm256_mul_pd(y[i], _mm256_load_pd(f.s[i])));
}

//! The steps of solve_by_normal_equations() after the Gram matrix, for four
//! systems at once, one in each lane of the AVX2 registers: the same
//! operations in the same order on each lane as the scalar code makes
//! (multiplications, additions, subtractions, divisions and square roots, no
//! fused ones: the same bits), the declines as a lane mask instead of
//! returns. Returns the lanes whose systems are well conditioned; their
//! first solution is in f.x.
template <int C>
__attribute__((target("avx2"))) unsigned factor_and_solve_x4(NormalEquationsX4<C>& f, double rank_threshold)
{
    using V = __m256d;
    const V one = _mm256_set1_pd(1.0), zero = _mm256_setzero_pd();
    V ok = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    // Equilibration.
    V d_min = zero, d_max = zero;
    for (int j = 0; j < C; ++j) {
        const V g = _mm256_load_pd(f.G[j][j]);
        ok = _mm256_and_pd(
            ok, _mm256_and_pd(_mm256_cmp_pd(g, zero, _CMP_GT_OQ),
                              _mm256_cmp_pd(g, _mm256_set1_pd(std::numeric_limits<double>::infinity()), _CMP_LT_OQ)));
        const V d = _mm256_sqrt_pd(g);
        _mm256_store_pd(f.s[j], _mm256_div_pd(one, d));
        // std::min(d_min, d) and std::max(d_max, d): d < d_min ? d : d_min, d_max < d ? d : d_max.
        d_min = j == 0 ? d : _mm256_min_pd(d, d_min);
        d_max = _mm256_max_pd(d, d_max);
    }
    // Cholesky.
    for (int j = 0; j < C; ++j) {
        V djj = one;
        for (int k = 0; k < j; ++k)
            djj = _mm256_sub_pd(djj, _mm256_mul_pd(_mm256_load_pd(f.L[j][k]), _mm256_load_pd(f.L[j][k])));
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(djj, zero, _CMP_GT_OQ));
        const V ljj = _mm256_sqrt_pd(djj);
        _mm256_store_pd(f.L[j][j], ljj);
        const V rdj = _mm256_div_pd(one, ljj);
        _mm256_store_pd(f.rd[j], rdj);
        for (int i = j + 1; i < C; ++i) {
            V v =
                _mm256_mul_pd(_mm256_mul_pd(_mm256_load_pd(f.G[i][j]), _mm256_load_pd(f.s[i])), _mm256_load_pd(f.s[j]));
            for (int k = 0; k < j; ++k)
                v = _mm256_sub_pd(v, _mm256_mul_pd(_mm256_load_pd(f.L[i][k]), _mm256_load_pd(f.L[j][k])));
            _mm256_store_pd(f.L[i][j], _mm256_mul_pd(v, rdj));
        }
    }
    // |L^-1|_F^2.
    alignas(32) double inv[C][C][4];
    for (int j = 0; j < C; ++j) _mm256_store_pd(inv[j][j], _mm256_load_pd(f.rd[j]));
    for (int i = 1; i < C; ++i)
        for (int j = 0; j < i; ++j) {
            V v = zero;
            for (int k = j; k < i; ++k)
                v = _mm256_sub_pd(v, _mm256_mul_pd(_mm256_load_pd(f.L[i][k]), _mm256_load_pd(inv[j][k])));
            _mm256_store_pd(inv[j][i], _mm256_mul_pd(v, _mm256_load_pd(f.rd[i])));
        }
    V inv_norm2 = zero;
    for (int j = 0; j < C; ++j)
        for (int i = j; i < C; ++i)
            inv_norm2 = _mm256_add_pd(inv_norm2, _mm256_mul_pd(_mm256_load_pd(inv[j][i]), _mm256_load_pd(inv[j][i])));
    ok = _mm256_and_pd(
        ok, _mm256_cmp_pd(_mm256_mul_pd(_mm256_set1_pd(double(C)), inv_norm2),
                          _mm256_set1_pd(kNormalEquationsMaxCondition * kNormalEquationsMaxCondition), _CMP_LE_OQ));
    const V rank_bound =
        _mm256_div_pd(_mm256_mul_pd(_mm256_set1_pd(kNormalEquationsRankMargin / rank_threshold), d_min), d_max);
    ok = _mm256_and_pd(ok, _mm256_cmp_pd(inv_norm2, _mm256_mul_pd(rank_bound, rank_bound), _CMP_LE_OQ));
    solve_x4(f, f.c, f.x);
    return unsigned(_mm256_movemask_pd(ok));
}

//! solve_by_normal_equations() of up to four systems (M[l], b[l]: l < n,
//! each rows >= C) at once, the latency-bound steps (the factorisation, the
//! inverse's norm, the triangular solves) on the lanes of AVX2 registers:
//! bit l of the result set, and x[l] written, exactly where the scalar
//! solve would return true, with the same x to the last bit. Needs AVX2
//! (use_avx2()).
template <int C, class MatrixType, class VectorType>
unsigned solve_by_normal_equations_x4(const MatrixType* const* M, const VectorType* const* b, int n,
                                      double rank_threshold, std::array<double, C>* x)
{
    NormalEquationsX4<C> f;
    for (int l = 0; l < 4; ++l) {
        std::array<std::array<double, C>, C> G{};
        std::array<double, C> c{};
        if (l < n) {
            gram<C>(*M[l], *b[l], G, c);
        } else {
            for (int j = 0; j < C; ++j) G[j][j] = 1.0;  // an idle lane: the identity
        }
        for (int j = 0; j < C; ++j) {
            f.c[j][l] = c[j];
            for (int k = 0; k < C; ++k) f.G[j][k][l] = k <= j ? G[j][k] : 0.0;
        }
    }
    const unsigned ok = factor_and_solve_x4<C>(f, rank_threshold) & ((1u << n) - 1u);
    alignas(32) double rc[C][4] = {};
    for (int l = 0; l < n; ++l) {
        if (!(ok >> l & 1u)) continue;
        for (int j = 0; j < C; ++j) x[l][std::size_t(j)] = f.x[j][l];
        std::array<double, C> r{};
        refinement_rhs<C>(*M[l], *b[l], x[l], r);
        for (int j = 0; j < C; ++j) rc[j][l] = r[std::size_t(j)];
    }
    alignas(32) double dx[C][4];
    solve_x4(f, rc, dx);
    for (int l = 0; l < n; ++l)
        if (ok >> l & 1u)
            for (int j = 0; j < C; ++j) x[l][std::size_t(j)] += dx[j][l];
    return ok;
}
#endif

}  // namespace meshdiff::detail
