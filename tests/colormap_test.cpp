#include "meshdiff/report/colormap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

using namespace meshdiff;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

const Rgb kWhite = {255, 255, 255};
const Rgb kGrey = {128, 128, 128};
// The endpoints stated in colormap.cpp, rounded to bytes: blue (0.23, 0.30,
// 0.75) and red (0.71, 0.02, 0.15).
const Rgb kDivergingBlue = {59, 77, 191};
const Rgb kDivergingRed = {181, 5, 38};

const Rgb kBlue = {0, 0, 255};
const Rgb kCyan = {0, 255, 255};
const Rgb kGreen = {0, 255, 0};
const Rgb kYellow = {255, 255, 0};
const Rgb kRed = {255, 0, 0};

// True if \p c is a colour of the sequential ramp: blue-cyan-green-yellow-red
// is piecewise linear with one channel moving at a time, so each of its
// colours has a channel at 255 and, apart from the moving one, a channel at 0.
bool on_sequential_ramp(const Rgb& c)
{
    const int r = c[0], g = c[1], b = c[2];
    return (r == 0 && (g == 255 || b == 255)) || (b == 0 && (g == 255 || r == 255));
}

}  // namespace

TEST(DivergingColors, ZeroIsWhiteAndTheRangeEndsAreTheStatedColours)
{
    const auto c = diverging_colors({0.0, -0.0, 2.5, -2.5}, 2.5);
    EXPECT_EQ(c[0], kWhite);
    EXPECT_EQ(c[1], kWhite);
    EXPECT_EQ(c[2], kDivergingRed);
    EXPECT_EQ(c[3], kDivergingBlue);
}

TEST(DivergingColors, HalfTheRangeIsHalfwayToTheEnd)
{
    const auto c = diverging_colors({1.0, -1.0}, 2.0);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(c[0][k], (255.0 + kDivergingRed[k]) / 2, 0.5 + 1e-9) << "channel " << k;
        EXPECT_NEAR(c[1][k], (255.0 + kDivergingBlue[k]) / 2, 0.5 + 1e-9) << "channel " << k;
    }
}

TEST(DivergingColors, ClampOutsideTheRangeAndGreyForNaN)
{
    const auto c = diverging_colors({3.0, 1e300, kInf, -3.0, -1e300, -kInf, kNaN}, 1.5);
    for (int i : {0, 1, 2}) EXPECT_EQ(c[std::size_t(i)], kDivergingRed) << "value " << i;
    for (int i : {3, 4, 5}) EXPECT_EQ(c[std::size_t(i)], kDivergingBlue) << "value " << i;
    EXPECT_EQ(c[6], kGrey);
    EXPECT_TRUE(diverging_colors({}, 1.0).empty());
}

TEST(DivergingColors, ADegenerateRangeStillSeparatesTheSigns)
{
    for (double range : {0.0, -1.0, kNaN}) {
        const auto c = diverging_colors({0.0, 0.5, -0.5, kNaN}, range);
        EXPECT_EQ(c[0], kWhite) << "range " << range;
        EXPECT_GT(c[1][0], c[1][2]) << "positive is reddish, range " << range;
        EXPECT_LT(c[2][0], c[2][2]) << "negative is bluish, range " << range;
        EXPECT_EQ(c[3], kGrey) << "range " << range;
    }
}

TEST(SequentialColors, BlueAtLowRedAtHighGreenHalfway)
{
    // Over [-3, 5]: quarters at -1, 1, 3.
    const auto c = sequential_colors({-3.0, -1.0, 1.0, 3.0, 5.0}, -3.0, 5.0);
    EXPECT_EQ(c[0], kBlue);
    EXPECT_EQ(c[1], kCyan);
    EXPECT_EQ(c[2], kGreen);
    EXPECT_EQ(c[3], kYellow);
    EXPECT_EQ(c[4], kRed);
}

