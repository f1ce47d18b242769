#include "meshdiff/studies/smoothing.h"

#include "meshdiff/error.h"
#include "meshdiff/studies/shapes.h"

#include <gtest/gtest.h>
#include <omp.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace meshdiff {
namespace {

const SmoothingMethod kMethods[] = {SmoothingMethod::Laplacian, SmoothingMethod::Taubin, SmoothingMethod::Bilaplacian,
                                    SmoothingMethod::MeanCurvatureFlow, SmoothingMethod::ModifiedMeanCurvatureFlow};
const SmoothingUpdate kUpdates[] = {SmoothingUpdate::Post, SmoothingUpdate::Pre};

std::string label(SmoothingMethod m, SmoothingUpdate u)
{
    return to_string(m) + "/" + to_string(u);
}

SmoothingOptions options(SmoothingMethod m, SmoothingUpdate u, int iterations)
{
    SmoothingOptions o;
    o.method = m;
    o.update = u;
    o.iterations = iterations;
    return o;
}

double signed_volume(const Mesh& m)
{
    double v = 0;
    for (const Face& f : m.faces)
        v += m.points[std::size_t(f[0])].dot(m.points[std::size_t(f[1])].cross(m.points[std::size_t(f[2])])) / 6.0;
    return v;
}

// Relative spread of the distance to the centroid: std(|x - c|) / mean(|x - c|).
double radial_spread(const Mesh& m)
{
    Vec3 c = Vec3::Zero();
    for (const auto& p : m.points) c += p;
    c /= double(m.n_vertices());
    double s = 0, s2 = 0;
    for (const auto& p : m.points) {
        const double r = (p - c).norm();
        s += r;
        s2 += r * r;
    }
    const double n = double(m.n_vertices()), mean = s / n;
    return std::sqrt(std::max(0.0, s2 / n - mean * mean)) / mean;
}

// Mean triangle quality 4 sqrt(3) area / sum of squared edges (1 = equilateral).
double mean_quality(const Mesh& m)
{
    double q = 0;
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
        const Face& t = m.faces[f];
        const Vec3 &a = m.points[std::size_t(t[0])], &b = m.points[std::size_t(t[1])], &c = m.points[std::size_t(t[2])];
        const double l2 = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
        q += 2 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / l2;
    }
    return q / double(m.n_faces());
}

double mean_edge_length(const Mesh& m)
{
    const Adjacency adj = vertex_adjacency(m);
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < adj.size(); ++i)
        for (auto j = adj.begin(i); j != adj.end(i); ++j) {
            sum += (m.points[i] - m.points[*j]).norm();
            ++n;
        }
    return sum / double(n);
}

bool all_finite(const Mesh& m)
{
    return std::all_of(m.points.begin(), m.points.end(), [](const Vec3& p) { return p.allFinite(); });
}

TEST(Smoothing, ZeroIterationsChangeNothing)
{
    const Shape s = noisy_sphere(2, 0.05, 3);
    for (auto m : kMethods)
        for (auto u : kUpdates) {
            Mesh mesh = s.mesh;
            SmoothingOptions o = options(m, u, 0);
            std::vector<int> calls;
            o.callback = [&](int k, const Mesh&) { calls.push_back(k); };
            smooth(mesh, o);
            EXPECT_EQ(mesh.points, s.mesh.points) << label(m, u);
            EXPECT_EQ(calls, std::vector<int>{0}) << label(m, u);
        }
}

TEST(Smoothing, CallbackSeesEveryIterationWithTheCurrentMesh)
{
    Mesh mesh = noisy_sphere(2, 0.05, 3).mesh;
    SmoothingOptions o = options(SmoothingMethod::Taubin, SmoothingUpdate::Post, 4);
    std::vector<int> calls;
    std::vector<double> spread;
    o.callback = [&](int k, const Mesh& current) {
        calls.push_back(k);
        spread.push_back(radial_spread(current));
    };
    smooth(mesh, o);
    EXPECT_EQ(calls, (std::vector<int>{0, 1, 2, 3, 4}));
    EXPECT_DOUBLE_EQ(spread.back(), radial_spread(mesh));
    for (std::size_t k = 1; k < spread.size(); ++k) EXPECT_LT(spread[k], spread[k - 1]) << k;
}

