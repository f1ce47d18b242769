// The curvature fits' normal-equations solve (src/roughness/normal_equations.h): it agrees with the QR on
// well-conditioned systems and declines every system the QR would find rank-deficient or that is badly
// conditioned, so the fits' rank decisions stay the QR's (issue 30, lever 1).
#include "roughness/normal_equations.h"

#include <gtest/gtest.h>
#include <Eigen/QR>

#include "geometry/simd.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace {

using Matrix9 = Eigen::Matrix<double, Eigen::Dynamic, 9>;

// Deterministic values in [-1, 1) from an integer hash.
double hashed(std::uint64_t i)
{
    i = (i ^ (i >> 31)) * 0x7fb5d329728ea185ULL;
    i = (i ^ (i >> 27)) * 0x81dadef4bc2dd44dULL;
    i ^= i >> 33;
    return double(i >> 11) / double(1ULL << 52) - 1.0;
}

// The jet's monomials of scattered points, rows weighted 1/|d|^4, and a right-hand side.
void jet_system(int rows, std::uint64_t seed, Matrix9& M, Eigen::VectorXd& b)
{
    M.resize(rows, 9);
    b.resize(rows);
    for (int i = 0; i < rows; ++i) {
        const double x = hashed(seed + 3 * std::uint64_t(i)), y = hashed(seed + 3 * std::uint64_t(i) + 1);
        const double d2 = x * x + y * y + 0.5, wt = 1.0 / (d2 * d2);
        M.row(i) << x, y, x * x, x * y, y * y, x * x * x, x * x * y, x * y * y, y * y * y;
        M.row(i) *= wt;
        b(i) = wt * (0.3 * x * x - 0.2 * x * y + 0.1 * y * y + 0.05 * hashed(seed + 3 * std::uint64_t(i) + 2));
    }
}

TEST(NormalEquations, AgreesWithTheQrOnWellConditionedFits)
{
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        Matrix9 M;
        Eigen::VectorXd b;
        jet_system(20 + int(seed % 20), seed * 1000, M, b);
        std::array<double, 9> x;
        ASSERT_TRUE(meshdiff::detail::solve_by_normal_equations<9>(M, b, 1e-10, x)) << seed;
        Eigen::ColPivHouseholderQR<Matrix9> qr(M);
        const Eigen::VectorXd q = qr.solve(b);
        for (int j = 0; j < 9; ++j) EXPECT_NEAR(x[std::size_t(j)], q(j), 1e-11 * q.cwiseAbs().maxCoeff()) << seed;
    }
}

TEST(NormalEquations, DeclinesRankDeficientAndBadlyConditionedSystems)
{
    Matrix9 M;
    Eigen::VectorXd b;
    jet_system(20, 7, M, b);
    std::array<double, 9> x;
    // All points on a line y = 0.5 x: the columns are dependent.
    Matrix9 line = M;
    for (int i = 0; i < 20; ++i) {
        const double t = hashed(100 + std::uint64_t(i)), u = 0.5 * t;
        line.row(i) << t, u, t * t, t * u, u * u, t * t * t, t * t * u, t * u * u, u * u * u;
    }
    EXPECT_FALSE(meshdiff::detail::solve_by_normal_equations<9>(line, b, 1e-10, x));
    // A column nearly a copy of another (condition number far above 1e4, the QR still of full rank).
    Matrix9 near = M;
    for (int i = 0; i < 20; ++i) near(i, 8) = near(i, 7) * (1.0 + 1e-7 * hashed(200 + std::uint64_t(i)));
    EXPECT_FALSE(meshdiff::detail::solve_by_normal_equations<9>(near, b, 1e-10, x));
    // Fewer rows than columns, a zero column.
    EXPECT_FALSE(meshdiff::detail::solve_by_normal_equations<9>(M.topRows(8), b.head(8), 1e-10, x));
    Matrix9 zero = M;
    zero.col(4).setZero();
    EXPECT_FALSE(meshdiff::detail::solve_by_normal_equations<9>(zero, b, 1e-10, x));
    // Whenever it solves, the QR finds full rank (random near-degenerate systems).
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        Matrix9 A = M;
        const double eps = std::pow(10.0, -double(seed % 12));
        for (int i = 0; i < 20; ++i) A(i, 8) = A(i, 7) + eps * hashed(seed * 50 + std::uint64_t(i));
        Eigen::ColPivHouseholderQR<Matrix9> qr(A);
        qr.setThreshold(1e-10);
        if (meshdiff::detail::solve_by_normal_equations<9>(A, b, 1e-10, x)) {
            EXPECT_EQ(qr.rank(), 9) << seed;
        }
    }
}

