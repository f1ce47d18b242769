#include "meshdiff/roughness/roughness.h"

#include <gtest/gtest.h>

#include "support/data.h"

#include "meshdiff/error.h"
#include "meshdiff/geometry/normals.h"
#include "meshdiff/io/io.h"
#include "meshdiff/roughness/curvature.h"
#include "meshdiff/roughness/neighborhood.h"
#include "meshdiff/studies/shapes.h"

#include <omp.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

using namespace meshdiff;
using meshdiff::test::data;

namespace {

// Brute force: D_L by a BFS per vertex, straight from the definition.
std::vector<double> brute_force_D(const Mesh& mesh, const std::vector<double>& H, int L)
{
    const Adjacency adj = vertex_adjacency(mesh);
    std::vector<double> D(H.size(), std::nan(""));
    for (std::size_t i = 0; i < H.size(); ++i) {
        if (std::isnan(H[i])) continue;
        const auto dist = ring_distances(adj, i, L);
        double sum = 0;
        int cnt = 0;
        for (std::size_t j = 0; j < H.size(); ++j)
            if (j != i && dist[j] > 0 && !std::isnan(H[j])) {
                sum += H[j];
                ++cnt;
            }
        if (cnt) D[i] = H[i] - sum / cnt;
    }
    return D;
}

double rms(const std::vector<double>& D)
{
    double s = 0;
    int n = 0;
    for (double d : D)
        if (!std::isnan(d)) {
            s += d * d;
            ++n;
        }
    return std::sqrt(s / n);
}

}  // namespace

TEST(RoughnessProfile, MatchesBruteForceOnARealMesh)
{
    const Mesh mesh = read_mesh(data("bunny_res4_ascii.ply")).mesh;
    ProfileOptions opt;
    opt.levels = {1, 2, 3, 5, 8};
    opt.keep_vertex_data = true;
    const auto p = roughness_profile(mesh, opt);
    const Mesh unit = apply_normalization(mesh, p.normalization);
    for (std::size_t k = 0; k < opt.levels.size(); ++k) {
        const auto D = brute_force_D(unit, p.H, opt.levels[k]);
        for (std::size_t i = 0; i < D.size(); ++i) {
            ASSERT_EQ(std::isnan(D[i]), std::isnan(p.D[k][i])) << "vertex " << i;
            if (!std::isnan(D[i])) {
                ASSERT_NEAR(D[i], p.D[k][i], 1e-12 * (1 + std::abs(D[i])));
            }
        }
        EXPECT_NEAR(p.levels[k].sigma, rms(D), 1e-12 * rms(D));
    }
}

TEST(RoughnessProfile, GlobalLevelIsScaledStandardDeviation)
{
    // METHOD.md section 5: sigma_G = n/(n-1) * population standard deviation of H.
    for (const char* name : {"bunny_res4_ascii.ply", "fandisk.ply", "teapot.obj"}) {
        const Mesh mesh = read_mesh(data(name)).mesh;
        ProfileOptions opt;
        opt.levels = {1};
        opt.keep_vertex_data = true;
        const auto p = roughness_profile(mesh, opt);
        double mean = 0;
        int n = 0;
        for (double h : p.H)
            if (!std::isnan(h)) {
                mean += h;
                ++n;
            }
        mean /= n;
        double var = 0;
        for (double h : p.H)
            if (!std::isnan(h)) var += (h - mean) * (h - mean);
        const double expected = double(n) / (n - 1) * std::sqrt(var / n);
        EXPECT_NEAR(p.global.sigma, expected, 1e-10 * expected) << name;
        EXPECT_EQ(p.global.vertices_used, std::size_t(n)) << name;
    }
}