TEST(Smoothing, EveryMethodMakesANoisySphereRounder)
{
    const Shape s = noisy_sphere(3, 0.05, 11);
    const double before = radial_spread(s.mesh);
    EXPECT_GT(before, 0.02);
    for (auto m : kMethods)
        for (auto u : kUpdates) {
            Mesh mesh = s.mesh;
            std::vector<double> spread;
            SmoothingOptions o = options(m, u, 10);
            o.callback = [&](int, const Mesh& current) { spread.push_back(radial_spread(current)); };
            smooth(mesh, o);
            ASSERT_TRUE(all_finite(mesh)) << label(m, u);
            EXPECT_LT(spread[1], spread[0]) << label(m, u);
            EXPECT_LT(radial_spread(mesh), 0.5 * before) << label(m, u);
            EXPECT_EQ(mesh.faces, s.mesh.faces);
        }
}

TEST(Smoothing, LaplacianShrinksAClosedMeshTaubinMuchLess)
{
    const Mesh sphere = icosphere(3).mesh;
    const double v0 = signed_volume(sphere);
    Mesh lap = sphere, taubin = sphere;
    smooth(lap, options(SmoothingMethod::Laplacian, SmoothingUpdate::Post, 20));
    smooth(taubin, options(SmoothingMethod::Taubin, SmoothingUpdate::Post, 20));  // same lambda 0.5
    const double lap_loss = 1 - signed_volume(lap) / v0;
    const double taubin_loss = 1 - signed_volume(taubin) / v0;
    EXPECT_GT(lap_loss, 0.05);
    EXPECT_LT(std::abs(taubin_loss), 0.1 * lap_loss);
}

TEST(Smoothing, MeanCurvatureFlowMovesASphereInwardAtSpeedH)
{
    // On a sphere of radius r, Hn has length 1/r and points inward: one step of
    // size dt shrinks the radius by about dt / r.
    const double r = 2.0;
    const Mesh sphere = icosphere(4, r).mesh;
    for (auto u : kUpdates) {
        Mesh mesh = sphere;
        SmoothingOptions o = options(SmoothingMethod::MeanCurvatureFlow, u, 1);
        o.step = 0.2;
        const double e = mean_edge_length(sphere);
        const double dt = o.step * e * e;
        smooth(mesh, o);
        double mean_r = 0;
        for (const auto& p : mesh.points) mean_r += p.norm() / double(mesh.n_vertices());
        if (u == SmoothingUpdate::Post) {
            EXPECT_NEAR(r - mean_r, dt / r, 0.05 * dt / r);
        } else {
            // In place, later vertices see neighbours that have already moved
            // inward, so the sphere shrinks somewhat more.
            EXPECT_GT(r - mean_r, dt / r);
            EXPECT_LT(r - mean_r, 1.5 * dt / r);
        }
    }
}

TEST(Smoothing, ExplicitFlowsReportTheirStabilityRatio)
{
    // On an icosphere the triangles are near-equilateral, where the bound S =
    // min 4 A / sum |w| is about e^2 / 2: step 0.1 is a ratio of about 0.2.
    const Mesh sphere = icosphere(3).mesh;
    for (auto m : {SmoothingMethod::MeanCurvatureFlow, SmoothingMethod::ModifiedMeanCurvatureFlow}) {
        Mesh mesh = sphere;
        SmoothingOptions o = options(m, SmoothingUpdate::Post, 3);
        const SmoothingReport r = smooth(mesh, o);
        ASSERT_EQ(r.steps.size(), 3u);
        ASSERT_EQ(r.stability_ratio.size(), 3u);
        EXPECT_NEAR(r.mean_edge, mean_edge_length(sphere), 1e-12);
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(r.steps[std::size_t(k)], o.step);
            EXPECT_GT(r.stability_ratio[std::size_t(k)], 0.15);
            EXPECT_LT(r.stability_ratio[std::size_t(k)], 0.3);
        }
        EXPECT_DOUBLE_EQ(r.time, 3 * o.step);
        EXPECT_EQ(r.unstable_iterations, 0);
        // Adaptive control leaves a stable step alone: bitwise the same result.
        Mesh adaptive = sphere;
        o.step_control = StepControl::Adaptive;
        smooth(adaptive, o);
        EXPECT_EQ(adaptive.points, mesh.points) << to_string(m);
    }
    // The umbrella methods and implicit MCF have no step limit to report.
    Mesh mesh = sphere;
    EXPECT_TRUE(smooth(mesh, options(SmoothingMethod::Taubin, SmoothingUpdate::Post, 2)).steps.empty());
    SmoothingOptions o = options(SmoothingMethod::MeanCurvatureFlow, SmoothingUpdate::Post, 2);
    o.implicit = true;
    EXPECT_TRUE(smooth(mesh, o).stability_ratio.empty());
}