TEST(NormalEquations, SameBitsFromAnyBuffer)
{
    // The same system in a fixed-capacity buffer and in a differently strided heap block.
    Matrix9 M;
    Eigen::VectorXd b;
    jet_system(17, 42, M, b);
    Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::ColMajor, 256, 9> fixed = M;
    Eigen::MatrixXd big(33, 9);
    big.setZero();
    big.block(1, 0, 17, 9) = M;
    std::array<double, 9> x1, x2, x3;
    ASSERT_TRUE(meshdiff::detail::solve_by_normal_equations<9>(M, b, 1e-10, x1));
    ASSERT_TRUE(meshdiff::detail::solve_by_normal_equations<9>(fixed, b, 1e-10, x2));
    ASSERT_TRUE(meshdiff::detail::solve_by_normal_equations<9>(big.block(1, 0, 17, 9), b, 1e-10, x3));
    EXPECT_EQ(x1, x2);
    EXPECT_EQ(x1, x3);
}

}  // namespace

namespace {

// The Gram matrix summed with AVX2 against the scalar loop: the same bits
// for both fits' column counts, short and long systems, any buffer.
TEST(NormalEquations, VectorSumsAreTheScalarSumsBitForBit)
{
    if (!meshdiff::detail::cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2: the scalar sums only";
    int solved = 0;
    for (int rows : {9, 10, 17, 31, 64, 255, 300})
        for (std::uint64_t seed = 1; seed <= 20; ++seed) {
            Matrix9 M;
            Eigen::VectorXd b;
            jet_system(rows, 1000 * seed + std::uint64_t(rows), M, b);
            Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::ColMajor, 256, 9> fixed = M.topRows(std::min(rows, 256));
            const Eigen::VectorXd bf = b.head(std::min(rows, 256));
            std::array<double, 9> scalar{}, vector{};
            std::array<double, 7> scalar7{}, vector7{};
            bool ok[4];
            {
                const bool before = meshdiff::detail::allow_vector_kernels(false);
                ok[0] = meshdiff::detail::solve_by_normal_equations<9>(M, b, 1e-10, scalar);
                ok[1] = meshdiff::detail::solve_by_normal_equations<7>(fixed.leftCols(7), bf, 1e-10, scalar7);
                meshdiff::detail::allow_vector_kernels(true);
                ok[2] = meshdiff::detail::solve_by_normal_equations<9>(M, b, 1e-10, vector);
                ok[3] = meshdiff::detail::solve_by_normal_equations<7>(fixed.leftCols(7), bf, 1e-10, vector7);
                meshdiff::detail::allow_vector_kernels(before);
            }
            ASSERT_EQ(ok[0], ok[2]) << rows << " rows, seed " << seed;
            ASSERT_EQ(ok[1], ok[3]) << rows << " rows, seed " << seed;
            if (ok[0]) {
                EXPECT_EQ(scalar, vector) << rows << " rows, seed " << seed;
            }
            if (ok[1]) {
                EXPECT_EQ(scalar7, vector7) << rows << " rows, seed " << seed;
            }
            solved += ok[0] + ok[1];
        }
    EXPECT_GT(solved, 200);
}

}  // namespace

namespace {

std::uint64_t bits_of(double v)
{
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
}

// Four systems at once against one at a time: the same lanes solved and the
// same solutions to the last bit, for groups of 1 to 4 systems of different
// row counts, well conditioned ones beside ones declined at each test (a
// zero column, exactly dependent columns, near copies from 1e-1 to 1e-11, a
// column far smaller than the others).
TEST(NormalEquations, FourLanesAreTheScalarSolvesBitForBit)
{
    if (!meshdiff::detail::cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2: one system at a time only";
    using Block = Eigen::Block<const Matrix9>;
    using Head = Eigen::VectorBlock<const Eigen::VectorXd>;
    int solved = 0, declined = 0;
    for (std::uint64_t seed = 1; seed <= 400; ++seed) {
        const int n = 1 + int(seed % 4);
        std::array<Matrix9, 4> M;
        std::array<Eigen::VectorXd, 4> b;
        for (int l = 0; l < n; ++l) {
            const std::uint64_t id = seed * 4 + std::uint64_t(l);
            const int rows = 9 + int(id % 23);
            jet_system(rows, id * 977, M[std::size_t(l)], b[std::size_t(l)]);
            Matrix9& A = M[std::size_t(l)];
            switch (id % 7) {
                case 1:
                    A.col(int(id % 9)).setZero();
                    break;
                case 2:
                    A.col(8) = A.col(7);
                    break;
                case 3:
                case 4:
                    for (int i = 0; i < rows; ++i)
                        A(i, 8) = A(i, 7) + std::pow(10.0, -double(1 + id % 11)) * hashed(id * 31 + std::uint64_t(i));
                    break;
                case 5:  // well conditioned once equilibrated, but a column 1e-9 of the others: the rank test
                    A.col(int(id % 9)) *= 1e-9;
                    break;
                default:
                    break;
            }
        }
        const Matrix9* Mc[4] = {&M[0], &M[1], &M[2], &M[3]};
        std::array<Block, 4> blocks{Block(*Mc[0], 0, 0, M[0].rows(), 9), Block(*Mc[1], 0, 0, M[1].rows(), 9),
                                    Block(*Mc[2], 0, 0, M[2].rows(), 9), Block(*Mc[3], 0, 0, M[3].rows(), 9)};
        const Eigen::VectorXd* bc[4] = {&b[0], &b[1], &b[2], &b[3]};
        std::array<Head, 4> heads{Head(*bc[0], 0, b[0].size()), Head(*bc[1], 0, b[1].size()),
                                  Head(*bc[2], 0, b[2].size()), Head(*bc[3], 0, b[3].size())};
        const Block* Mp[4] = {&blocks[0], &blocks[1], &blocks[2], &blocks[3]};
        const Head* bp[4] = {&heads[0], &heads[1], &heads[2], &heads[3]};
        std::array<std::array<double, 9>, 4> x4{};
        const unsigned ok = meshdiff::detail::solve_by_normal_equations_x4<9>(Mp, bp, n, 1e-10, x4.data());
        EXPECT_EQ(ok >> n, 0u) << "an idle lane reported solved, seed " << seed;
        for (int l = 0; l < n; ++l) {
            std::array<double, 9> x{};
            const bool one =
                meshdiff::detail::solve_by_normal_equations<9>(blocks[std::size_t(l)], heads[std::size_t(l)], 1e-10, x);
            ASSERT_EQ(one, bool(ok >> l & 1u)) << "seed " << seed << " lane " << l;
            if (one) {
                for (int j = 0; j < 9; ++j)
                    ASSERT_EQ(bits_of(x[std::size_t(j)]), bits_of(x4[std::size_t(l)][std::size_t(j)]))
                        << "seed " << seed << " lane " << l << " column " << j;
                ++solved;
            } else {
                ++declined;
            }
        }
    }
    EXPECT_GT(solved, 300);
    EXPECT_GT(declined, 100);
}

}  // namespace