TEST(RoughnessProfile, LevelsBeyondTheDiameterEqualGlobal)
{
    const Shape s = icosphere(2);  // 162 vertices, graph diameter well below 30
    ProfileOptions opt;
    opt.levels = {30, 100};
    const auto p = roughness_profile(s.mesh, opt);
    EXPECT_NEAR(p.levels[0].sigma, p.global.sigma, 1e-12 * p.global.sigma);
    EXPECT_NEAR(p.levels[1].sigma, p.global.sigma, 1e-12 * p.global.sigma);
    EXPECT_GT(p.global.sigma, 0.0);
}

TEST(RoughnessProfile, InvariantToTranslationRotationScaleAndVertexOrder)
{
    const Mesh mesh = read_mesh(data("bunny_res3.ply")).mesh;
    ProfileOptions opt;
    opt.levels = {1, 2, 5, 10};
    const auto ref = roughness_profile(mesh, opt);

    Mesh moved = mesh;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    for (auto& p : moved.points) p = 37.5 * (R * p) + Vec3(100, -20, 5);
    const auto q = roughness_profile(moved, opt);

    // A random permutation of the vertices (faces renumbered).
    Mesh perm = mesh;
    std::vector<std::int32_t> order(mesh.n_vertices());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937_64(3));
    for (std::size_t i = 0; i < order.size(); ++i) perm.points[std::size_t(order[i])] = mesh.points[i];
    for (auto& f : perm.faces)
        for (auto& v : f) v = order[std::size_t(v)];
    const auto r = roughness_profile(perm, opt);

    for (std::size_t k = 0; k < ref.levels.size(); ++k) {
        EXPECT_NEAR(q.levels[k].sigma, ref.levels[k].sigma, 1e-8 * ref.levels[k].sigma);
        EXPECT_NEAR(r.levels[k].sigma, ref.levels[k].sigma, 1e-10 * ref.levels[k].sigma);
    }
    EXPECT_NEAR(q.global.sigma, ref.global.sigma, 1e-8 * ref.global.sigma);
    EXPECT_NEAR(r.global.sigma, ref.global.sigma, 1e-10 * ref.global.sigma);
    EXPECT_NEAR(q.normalization.scale, 37.5 * ref.normalization.scale, 1e-9 * q.normalization.scale);
}

TEST(RoughnessProfile, IdenticalForAnyThreadCount)
{
    const Mesh mesh = read_mesh(data("fandisk.ply")).mesh;
    ProfileOptions opt;
    opt.keep_vertex_data = true;
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const auto a = roughness_profile(mesh, opt);
    omp_set_num_threads(2);
    const auto b = roughness_profile(mesh, opt);
    omp_set_num_threads(3);
    const auto c = roughness_profile(mesh, opt);
    omp_set_num_threads(saved);
    for (std::size_t k = 0; k < a.levels.size(); ++k) {
        EXPECT_EQ(a.levels[k].sigma, b.levels[k].sigma);
        EXPECT_EQ(a.levels[k].sigma, c.levels[k].sigma);
    }
    EXPECT_EQ(a.H, b.H);
    EXPECT_EQ(a.global.sigma, c.global.sigma);
}

TEST(RoughnessProfile, NoisySphereIsRougherLocallyThanGlobally)
{
    // The paper's observation for a noisy sphere, with its own sphere generator.
    const Shape s = noisy_sphere(4, 0.01, 11);
    const auto p = roughness_profile(s.mesh);
    EXPECT_GT(p.levels[0].sigma, p.global.sigma);
    // Smooth sphere: every level is small next to the noisy one.
    const auto smooth = roughness_profile(icosphere(4).mesh);
    EXPECT_LT(smooth.levels[0].sigma, 0.2 * p.levels[0].sigma);
}