TEST(Smoothing, AdaptiveStepControlKeepsAnUnstableFlowStable)
{
    // A step of 1.5 e^2 is three times the stability bound of an equilateral
    // mesh: the fixed-step flow amplifies the noise of a noisy sphere, the
    // adaptive one takes at most half the bound and makes it rounder.
    const Shape s = noisy_sphere(3, 0.02, 5);
    for (auto m : {SmoothingMethod::MeanCurvatureFlow, SmoothingMethod::ModifiedMeanCurvatureFlow})
        for (auto u : kUpdates) {
            SmoothingOptions o = options(m, u, 20);
            o.step = 1.5;
            Mesh fixed = s.mesh, adaptive = s.mesh;
            SmoothingReport rf;
            try {
                rf = smooth(fixed, o);
            } catch (const SolverError&) {
                rf.unstable_iterations = 1;  // diverged to infinity: also unstable
            }
            EXPECT_GT(rf.unstable_iterations, 0) << label(m, u);
            const bool fixed_worse = !all_finite(fixed) || radial_spread(fixed) > radial_spread(s.mesh);
            EXPECT_TRUE(fixed_worse) << label(m, u) << " fixed spread " << radial_spread(fixed);

            o.step_control = StepControl::Adaptive;
            std::vector<double> spread;
            o.callback = [&](int, const Mesh& current) { spread.push_back(radial_spread(current)); };
            const SmoothingReport ra = smooth(adaptive, o);
            ASSERT_TRUE(all_finite(adaptive)) << label(m, u);
            EXPECT_EQ(ra.unstable_iterations, 0) << label(m, u);
            double time = 0;
            for (std::size_t k = 0; k < ra.steps.size(); ++k) {
                EXPECT_LE(ra.stability_ratio[k], o.stability * (1 + 1e-12)) << label(m, u) << " " << k;
                EXPECT_LE(ra.steps[k], o.step) << label(m, u);
                EXPECT_GT(ra.steps[k], 0.0) << label(m, u);
                time += ra.steps[k];
            }
            EXPECT_DOUBLE_EQ(ra.time, time);
            EXPECT_LT(spread.back(), 0.5 * spread.front()) << label(m, u);
        }
}

TEST(Smoothing, BoundaryVerticesStayFixed)
{
    const Shape s = heightfield_irregular(400, 2);
    const std::vector<char> boundary = boundary_vertex_mask(s.mesh);
    ASSERT_GT(std::count(boundary.begin(), boundary.end(), 1), 0);
    for (auto m : kMethods)
        for (auto u : kUpdates) {
            Mesh mesh = s.mesh;
            smooth(mesh, options(m, u, 5));
            std::size_t moved_inner = 0;
            for (std::size_t i = 0; i < mesh.n_vertices(); ++i) {
                if (boundary[i])
                    EXPECT_EQ(mesh.points[i], s.mesh.points[i]) << label(m, u) << " vertex " << i;
                else if (mesh.points[i] != s.mesh.points[i])
                    ++moved_inner;
            }
            EXPECT_GT(moved_inner, mesh.n_vertices() / 2) << label(m, u);
        }
}

TEST(Smoothing, PreAndPostUpdatingDifferAndAreDeterministic)
{
    const Shape s = noisy_sphere(2, 0.05, 5);
    for (auto m : kMethods) {
        Mesh post1 = s.mesh, post2 = s.mesh, pre1 = s.mesh, pre2 = s.mesh;
        smooth(post1, options(m, SmoothingUpdate::Post, 3));
        smooth(post2, options(m, SmoothingUpdate::Post, 3));
        smooth(pre1, options(m, SmoothingUpdate::Pre, 3));
        smooth(pre2, options(m, SmoothingUpdate::Pre, 3));
        EXPECT_EQ(post1.points, post2.points) << to_string(m);
        EXPECT_EQ(pre1.points, pre2.points) << to_string(m);
        double diff = 0;
        for (std::size_t i = 0; i < post1.n_vertices(); ++i)
            diff = std::max(diff, (post1.points[i] - pre1.points[i]).norm());
        EXPECT_GT(diff, 1e-4) << to_string(m);
        // The first vertex sees only old positions in both schemes.
        EXPECT_NE(post1.points, pre1.points);
    }
}

