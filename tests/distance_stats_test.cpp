#include "meshdiff/distance/distance_stats.h"

#include "meshdiff/error.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"
#include "meshdiff/studies/shapes.h"

#include "distance/distance_accumulators.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace meshdiff;

namespace {

std::vector<double> random_distances(std::size_t n, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> v(n);
    for (double& x : v) x = u(rng) < 0.1 ? 0.25 : u(rng);  // ties included
    return v;
}

SurfaceSamples samples_of(std::size_t n)
{
    SurfaceSamples s;
    for (std::size_t i = 0; i < n; ++i) s.points.emplace_back(double(i), 0.0, 0.0);
    s.n_vertex = n;
    return s;
}

}  // namespace

TEST(DistanceStats, NearestRankIsTheSortedElementAtCeilOfQnOver1000)
{
    for (const std::size_t n : {1u, 2u, 3u, 7u, 100u, 999u, 1000u, 1001u, 4096u}) {
        const std::vector<double> v = random_distances(n, n);
        std::vector<double> sorted = v;
        std::sort(sorted.begin(), sorted.end());
        for (const unsigned q : {1u, 10u, 500u, 950u, 990u, 999u, 1000u}) {
            std::vector<double> w = v;
            const std::size_t rank = std::max<std::size_t>(1, (q * n + 999) / 1000);
            EXPECT_EQ(nearest_rank(w, q), sorted[rank - 1]) << n << " " << q;
        }
        // Each percentile searched above the one before it, as the statistics do.
        std::vector<double> w = v;
        unsigned below = 0;
        for (const PercentileField& p : kPercentiles) {
            const std::size_t rank = std::max<std::size_t>(1, (p.per_mille * n + 999) / 1000);
            EXPECT_EQ(nearest_rank(w, p.per_mille, below), sorted[rank - 1]) << n << " " << p.per_mille;
            below = p.per_mille;
        }
    }
}

// The grouped selection against a sort: exact zeros and ties, values over
// many binades and within one group, denormals and infinity, one value; a
// negative value or -0 takes the sorting path, a NaN is refused; at 1 and 3
// threads.
TEST(DistanceStats, NearestRanksEqualTheSortedElementsAndLeaveTheValues)
{
    std::mt19937 rng(3);
    std::vector<std::vector<double>> cases;
    for (const std::size_t n : {1u, 2u, 7u, 1001u, 100000u}) cases.push_back(random_distances(n, n));
    std::vector<double> wide(20000), ties(5000, 0.0), narrow(30000);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (double& x : wide) x = std::ldexp(u(rng), int(u(rng) * 60) - 40);
    for (std::size_t i = 0; i < ties.size(); i += 3) ties[i] = 0.5;
    for (double& x : narrow) x = 1.0 + 1e-3 * u(rng);  // one group of the top 16 bits
    wide[7] = std::numeric_limits<double>::denorm_min();
    wide[9] = std::numeric_limits<double>::infinity();
    cases.insert(cases.end(), {wide, ties, narrow});
    std::vector<double> negative = wide, minus_zero = ties, nan = narrow;
    negative[3] = -2.0;
    minus_zero[4] = -0.0;
    nan[5] = std::numeric_limits<double>::quiet_NaN();
    const std::vector<unsigned> per_mille = {0, 1, 500, 950, 990, 999, 1000};
    const int saved = omp_get_max_threads();
    for (int threads : {1, 3}) {
        omp_set_num_threads(threads);
        for (const std::vector<double>& v : cases) {
            std::vector<double> sorted = v;
            std::sort(sorted.begin(), sorted.end());
            const std::vector<double> got = nearest_ranks(v, per_mille);
            for (std::size_t j = 0; j < per_mille.size(); ++j) {
                std::vector<double> w = v;
                EXPECT_EQ(got[j], nearest_rank(w, per_mille[j])) << v.size() << " " << per_mille[j];
                const std::size_t rank = std::max<std::size_t>(1, (per_mille[j] * v.size() + 999) / 1000);
                EXPECT_EQ(got[j], sorted[rank - 1]) << v.size() << " " << per_mille[j];
            }
        }
        for (const std::vector<double>* v : {&negative, &minus_zero}) {
            const std::vector<double> before = *v;
            std::vector<double> sorted = *v;
            std::sort(sorted.begin(), sorted.end());
            const std::vector<double> got = nearest_ranks(*v, {500, 1000});
            EXPECT_EQ(got[0], sorted[(500 * v->size() + 999) / 1000 - 1]);
            EXPECT_EQ(got[1], sorted.back());
            EXPECT_EQ(std::memcmp(v->data(), before.data(), v->size() * sizeof(double)), 0);  // left as it was
        }
        EXPECT_THROW(nearest_ranks(nan, {0}), InvalidArgumentError);  // no rank, not a wrong one
    }
    omp_set_num_threads(saved);
    EXPECT_THROW(nearest_ranks({}, {500}), InvalidArgumentError);
}

TEST(DistanceStats, PercentilesAscendAndStatFieldsAreDistinct)
{
    unsigned last = 0;
    for (const PercentileField& p : kPercentiles) {
        EXPECT_GT(p.per_mille, last);
        EXPECT_LE(p.per_mille, 1000u);
        last = p.per_mille;
    }
    std::set<std::string> keys, labels;
    for (const StatField& f : kStatFields) {
        EXPECT_TRUE(keys.insert(f.key).second) << f.key;
        EXPECT_TRUE(labels.insert(f.label).second) << f.label;
    }
    // Every percentile is reported.
    for (const PercentileField& p : kPercentiles)
        EXPECT_TRUE(std::any_of(std::begin(kStatFields), std::end(kStatFields),
                                [&](const StatField& f) { return f.field == p.field; }));
}