TEST(RoughnessProfile, DirtyMeshesGiveFiniteProfiles)
{
    for (const char* name : {"teapot.obj", "bunny_res3.ply", "bunny_res4_ascii.ply", "hemisphere.ply"}) {
        for (auto method :
             {CurvatureMethod::GoldfeatherCubic, CurvatureMethod::Quadric, CurvatureMethod::MeyerCotangent}) {
            const Mesh mesh = read_mesh(data(name)).mesh;
            ProfileOptions opt;
            opt.curvature.method = method;
            const auto p = roughness_profile(mesh, opt);
            for (const auto& l : p.levels) {
                EXPECT_TRUE(std::isfinite(l.sigma)) << name;
                EXPECT_GT(l.vertices_used, 0u) << name;
                EXPECT_EQ(l.vertices_used + l.no_neighborhood + p.curvature_undefined, mesh.n_vertices()) << name;
            }
            EXPECT_TRUE(std::isfinite(p.global.sigma)) << name;
        }
    }
}

TEST(RoughnessProfile, RejectsBadLevels)
{
    const Shape s = icosphere(1);
    ProfileOptions opt;
    opt.levels = {1, 0};
    EXPECT_THROW(roughness_profile(s.mesh, opt), InvalidArgumentError);
    opt.levels = {};
    opt.global = false;
    EXPECT_THROW(roughness_profile(s.mesh, opt), InvalidArgumentError);
}

TEST(LevelRoughness, TopShareFlagsOneDominantVertex)
{
    std::vector<double> D(2000, 0.01);
    D[17] = 100.0;
    D[3] = std::nan("");
    const auto l = level_roughness(1, D);
    EXPECT_EQ(l.vertices_used, 1999u);
    EXPECT_GT(l.top_share, 0.99);
    ASSERT_FALSE(l.worst_vertices.empty());
    EXPECT_EQ(l.worst_vertices[0], 17u);
    std::vector<double> even(2000, 0.5);
    EXPECT_NEAR(level_roughness(1, even).top_share, 2.0 / 2000.0, 1e-12);
}

// The worst vertices against a brute-force sort by (|D| descending, id),
// with many ties (values from a small set, both signs), NaN and fewer
// defined values than the list's length; the top share against a full sort
// (equal up to the order of the top k's summation).
TEST(LevelRoughness, WorstVerticesAndTopShareMatchABruteForceSort)
{
    std::mt19937 rng(11);
    for (const std::size_t n : {0u, 1u, 5u, 9u, 10u, 11u, 300u, 5000u}) {
        std::uniform_int_distribution<int> pick(-6, 6);
        std::vector<double> D(n);
        for (auto& d : D) {
            const int k = pick(rng);
            d = k == 6 ? std::nan("") : 0.25 * k;
        }
        const auto l = level_roughness(1, D, 0.05);
        std::vector<std::uint32_t> ids;
        for (std::size_t i = 0; i < n; ++i)
            if (!std::isnan(D[i])) ids.push_back(std::uint32_t(i));
        std::sort(ids.begin(), ids.end(), [&](std::uint32_t a, std::uint32_t b) {
            return std::abs(D[a]) != std::abs(D[b]) ? std::abs(D[a]) > std::abs(D[b]) : a < b;
        });
        ids.resize(std::min<std::size_t>(10, ids.size()));
        EXPECT_EQ(l.worst_vertices, ids) << n;
        std::vector<double> sq;
        for (double d : D)
            if (!std::isnan(d)) sq.push_back(d * d);
        std::sort(sq.begin(), sq.end(), std::greater<>());
        const double total = std::accumulate(sq.begin(), sq.end(), 0.0);
        if (total > 0.0) {
            const auto k = std::max<std::size_t>(1, std::size_t(std::ceil(0.05 * double(sq.size()))));
            EXPECT_NEAR(l.top_share, std::accumulate(sq.begin(), sq.begin() + std::ptrdiff_t(k), 0.0) / total, 1e-12)
                << n;
        }
    }
}