TEST(Smoothing, ResultDoesNotDependOnTheThreadCount)
{
    const Shape s = torus_irregular(1500, 1.0, 0.3, 4);
    const int threads = omp_get_max_threads();
    for (auto m : kMethods) {
        Mesh one = s.mesh, many = s.mesh;
        omp_set_num_threads(1);
        smooth(one, options(m, SmoothingUpdate::Post, 3));
        omp_set_num_threads(4);
        smooth(many, options(m, SmoothingUpdate::Post, 3));
        EXPECT_EQ(one.points, many.points) << to_string(m);
    }
    omp_set_num_threads(threads);
}

TEST(Smoothing, ModifiedMeanCurvatureFlowRegularisesTrianglesMeanCurvatureFlowDoesNot)
{
    const Shape s = torus_irregular(2000, 1.0, 0.3, 9);
    const double q0 = mean_quality(s.mesh);
    for (auto u : kUpdates) {
        Mesh mcf = s.mesh, modified = s.mesh;
        SmoothingOptions o = options(SmoothingMethod::MeanCurvatureFlow, u, 20);
        o.step = 0.05;
        smooth(mcf, o);
        o.method = SmoothingMethod::ModifiedMeanCurvatureFlow;
        smooth(modified, o);
        const double q_mcf = mean_quality(mcf), q_mod = mean_quality(modified);
        EXPECT_GT(q_mod, q0 + 0.02) << to_string(u) << " q0 " << q0 << " mcf " << q_mcf;
        EXPECT_GT(q_mod, q_mcf + 0.02) << to_string(u) << " q0 " << q0 << " mcf " << q_mcf;
    }
}

TEST(Smoothing, ImplicitMeanCurvatureFlowMatchesExplicitForSmallStepsAndTakesLargeOnes)
{
    const Shape s = noisy_sphere(3, 0.03, 21);
    SmoothingOptions o = options(SmoothingMethod::MeanCurvatureFlow, SmoothingUpdate::Post, 1);
    o.step = 0.005;
    Mesh expl = s.mesh, impl = s.mesh;
    smooth(expl, o);
    o.implicit = true;
    smooth(impl, o);
    double moved = 0, diff = 0;
    for (std::size_t i = 0; i < expl.n_vertices(); ++i) {
        moved = std::max(moved, (expl.points[i] - s.mesh.points[i]).norm());
        diff = std::max(diff, (expl.points[i] - impl.points[i]).norm());
    }
    EXPECT_GT(moved, 0.0);
    EXPECT_LT(diff, 0.1 * moved);

    // A step twenty times the explicit stability limit: stays finite and smooths.
    Mesh big = s.mesh;
    o.step = 10;
    o.iterations = 3;
    smooth(big, o);
    ASSERT_TRUE(all_finite(big));
    EXPECT_LT(radial_spread(big), 0.3 * radial_spread(s.mesh));
    // The continuous flow would have collapsed the sphere (t = 30 e^2 > 1/2);
    // backward Euler lags it and keeps a small positive volume.
    EXPECT_GT(signed_volume(big), 0.01 * signed_volume(s.mesh));

    // A sphere under mean curvature flow (speed H = 1/r) has r^2 = r0^2 - 2t;
    // with moderate implicit steps the volume follows (r^2)^(3/2).
    Mesh moderate = s.mesh;
    o.step = 1;
    o.iterations = 5;
    smooth(moderate, o);
    const double e = mean_edge_length(s.mesh), t = o.iterations * o.step * e * e;
    const double expected = std::pow(1 - 2 * t, 1.5);
    EXPECT_NEAR(signed_volume(moderate) / signed_volume(s.mesh), expected, 0.1 * expected) << "t " << t;

    // Boundary rows stay fixed.
    const Shape hf = heightfield_irregular(400, 2);
    const std::vector<char> boundary = boundary_vertex_mask(hf.mesh);
    Mesh open = hf.mesh;
    o.step = 2;
    smooth(open, o);
    std::size_t moved_inner = 0;
    for (std::size_t i = 0; i < open.n_vertices(); ++i) {
        if (boundary[i])
            EXPECT_EQ(open.points[i], hf.mesh.points[i]) << i;
        else if (open.points[i] != hf.mesh.points[i])
            ++moved_inner;
    }
    EXPECT_GT(moved_inner, open.n_vertices() / 2);
}