TEST(DistanceStats, StatisticsMatchABruteForceComputation)
{
    const std::vector<double> d = random_distances(5000, 3);
    const DistanceStats s = distance_stats(samples_of(d.size()), d);
    std::vector<double> sorted = d;
    std::sort(sorted.begin(), sorted.end());
    double sum = 0.0, sum2 = 0.0;
    for (double x : d) {
        sum += x;
        sum2 += x * x;
    }
    const double n = double(d.size());
    EXPECT_EQ(s.min, sorted.front());
    EXPECT_EQ(s.max, sorted.back());
    EXPECT_NEAR(s.mean, sum / n, 1e-14);
    EXPECT_NEAR(s.rms, std::sqrt(sum2 / n), 1e-14);
    double dev = 0.0;
    for (double x : d) dev += (x - sum / n) * (x - sum / n);
    EXPECT_NEAR(s.stddev, std::sqrt(dev / n), 1e-14);
    for (const PercentileField& p : kPercentiles)
        EXPECT_EQ(s.*p.field, sorted[(p.per_mille * d.size() + 999) / 1000 - 1]) << p.per_mille;
    // The first sample at the maximum.
    const auto at = std::size_t(std::max_element(d.begin(), d.end()) - d.begin());
    EXPECT_EQ(s.max_point, Vec3(double(at), 0.0, 0.0));
}

TEST(DistanceStats, RelativeToDividesEveryReportedStatisticAndNothingElse)
{
    const std::vector<double> d = random_distances(300, 5);
    const DistanceStats s = distance_stats(samples_of(d.size()), d);
    const DistanceStats r = relative_to(s, 4.0);
    for (const StatField& f : kStatFields) EXPECT_EQ(r.*f.field, s.*f.field / 4.0) << f.key;
    EXPECT_EQ(r.n_samples(), s.n_samples());
    EXPECT_EQ(r.max_point, s.max_point);
}

TEST(DistanceStats, EveryStatFieldIsInTheJsonAndTheTextOfADirection)
{
    const std::vector<double> d = random_distances(300, 9);
    DistanceStats s = distance_stats(samples_of(d.size()), d);
    const nlohmann::json j = distance_stats_json(s, 2.0);
    for (const StatField& f : kStatFields) {
        ASSERT_TRUE(j.contains(f.key)) << f.key;
        EXPECT_EQ(j[f.key].get<double>(), s.*f.field) << f.key;
        EXPECT_EQ(j["relative"][f.key].get<double>(), s.*f.field / 2.0) << f.key;
    }
}

TEST(DistanceStats, SignedStatisticsMatchABruteForceComputation)
{
    std::vector<double> d = random_distances(1000, 11);
    for (std::size_t i = 0; i < d.size(); i += 3) d[i] = -d[i];
    const SignedDistanceStats s = signed_distance_stats(d);
    EXPECT_EQ(s.min, *std::min_element(d.begin(), d.end()));
    EXPECT_EQ(s.max, *std::max_element(d.begin(), d.end()));
    double sum = 0.0, sum2 = 0.0;
    for (double x : d) {
        sum += x;
        sum2 += x * x;
    }
    EXPECT_NEAR(s.mean, sum / double(d.size()), 1e-14);
    EXPECT_NEAR(s.rms, std::sqrt(sum2 / double(d.size())), 1e-14);
    EXPECT_THROW(signed_distance_stats({}), InvalidArgumentError);
}

// Face samples in any order, a face sampled in two runs and an edge sample
// between them: each face sample weighs its face's area over the face's
// sample count, as a brute-force sum of w x d says.
TEST(DistanceStats, AreaWeightedStatsMatchABruteForceSumInAnySampleOrder)
{
    const Mesh m = plane_grid(3, 3, 1.0).mesh;
    SurfaceSamples s;
    const std::vector<std::pair<SampleKind, std::uint32_t>> order = {{SampleKind::OnFace, 0}, {SampleKind::OnFace, 0},
                                                                     {SampleKind::OnEdge, 3}, {SampleKind::OnFace, 0},
                                                                     {SampleKind::OnFace, 2}, {SampleKind::OnFace, 1}};
    std::vector<double> d;
    for (std::size_t i = 0; i < order.size(); ++i) {
        s.points.emplace_back(0.0, 0.0, 0.0);
        s.kind.push_back(order[i].first);
        s.element.push_back(order[i].second);
        d.push_back(0.1 * double(i + 1));
    }
    s.n_face = 5;
    s.n_edge = 1;
    std::vector<double> within;
    const auto a = area_weighted_stats(m, s, d, {0.35}, &within);
    ASSERT_TRUE(a);
    auto area = [&](std::uint32_t f) { return 0.5 * face_cross(m, f).norm(); };
    const double w0 = area(0) / 3.0, w1 = area(1), w2 = area(2);
    const double total_w = area(0) + area(1) + area(2);
    const double mean = (w0 * (0.1 + 0.2) + w0 * 0.4 + w2 * 0.5 + w1 * 0.6) / total_w;
    EXPECT_EQ(a->n_face, 5u);
    EXPECT_NEAR(a->area, total_w, 1e-15);
    EXPECT_NEAR(a->mean, mean, 1e-15);
    EXPECT_NEAR(within[0], 2.0 * w0 / total_w, 1e-15);  // 0.1 and 0.2 below 0.35
}