TEST(RoughnessProfile, FromExactCurvatureOfASphereIsZeroEverywhere)
{
    const Shape s = icosphere(3, 2.5);
    const auto p = roughness_profile_from_curvature(s.mesh, s.exact_H);
    for (const auto& l : p.levels) EXPECT_NEAR(l.sigma, 0.0, 1e-14);
    EXPECT_NEAR(p.global.sigma, 0.0, 1e-14);
    // The torus has a non-constant exact H: the true profile grows with the level.
    const Shape t = torus(64, 32);
    const auto q = roughness_profile_from_curvature(t.mesh, t.exact_H);
    EXPECT_LT(q.levels[0].sigma, q.levels[9].sigma);
    EXPECT_LT(q.levels[9].sigma, q.global.sigma * 1.0001);
    EXPECT_THROW(roughness_profile_from_curvature(t.mesh, {1.0, 2.0}), InvalidArgumentError);
}

// ---- bootstrap interval of sigma (issue 29: "a seeded bootstrap interval of sigma_L over vertices")

TEST(Bootstrap, IntervalOfTheRmsOfNormalNoiseHasTheWidthTheoryGives)
{
    // D iid normal(0, 1), n = 20,000: sigma-hat = RMS has standard error about
    // 1 / sqrt(2 n) (Var(D^2) = 2), so the 95% interval is about 2 x 1.96 / sqrt(2 n) = 0.0196 wide around 1.
    std::mt19937_64 rng(5);
    std::normal_distribution<double> normal;
    std::vector<double> D(20000);
    for (double& d : D) d = normal(rng);
    D[7] = std::numeric_limits<double>::quiet_NaN();  // undefined values are left out
    const auto i = bootstrap_interval(D, 0.0, 2000, 1);
    ASSERT_TRUE(i);
    double sum = 0.0;
    for (double d : D)
        if (!std::isnan(d)) sum += d * d;
    const double sigma = std::sqrt(sum / double(D.size() - 1));
    EXPECT_LT(i->first, sigma);
    EXPECT_GT(i->second, sigma);
    const double width = i->second - i->first, theory = 2.0 * 1.96 / std::sqrt(2.0 * double(D.size() - 1));
    EXPECT_NEAR(width, theory, 0.15 * theory);
    // Nothing to resample: no interval.
    EXPECT_FALSE(bootstrap_interval(D, 0.0, 0, 1));
    EXPECT_FALSE(bootstrap_interval(std::vector<double>(5, std::nan("")), 0.0, 100, 1));
}

TEST(Bootstrap, SeededAndTheSameAtAnyThreadCount)
{
    std::mt19937_64 rng(3);
    std::exponential_distribution<double> e;
    std::vector<double> D(5000), w(5000);
    for (double& d : D) d = e(rng);
    for (double& x : w) x = 0.5 + e(rng);
    for (double trim : {0.0, 0.05})
        for (const std::vector<double>* weights :
             {static_cast<const std::vector<double>*>(nullptr), static_cast<const std::vector<double>*>(&w)}) {
            const int saved = omp_get_max_threads();
            omp_set_num_threads(1);
            const auto one = bootstrap_interval(D, trim, 300, 9, weights);
            omp_set_num_threads(2);
            const auto two = bootstrap_interval(D, trim, 300, 9, weights);
            omp_set_num_threads(saved);
            ASSERT_TRUE(one && two);
            EXPECT_EQ(one->first, two->first);  // bitwise
            EXPECT_EQ(one->second, two->second);
            EXPECT_EQ(*one, *bootstrap_interval(D, trim, 300, 9, weights));
            EXPECT_NE(*one, *bootstrap_interval(D, trim, 300, 10, weights));  // another seed, another draw
            // The interval holds the statistic it is about.
            std::size_t dropped = 0;
            const double s = trimmed_rms(D, trim, weights, &dropped);
            EXPECT_LT(one->first, s) << trim;
            EXPECT_GT(one->second, s) << trim;
        }
}