TEST(Smoothing, DegenerateFacesProduceNoNaN)
{
    Mesh mesh = noisy_sphere(2, 0.02, 4).mesh;
    // Collapse vertex 0 onto a neighbour: two faces get zero area, one edge zero length.
    const Adjacency adj = vertex_adjacency(mesh);
    mesh.points[0] = mesh.points[*adj.begin(0)];
    for (auto m : kMethods)
        for (auto u : kUpdates) {
            Mesh out = mesh;
            smooth(out, options(m, u, 5));
            EXPECT_TRUE(all_finite(out)) << label(m, u);
        }
    SmoothingOptions o = options(SmoothingMethod::MeanCurvatureFlow, SmoothingUpdate::Post, 5);
    o.implicit = true;
    smooth(mesh, o);
    EXPECT_TRUE(all_finite(mesh)) << "implicit mcf";
}

TEST(Smoothing, InvalidOptionsThrowNamingTheField)
{
    auto message = [](SmoothingOptions o) {
        Mesh mesh = icosphere(1).mesh;
        try {
            smooth(mesh, o);
        } catch (const InvalidArgumentError& e) {
            return std::string(e.what());
        }
        return std::string("no throw");
    };
    SmoothingOptions o;
    o.iterations = -1;
    EXPECT_NE(message(o).find("iterations"), std::string::npos);
    o = SmoothingOptions{};
    o.lambda = 0;
    EXPECT_NE(message(o).find("lambda"), std::string::npos);
    o = SmoothingOptions{};
    o.method = SmoothingMethod::Taubin;
    o.mu = -0.4;
    EXPECT_NE(message(o).find("mu"), std::string::npos);
    o = SmoothingOptions{};
    o.method = SmoothingMethod::Bilaplacian;
    o.damping = 1.5;
    EXPECT_NE(message(o).find("damping"), std::string::npos);
    o = SmoothingOptions{};
    o.method = SmoothingMethod::MeanCurvatureFlow;
    o.step = std::nan("");
    EXPECT_NE(message(o).find("step"), std::string::npos);
    o = SmoothingOptions{};
    o.method = SmoothingMethod::ModifiedMeanCurvatureFlow;
    o.epsilon = 1.0;
    EXPECT_NE(message(o).find("epsilon"), std::string::npos);
    o = SmoothingOptions{};
    o.method = SmoothingMethod::Taubin;
    o.implicit = true;
    EXPECT_NE(message(o).find("implicit"), std::string::npos);
    o.method = SmoothingMethod::MeanCurvatureFlow;
    o.update = SmoothingUpdate::Pre;
    EXPECT_NE(message(o).find("implicit"), std::string::npos);
    o = SmoothingOptions{};
    o.method = SmoothingMethod::MeanCurvatureFlow;
    o.stability = 0;
    EXPECT_NE(message(o).find("stability"), std::string::npos);
    // Fields of other methods are not checked.
    o = SmoothingOptions{};
    o.mu = 0.7;
    o.stability = 2;
    EXPECT_EQ(message(o), "no throw");

    EXPECT_THROW(parse_enum<SmoothingMethod>("gauss"), InvalidArgumentError);
    EXPECT_THROW(parse_enum<SmoothingUpdate>("sideways"), InvalidArgumentError);
    for (auto m : kMethods) EXPECT_EQ(parse_enum<SmoothingMethod>(to_string(m)), m);
    for (auto u : kUpdates) EXPECT_EQ(parse_enum<SmoothingUpdate>(to_string(u)), u);
    EXPECT_THROW(parse_enum<StepControl>("sometimes"), InvalidArgumentError);
    for (auto c : {StepControl::Fixed, StepControl::Adaptive}) EXPECT_EQ(parse_enum<StepControl>(to_string(c)), c);
}

TEST(Smoothing, HugeFlowStepLeavesOnlyFiniteCoordinates)
{
    Mesh mesh = torus_irregular(1000, 1.0, 0.25, 3).mesh;
    SmoothingOptions o = options(SmoothingMethod::MeanCurvatureFlow, SmoothingUpdate::Post, 100);
    o.step = 10;
    try {
        smooth(mesh, o);
    } catch (const SolverError&) {}
    EXPECT_TRUE(all_finite(mesh));
}

}  // namespace
}  // namespace meshdiff