TEST(SequentialColors, ClampOutsideTheRangeAndGreyForNaN)
{
    const auto c = sequential_colors({-4.0, -kInf, 6.0, kInf, kNaN}, -3.0, 5.0);
    EXPECT_EQ(c[0], kBlue);
    EXPECT_EQ(c[1], kBlue);
    EXPECT_EQ(c[2], kRed);
    EXPECT_EQ(c[3], kRed);
    EXPECT_EQ(c[4], kGrey);
}

TEST(SequentialColors, EveryValueInRangeLandsOnTheRampInOrder)
{
    std::vector<double> v;
    for (int i = 0; i <= 1000; ++i) v.push_back(0.001 * i);
    const auto c = sequential_colors(v, 0.0, 1.0);
    // The hue advances monotonically: blue falls, then red rises.
    for (std::size_t i = 0; i < c.size(); ++i) {
        ASSERT_TRUE(on_sequential_ramp(c[i])) << "value " << v[i];
        if (i == 0) continue;
        ASSERT_LE(c[i][2], c[i - 1][2]) << "value " << v[i];
        ASSERT_GE(c[i][0], c[i - 1][0]) << "value " << v[i];
    }
}

TEST(SequentialColors, ADegenerateRangeGivesRampColoursNotGarbage)
{
    const std::vector<double> v = {2.0, 1.0, 2.3, 2.7, 3.0, 1e9, -kInf, kInf, kNaN};
    for (const auto& [lo, hi] : {std::pair{2.0, 2.0}, std::pair{2.0, 1.0}, std::pair{2.0, -kInf}}) {
        const auto c = sequential_colors(v, lo, hi);
        ASSERT_EQ(c.size(), v.size());
        EXPECT_EQ(c[0], kBlue) << "the value lo, [" << lo << ", " << hi << "]";
        EXPECT_EQ(c[1], kBlue) << "below lo, [" << lo << ", " << hi << "]";
        for (std::size_t i = 0; i + 1 < v.size(); ++i)
            EXPECT_TRUE(on_sequential_ramp(c[i])) << "value " << v[i] << ", [" << lo << ", " << hi << "]";
        EXPECT_EQ(c.back(), kGrey);
    }
}

TEST(RobustSymmetricRange, Is95thPercentileOfAbsoluteValuesIgnoringNaN)
{
    // 21 defined values, |v| = 0.5, 1, ..., 10 and an infinite outlier: the
    // 95th percentile of 21 sorted values is the 20th (rank 0.95 * 20 = 19,
    // counted from 0), whatever the interpolation rule: 10.
    std::vector<double> v;
    for (int i = 1; i <= 20; ++i) v.push_back(i % 2 ? 0.5 * i : -0.5 * i);
    v.push_back(-kInf);
    for (int i = 0; i < 5; ++i) v.push_back(kNaN);
    std::shuffle(v.begin(), v.end(), std::mt19937_64(4));
    EXPECT_EQ(robust_symmetric_range(v), 10.0);

    // 41 values |v| = 1..41 with an outlier of 1e12: rank 38, value 39.
    std::vector<double> w;
    for (int i = 1; i <= 40; ++i) w.push_back(i % 3 ? double(i) : -double(i));
    w.push_back(1e12);
    std::shuffle(w.begin(), w.end(), std::mt19937_64(9));
    w.insert(w.begin() + 7, kNaN);
    EXPECT_EQ(robust_symmetric_range(w), 39.0);
    EXPECT_EQ(robust_symmetric_range({-3.0}), 3.0);
}

TEST(RobustSymmetricRange, IsOneWhenNothingIsDefinedOrAllIsZero)
{
    EXPECT_EQ(robust_symmetric_range({}), 1.0);
    EXPECT_EQ(robust_symmetric_range({kNaN, kNaN}), 1.0);
    EXPECT_EQ(robust_symmetric_range({0.0, -0.0, 0.0, kNaN}), 1.0);
    // 95th percentile zero, a single nonzero outlier above it: still 1.
    std::vector<double> mostly_zero(100, 0.0);
    mostly_zero[42] = 5.0;
    EXPECT_EQ(robust_symmetric_range(mostly_zero), 1.0);
}