TEST(Bootstrap, ProfileLevelsCarryTheirIntervalAndTheOptionIsChecked)
{
    const Shape s = noisy_sphere(3, 0.02, 1);
    ProfileOptions o;
    o.levels = {1, 3};
    o.radii = {0.3};
    o.bootstrap = 200;
    const RoughnessProfile p = roughness_profile(s.mesh, o);
    EXPECT_EQ(p.bootstrap, 200u);
    for (const LevelRoughness* l : {&p.levels[0], &p.levels[1], &p.global, &p.radii[0]}) {
        ASSERT_TRUE(l->sigma_interval);
        EXPECT_LT(l->sigma_interval->first, l->sigma);
        EXPECT_GT(l->sigma_interval->second, l->sigma);
    }
    o.bootstrap = 0;
    EXPECT_FALSE(roughness_profile(s.mesh, o).levels[0].sigma_interval);
    o.bootstrap = kMaxBootstrap + 1;
    EXPECT_THROW(roughness_profile(s.mesh, o), OptionError);
}

TEST(PaperMethod, IsTheGoldfeatherFitPaperScaleUntrimmedAndKeepsTheOtherFields)
{
    ProfileOptions base;
    base.levels = {1, 4};
    base.radii = {0.2};
    base.bootstrap = 30;
    base.trim = 0.1;
    base.normalize = NormalizeMethod::Area;
    const ProfileOptions p = paper_profile_options(base);
    EXPECT_TRUE(p.paper);
    EXPECT_EQ(p.curvature.method, CurvatureMethod::GoldfeatherCubic);
    EXPECT_EQ(p.curvature.weighting, RowWeighting::None);
    EXPECT_EQ(p.normalize, NormalizeMethod::Paper);
    EXPECT_EQ(p.trim, 0.0);
    EXPECT_EQ(p.levels, base.levels);
    EXPECT_EQ(p.radii, base.radii);
    EXPECT_EQ(p.bootstrap, base.bootstrap);
    EXPECT_NO_THROW(validate(p));

    // The same numbers, bit for bit, as the goldfeather fit asked for field by field.
    const Shape s = noisy_sphere(3, 0.02, 1);
    ProfileOptions by_hand;
    by_hand.levels = {1, 4};
    by_hand.curvature.method = CurvatureMethod::GoldfeatherCubic;
    const RoughnessProfile a = roughness_profile(s.mesh, paper_profile_options(by_hand));
    const RoughnessProfile b = roughness_profile(s.mesh, by_hand);
    ASSERT_EQ(a.levels.size(), b.levels.size());
    for (std::size_t i = 0; i < a.levels.size(); ++i) EXPECT_EQ(a.levels[i].sigma, b.levels[i].sigma);
    EXPECT_EQ(a.global.sigma, b.global.sigma);
}

TEST(PaperMethod, AFieldThatContradictsItIsRefusedNamingPaperAndTheField)
{
    auto refused = [](const ProfileOptions& o, const std::string& field) {
        try {
            validate(o);
        } catch (const OptionError& e) {
            EXPECT_EQ(e.field(), "profile.paper");
            EXPECT_NE(e.problem().find("{" + field + "}"), std::string::npos) << e.problem();
            return;
        }
        ADD_FAILURE() << "not refused: " << field;
    };
    ProfileOptions o = paper_profile_options();
    o.curvature.method = CurvatureMethod::Jet;
    refused(o, "profile.curvature.method");
    o = paper_profile_options();
    o.curvature.weighting = RowWeighting::InverseSquare;
    refused(o, "profile.curvature.weighting");
    o = paper_profile_options();
    o.normalize = NormalizeMethod::Area;
    refused(o, "profile.normalize");
    o = paper_profile_options();
    o.trim = 0.05;
    refused(o, "profile.trim");
}

