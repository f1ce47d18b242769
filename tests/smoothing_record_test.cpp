#include "meshdiff/studies/smoothing_record.h"

#include <gtest/gtest.h>

#include "meshdiff/error.h"
#include "meshdiff/studies/shapes.h"

#include <vector>

using namespace meshdiff;

namespace {

Mesh noisy()
{
    return noisy_sphere(2, 0.05, 3).mesh;  // 162 vertices
}

SmoothingOptions laplacian(int iterations)
{
    SmoothingOptions o;
    o.iterations = iterations;
    return o;
}

RecordOptions record_every(int every, bool distance = false)
{
    RecordOptions r;
    r.every = every;
    r.profile.levels = {1, 2};
    r.distance = distance;
    r.sampling.samples = 3000;
    return r;
}

std::vector<int> recorded(int iterations, int every)
{
    Mesh m = noisy();
    return smooth_and_record(m, laplacian(iterations), record_every(every)).iterations;
}

}  // namespace

TEST(SmoothAndRecord, RecordsAtZeroEveryKAndTheLast)
{
    EXPECT_EQ(recorded(7, 3), (std::vector<int>{0, 3, 6, 7}));
    EXPECT_EQ(recorded(6, 3), (std::vector<int>{0, 3, 6}));  // the last once
    EXPECT_EQ(recorded(2, 5), (std::vector<int>{0, 2}));
    EXPECT_EQ(recorded(4, 1), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(SmoothAndRecord, EveryZeroRecordsTheInputAndTheLastOnly)
{
    EXPECT_EQ(recorded(7, 0), (std::vector<int>{0, 7}));
    EXPECT_EQ(recorded(0, 0), (std::vector<int>{0}));
}

TEST(SmoothAndRecord, RecordSizesFollowTheRecordedIterations)
{
    Mesh m = noisy();
    const SmoothingRecord r = smooth_and_record(m, laplacian(7), record_every(3, true));
    const std::size_t n = r.iterations.size();
    EXPECT_EQ(r.sigma.size(), n);
    for (const auto& s : r.sigma) EXPECT_EQ(s.size(), 2u);
    EXPECT_EQ(r.sigma_global.size(), n);
    EXPECT_EQ(r.undefined.size(), n);
    EXPECT_EQ(r.distance.size(), n);
    EXPECT_TRUE(r.flow_time.empty());  // no explicit flow
}

TEST(SmoothAndRecord, SigmaAtIterationZeroIsTheProfileOfTheInputBitwise)
{
    const Mesh input = noisy();
    Mesh m = input;
    const RecordOptions ro = record_every(2);
    const SmoothingRecord r = smooth_and_record(m, laplacian(4), ro);
    const RoughnessProfile p = roughness_profile(input, ro.profile);
    ASSERT_EQ(r.sigma[0].size(), p.levels.size());
    for (std::size_t k = 0; k < p.levels.size(); ++k) EXPECT_EQ(r.sigma[0][k], p.levels[k].sigma);
    EXPECT_EQ(r.sigma_global[0], p.global.sigma);
    EXPECT_EQ(r.undefined[0], p.curvature_undefined);
    // Smoothing lowers the first level's roughness of a noisy sphere.
    EXPECT_LT(r.sigma.back()[0], r.sigma[0][0]);
}

TEST(SmoothAndRecord, TheFinalMeshIsThatOfSmoothBitwise)
{
    for (const SmoothingMethod method : {SmoothingMethod::Taubin, SmoothingMethod::MeanCurvatureFlow}) {
        SmoothingOptions o = laplacian(5);
        o.method = method;
        Mesh recorded_mesh = noisy(), plain = noisy();
        const SmoothingRecord r = smooth_and_record(recorded_mesh, o, record_every(2));
        const SmoothingReport report = smooth(plain, o);
        EXPECT_EQ(recorded_mesh.points, plain.points) << to_string(method);
        EXPECT_EQ(r.report.steps, report.steps);
        EXPECT_EQ(r.report.time, report.time);
    }
}

TEST(SmoothAndRecord, DistanceAtIterationZeroIsRoundingLevelAndGrows)
{
    const Mesh input = noisy();
    Mesh m = input;
    const SmoothingRecord r = smooth_and_record(m, laplacian(6), record_every(3, true));
    ASSERT_EQ(r.distance.size(), 3u);
    const double diag = bounding_box(input).diagonal();
    EXPECT_EQ(r.distance[0].diagonal, diag);
    EXPECT_LT(r.distance[0].hausdorff, 1e-12 * diag);
    EXPECT_GT(r.distance[1].hausdorff, 1e-4 * diag);
    EXPECT_GT(r.distance[2].hausdorff, r.distance[1].hausdorff);
    // The same as surface_distance() of the input and the final state.
    const SurfaceDistance last = surface_distance(input, m, record_every(3, true).sampling);
    EXPECT_EQ(r.distance[2].hausdorff, last.hausdorff);
    EXPECT_EQ(r.distance[2].forward.mean, last.forward.mean);
}

TEST(SmoothAndRecord, NoDistanceWhenSwitchedOff)
{
    Mesh m = noisy();
    EXPECT_TRUE(smooth_and_record(m, laplacian(3), record_every(1, false)).distance.empty());
}

TEST(SmoothAndRecord, FlowTimeIsTheRunningSumOfTheStepsOfAnExplicitFlow)
{
    SmoothingOptions o = laplacian(7);
    o.method = SmoothingMethod::MeanCurvatureFlow;
    o.step = 0.5;
    o.step_control = StepControl::Adaptive;  // limited by the stability bound: steps differ
    Mesh m = noisy();
    const SmoothingRecord r = smooth_and_record(m, o, record_every(3));
    ASSERT_EQ(r.report.steps.size(), 7u);
    ASSERT_NE(r.report.steps[0], r.report.steps[6]);
    ASSERT_EQ(r.flow_time.size(), r.iterations.size());
    for (std::size_t i = 0; i < r.iterations.size(); ++i) {
        double t = 0.0;
        for (int k = 0; k < r.iterations[i]; ++k) t += r.report.steps[std::size_t(k)];
        EXPECT_EQ(r.flow_time[i], t) << r.iterations[i];
    }
    EXPECT_EQ(r.flow_time.front(), 0.0);
    EXPECT_DOUBLE_EQ(r.flow_time.back(), r.report.time);
    // Implicit steps report no steps, hence no flow time.
    o.implicit = true;
    o.step_control = StepControl::Fixed;
    Mesh n = noisy();
    EXPECT_TRUE(smooth_and_record(n, o, record_every(3)).flow_time.empty());
}

TEST(SmoothAndRecord, CallsTheCallbackOfTheOptionsAtEveryIteration)
{
    SmoothingOptions o = laplacian(7);
    std::vector<int> seen;
    std::vector<std::size_t> sizes;
    o.callback = [&](int k, const Mesh& state) {
        seen.push_back(k);
        sizes.push_back(state.n_vertices());
    };
    Mesh m = noisy();
    smooth_and_record(m, o, record_every(3));
    EXPECT_EQ(seen, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(sizes, std::vector<std::size_t>(8, m.n_vertices()));
}

TEST(SmoothAndRecord, NegativeEveryThrowsAndLeavesTheMesh)
{
    const Mesh input = noisy();
    Mesh m = input;
    EXPECT_THROW(smooth_and_record(m, laplacian(3), record_every(-1)), InvalidArgumentError);
    EXPECT_EQ(m.points, input.points);
    SmoothingOptions bad = laplacian(3);
    bad.lambda = 2.0;  // as smooth()
    EXPECT_THROW(smooth_and_record(m, bad, record_every(1)), InvalidArgumentError);
}