// Issue 30, lever 5: without per-vertex data the ring levels are folded batch
// by batch (no levels x n means, no D). Against the stored path (D kept):
// the same counts, trims and worst vertices (the same D in the same total
// order), sigma and the top share within the rounding of their sums; and the
// same bits at any thread count. H with undefined vertices, so that centres
// and levels without a defined neighbour are left out as in the stored path.
TEST(RoughnessProfile, FoldedLevelsAreTheStoredLevelsButForTheRoundingOfTheirSums)
{
    const Mesh mesh = read_mesh(data("fandisk.ply")).mesh;
    std::vector<double> H(mesh.n_vertices());
    for (std::size_t i = 0; i < H.size(); ++i)
        H[i] = i % 13 == 4 ? std::nan("") : std::sin(0.37 * double(i)) + (i % 97 == 0 ? 40.0 : 0.0);
    struct Case
    {
        double trim, outlier;
    };
    for (const Case c : {Case{0.0, 0.001}, Case{0.1, 0.001}, Case{0.0, 0.05}, Case{0.04, 0.02}}) {
        ProfileOptions o;
        o.levels = {1, 2, 3, 7, 20};
        o.trim = c.trim;
        o.outlier_fraction = c.outlier;
        o.keep_vertex_data = true;
        const RoughnessProfile stored = roughness_profile_from_curvature(mesh, H, o);
        o.keep_vertex_data = false;
        const int saved = omp_get_max_threads();
        omp_set_num_threads(1);
        const RoughnessProfile one = roughness_profile_from_curvature(mesh, H, o);
        omp_set_num_threads(2);
        const RoughnessProfile folded = roughness_profile_from_curvature(mesh, H, o);
        omp_set_num_threads(saved);
        ASSERT_TRUE(folded.D.empty());
        ASSERT_EQ(folded.levels.size(), stored.levels.size());
        for (std::size_t k = 0; k < stored.levels.size(); ++k) {
            const LevelRoughness &s = stored.levels[k], &f = folded.levels[k], &f1 = one.levels[k];
            SCOPED_TRACE(testing::Message() << "trim " << c.trim << " outlier " << c.outlier << " level " << s.level);
            EXPECT_EQ(f.vertices_used, s.vertices_used);
            EXPECT_EQ(f.no_neighborhood, s.no_neighborhood);
            EXPECT_EQ(f.trimmed, s.trimmed);
            EXPECT_EQ(f.worst_vertices, s.worst_vertices);
            EXPECT_GT(s.sigma, 0.0);
            EXPECT_NEAR(f.sigma, s.sigma, 1e-13 * s.sigma);
            EXPECT_NEAR(f.top_share, s.top_share, 1e-13 * s.top_share);
            // The same bits at 1 and 2 threads.
            EXPECT_EQ(f1.sigma, f.sigma);
            EXPECT_EQ(f1.top_share, f.top_share);
            EXPECT_EQ(f1.worst_vertices, f.worst_vertices);
        }
        if (c.trim > 0.0) {  // the trim left vertices out
            EXPECT_GT(folded.levels[0].trimmed, 0u);
        }
    }
}

// The folded path is not taken where the stored D is needed: the bootstrap
// resamples it (its interval is there) and keep_vertex_data keeps it.
TEST(RoughnessProfile, BootstrapAndVertexDataKeepTheStoredLevels)
{
    const Mesh mesh = read_mesh(data("bunny_res3.ply")).mesh;
    ProfileOptions o;
    o.levels = {1, 2};
    o.bootstrap = 20;
    const RoughnessProfile p = roughness_profile(mesh, o);
    ASSERT_TRUE(p.levels[0].sigma_interval.has_value());
    EXPECT_LE(p.levels[0].sigma_interval->first, p.levels[0].sigma_interval->second);
    o.bootstrap = 0;
    o.keep_vertex_data = true;
    const RoughnessProfile kept = roughness_profile(mesh, o);
    ASSERT_EQ(kept.D.size(), 2u);
    EXPECT_EQ(kept.D[0].size(), mesh.n_vertices());
}
