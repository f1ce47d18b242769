#include "meshdiff/roughness/local_roughness.h"

#include <gtest/gtest.h>

#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/geometry/normalize.h"
#include "meshdiff/geometry/point_triangle.h"
#include "meshdiff/report/json.h"
#include "meshdiff/roughness/metric_levels.h"
#include "meshdiff/roughness/neighborhood.h"
#include "meshdiff/roughness/roughness_distance.h"
#include "meshdiff/studies/shapes.h"

#include <omp.h>

#include <cmath>

using namespace meshdiff;

namespace {

ProfileOptions with_data(std::vector<int> levels = {1, 2, 5})
{
    ProfileOptions o;
    o.levels = std::move(levels);
    o.keep_vertex_data = true;
    return o;
}

LoadedMesh loaded(Mesh m)
{
    LoadedMesh l;
    l.mesh = std::move(m);
    return l;
}

Mesh transformed(const Mesh& m, double scale, const Vec3& shift)
{
    // A rotation about a skew axis, a scale and a shift.
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
    Mesh out = m;
    for (auto& p : out.points) p = scale * (R * p) + shift;
    return out;
}

// H' of \p pb at the brute-force closest point of \p b to \p p, interpolated
// over the triangle holding it.
double H_at_closest_point(const Mesh& b, const RoughnessProfile& pb, const Vec3& p)
{
    const ClosestPoint cp = closest_point_brute_force(b, p);
    const Face& f = b.faces[cp.face];
    const Vec3 w =
        barycentric(cp.point, b.points[std::size_t(f[0])], b.points[std::size_t(f[1])], b.points[std::size_t(f[2])]);
    double at = 0.0;
    for (int c = 0; c < 3; ++c) at += w[c] * pb.H[std::size_t(f[std::size_t(c)])];
    return at;
}

// The first form of the measure (before the operator was shared), written
// out: D_L(i) - D'_L(cp(i)) with D' on the other mesh's own rings, untrimmed.
double first_form(const Mesh& a, const RoughnessProfile& pa, const Mesh& b, const RoughnessProfile& pb, std::size_t k)
{
    double total = 0.0;
    for (std::size_t i = 0; i < a.n_vertices(); ++i) {
        const ClosestPoint cp = closest_point_brute_force(b, a.points[i]);
        const Face& f = b.faces[cp.face];
        const Vec3 w = barycentric(cp.point, b.points[std::size_t(f[0])], b.points[std::size_t(f[1])],
                                   b.points[std::size_t(f[2])]);
        double at = 0.0;
        for (int c = 0; c < 3; ++c) at += w[c] * pb.D[k][std::size_t(f[std::size_t(c)])];
        total += (pa.D[k][i] - at) * (pa.D[k][i] - at);
    }
    return std::sqrt(total / double(a.n_vertices()));
}

// A sphere with smooth radial bumps, sampled by icosphere(subdivisions): the
// coarser samplings of the same surface play a decimation series.
Mesh bumpy_sphere(int subdivisions)
{
    Mesh m = icosphere(subdivisions).mesh;
    for (auto& p : m.points) p *= 1.0 + 0.05 * std::sin(6.0 * p.x()) * std::sin(6.0 * p.y()) * std::sin(6.0 * p.z());
    return m;
}

}  // namespace

TEST(LocalRoughness, ZeroForAMeshAgainstItself)
{
    const Mesh m = noisy_sphere(3, 0.02, 7).mesh;
    ProfileOptions o = with_data();
    o.radii = {0.2};
    const RoughnessProfile p = roughness_profile(m, o);
    const ClosestPointIndex index(m);
    const LocalRoughnessDistance d = local_roughness_distance(m, p, m, p, index, 0.0, true);
    ASSERT_EQ(d.levels, (std::vector<int>{1, 2, 5}));
    for (std::size_t k = 0; k < d.levels.size(); ++k) {
        EXPECT_EQ(d.rms[k], 0.0) << d.levels[k];
        EXPECT_EQ(d.used[k], m.n_vertices());
    }
    ASSERT_TRUE(d.has_global);
    EXPECT_EQ(d.global, 0.0);
    ASSERT_EQ(d.rms_radii.size(), 1u);
    EXPECT_EQ(d.rms_radii[0], 0.0);
    ASSERT_EQ(d.vertex.size(), 3u);
    for (double x : d.vertex[0]) EXPECT_EQ(x, 0.0);
}

// The formula written out on small meshes: F(i) = H(i) - H'(cp(i)) with a
// brute-force closest point, the original's rings by breadth-first search,
// its balls by ball_patch(), its global level by a plain mean, and the
// area-weighted RMS.
TEST(LocalRoughness, EqualsABruteForceFormulaOnSmallMeshes)
{
    const Mesh a = noisy_sphere(2, 0.03, 1).mesh;
    const Mesh b = noisy_sphere(1, 0.01, 2).mesh;  // coarser: a "decimation"
    ProfileOptions o = with_data();
    o.radii = {0.5};
    const RoughnessProfile pa = roughness_profile(a, o);
    const RoughnessProfile pb = roughness_profile(b, o);
    const LocalRoughnessDistance d = local_roughness_distance(a, pa, b, pb, ClosestPointIndex(b), 0.0, true);
    const std::size_t n = a.n_vertices();
    std::vector<double> F(n);
    for (std::size_t i = 0; i < n; ++i) F[i] = pa.H[i] - H_at_closest_point(b, pb, a.points[i]);
    const Mesh unit = apply_normalization(a, pa.normalization);
    const Adjacency adj = vertex_adjacency(unit);
    const std::vector<double> area = vertex_areas(unit);
    double area_sum = 0.0;
    for (double x : area) area_sum += x;
    // The area-weighted RMS of F(i) - mean(i), mean(i) over the j with in(i, j).
    auto expected = [&](auto in, const std::vector<double>* map) {
        double total = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            double sum = 0.0, count = 0.0;
            for (std::size_t j = 0; j < n; ++j)
                if (j != i) {
                    const double w = in(i, j);
                    sum += w * F[j];
                    count += w;
                }
            const double D = F[i] - sum / count;
            if (map) {
                EXPECT_NEAR((*map)[i], D, 1e-9 * (1.0 + std::abs(D))) << i;
            }
            total += area[i] * D * D;
        }
        return std::sqrt(total / area_sum);
    };
    ASSERT_EQ(d.levels, (std::vector<int>{1, 2, 5}));
    for (std::size_t k = 0; k < 3; ++k) {
        std::vector<std::vector<int>> ring(n);
        for (std::size_t i = 0; i < n; ++i) ring[i] = ring_distances(adj, i, d.levels[k]);
        const double e =
            expected([&](std::size_t i, std::size_t j) { return ring[i][j] >= 1 ? 1.0 : 0.0; }, &d.vertex[k]);
        EXPECT_NEAR(d.rms[k], e, 1e-9 * e) << d.levels[k];
        EXPECT_GT(d.rms[k], 0.0);
        EXPECT_EQ(d.used[k], n);
    }
    ASSERT_TRUE(d.has_global);
    const double g = expected([](std::size_t, std::size_t) { return 1.0; }, nullptr);
    EXPECT_NEAR(d.global, g, 1e-9 * g);
    std::vector<std::vector<double>> ball(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i)
        for (std::uint32_t j : ball_patch(unit, adj, i, 0.5)) ball[i][j] = area[j];
    ASSERT_EQ(d.radii, (std::vector<double>{0.5}));
    const double r = expected([&](std::size_t i, std::size_t j) { return ball[i][j]; }, nullptr);
    EXPECT_NEAR(d.rms_radii[0], r, 1e-9 * r);
    // Linear in F: the original's D_L minus the processed H' read through the
    // original's rings.
    std::vector<double> G(n);
    for (std::size_t i = 0; i < n; ++i) G[i] = pa.H[i] - F[i];
    const DiskMeans gm = disk_means(unit, adj, G, {1});
    for (std::size_t i = 0; i < n; ++i)
        EXPECT_NEAR(d.vertex[0][i], pa.D[0][i] - (G[i] - gm.mean[0][i]), 1e-9 * (1.0 + std::abs(pa.D[0][i])));
}

// Today's first form lets two changes cancel: against ever coarser samplings
// of one bumpy sphere it falls at level 1 (the coarse mesh's own D', on rings
// that span ever larger patches, is uncorrelated with the original's and
// shrinks), while the detail of the change on the original's rings grows.
TEST(LocalRoughness, GrowsWhereTheFirstFormSaturates)
{
    const Mesh a = bumpy_sphere(4);
    const RoughnessProfile pa = roughness_profile(a, with_data({1, 2}));
    std::vector<double> first, now;
    for (int s : {3, 2, 1}) {
        const Mesh b = bumpy_sphere(s);
        const RoughnessProfile pb = roughness_profile(b, with_data({1, 2}));
        first.push_back(first_form(a, pa, b, pb, 0));
        now.push_back(local_roughness_distance(a, pa, b, pb, ClosestPointIndex(b)).rms[0]);
    }
    EXPECT_GT(first[1], first[2]);  // the first form falls from 162 to 42 vertices
    EXPECT_GT(now[1], now[0]);
    EXPECT_GT(now[2], now[1]);
    // And the bound: all detail lost, the original's own area-weighted sigma_1.
    const Mesh unit = apply_normalization(a, pa.normalization);
    const std::vector<double> area = vertex_areas(unit);
    const double sigma = trimmed_rms(pa.D[0], 0.0, &area);
    EXPECT_LT(now[2], 1.2 * sigma);
}

TEST(LocalRoughness, BarycentricCoordinates)
{
    const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    const Vec3 w = barycentric(Vec3(0.5, 0.5, 0), a, b, c);
    EXPECT_NEAR(w[0], 0.5, 1e-15);
    EXPECT_NEAR(w[1], 0.25, 1e-15);
    EXPECT_NEAR(w[2], 0.25, 1e-15);
    EXPECT_EQ(barycentric(b, a, b, c), Vec3(0, 1, 0));
    // A degenerate triangle: the nearest corner.
    EXPECT_EQ(barycentric(Vec3(1.9, 0, 0), a, b, Vec3(1, 0, 0)), Vec3(0, 1, 0));
}

TEST(LocalRoughness, GrowsWithTheNoiseOfTheProcessedMesh)
{
    const Mesh a = noisy_sphere(3, 0.0, 1).mesh;
    double last = -1.0;
    for (double noise : {0.005, 0.01, 0.02, 0.04}) {
        CompareOptions o;
        o.distance = false;
        o.profile.levels = {1, 2};
        const Comparison c = compare_meshes(loaded(a), loaded(noisy_sphere(3, noise, 5).mesh), o);
        ASSERT_TRUE(c.local_roughness);
        EXPECT_GT(c.local_roughness->rms[0], last) << noise;
        last = c.local_roughness->rms[0];
    }
}

// The comparison of a pair moved, turned and scaled together: the same
// local difference (the profiles are normalised), with each normalisation.
TEST(LocalRoughness, InvariantToAJointSimilarity)
{
    const Mesh a = noisy_sphere(3, 0.02, 3).mesh, b = noisy_sphere(2, 0.01, 4).mesh;
    for (NormalizeMethod n : {NormalizeMethod::Paper, NormalizeMethod::Area, NormalizeMethod::Original}) {
        CompareOptions o;
        o.distance = false;
        o.profile.levels = {1, 3};
        o.profile.normalize = n;
        const Comparison c0 = compare_meshes(loaded(a), loaded(b), o);
        const Vec3 shift(10.0, -3.0, 2.0);
        const Comparison c1 = compare_meshes(loaded(transformed(a, 7.5, shift)), loaded(transformed(b, 7.5, shift)), o);
        for (std::size_t k = 0; k < 2; ++k)
            EXPECT_NEAR(c1.local_roughness->rms[k], c0.local_roughness->rms[k], 1e-9 * c0.local_roughness->rms[k])
                << to_string(n);
        EXPECT_NEAR(c1.local_roughness->global, c0.local_roughness->global, 1e-9 * c0.local_roughness->global);
    }
}

TEST(LocalRoughness, NeedsVertexData)
{
    const Mesh m = icosphere(1).mesh;
    const RoughnessProfile p = roughness_profile(m);  // no vertex data
    EXPECT_THROW(local_roughness_distance(m, p, m, p, ClosestPointIndex(m)), InvalidArgumentError);
}

// A comparison pools the ring levels and the global level over the processed
// mesh's vertices (its rings, against the original surface) and the radii
// over the original's (its balls, against the processed surface): the
// decimation study's choice (local_roughness.h).
TEST(LocalRoughness, ComparisonPoolsLevelsOverTheProcessedMeshAndRadiiOverTheOriginal)
{
    const Mesh a = noisy_sphere(3, 0.02, 1).mesh, b = noisy_sphere(2, 0.03, 2).mesh;
    ASSERT_NE(a.n_vertices(), b.n_vertices());
    CompareOptions o;
    o.distance = false;
    o.profile.levels = {1, 2};
    o.profile.radii = {0.3};
    o.profile.keep_vertex_data = true;
    const Comparison c = compare_meshes(loaded(a), loaded(b), o);
    ASSERT_TRUE(c.local_roughness);
    const LocalRoughnessDistance& l = *c.local_roughness;
    EXPECT_EQ(l.vertices, b.n_vertices());
    EXPECT_EQ(l.vertices_radii, a.n_vertices());
    const RoughnessProfile &pa = *c.original_profile, &pb = *c.processed_profile;
    const LocalRoughnessDistance on_processed =
        local_roughness_distance(b, pb, a, pa, ClosestPointIndex(a), o.local_trim);
    const LocalRoughnessDistance on_original =
        local_roughness_distance(a, pa, b, pb, ClosestPointIndex(b), o.local_trim);
    EXPECT_EQ(l.levels, on_processed.levels);
    EXPECT_EQ(l.rms, on_processed.rms);
    EXPECT_EQ(l.global, on_processed.global);
    EXPECT_EQ(l.radii, on_original.radii);
    EXPECT_EQ(l.rms_radii, on_original.rms_radii);
    EXPECT_NE(l.rms[0], on_original.rms[0]);  // the two directions differ
    const nlohmann::json j = comparison_json(c)["roughness_distance"]["local"];
    EXPECT_EQ(j["vertices"].get<std::size_t>(), b.n_vertices());
    EXPECT_EQ(j["vertices_radii"].get<std::size_t>(), a.n_vertices());
    // Without radii none are pooled.
    o.profile.radii.clear();
    EXPECT_EQ(compare_meshes(loaded(a), loaded(b), o).local_roughness->vertices_radii, 0u);
}

TEST(LocalRoughness, OffSwitchAndTheJsonBlock)
{
    const Mesh a = noisy_sphere(2, 0.02, 1).mesh, b = noisy_sphere(2, 0.03, 2).mesh;
    CompareOptions o;
    o.distance = false;
    o.profile.levels = {1, 2};
    Comparison c = compare_meshes(loaded(a), loaded(b), o);
    ASSERT_TRUE(c.local_roughness);
    EXPECT_TRUE(c.original_profile->D.empty());  // freed: not asked for
    const nlohmann::json j = comparison_json(c)["roughness_distance"]["local"];
    EXPECT_EQ(j["levels"], (std::vector<int>{1, 2}));
    EXPECT_EQ(j["rms"][0].get<double>(), c.local_roughness->rms[0]);
    EXPECT_EQ(j["global"].get<double>(), c.local_roughness->global);
    o.local = false;
    c = compare_meshes(loaded(a), loaded(b), o);
    EXPECT_FALSE(c.local_roughness);
    EXPECT_FALSE(comparison_json(c)["roughness_distance"].contains("local"));
}

TEST(Normalization, AreaScaleOfASphereAndItsSimilarities)
{
    const Mesh m = icosphere(4).mesh;  // inscribed: a little less area than the sphere
    const Normalization n = area_normalization(m);
    EXPECT_EQ(n.method, NormalizeMethod::Area);
    EXPECT_NEAR(n.scale, 1.0, 2e-3);
    EXPECT_LT(n.scale, 1.0);
    EXPECT_LT(n.center.norm(), 1e-12);
    const Normalization t = area_normalization(transformed(m, 3.0, Vec3(1, 2, 3)));
    EXPECT_NEAR(t.scale, 3.0 * n.scale, 1e-12);
    EXPECT_NEAR((t.center - Vec3(1, 2, 3)).norm(), 0.0, 1e-12);
    Mesh flat;
    flat.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
    flat.faces = {{0, 1, 2}};
    EXPECT_THROW(area_normalization(flat), InvalidMeshError);
}

// The original's frame: a mesh against itself scaled by 2 keeps every paper
// or area sigma (each mesh scaled alone) but halves the processed sigma in
// the original's frame (H halves).
TEST(Normalization, OriginalFrameSeesAScaleChange)
{
    const Mesh a = noisy_sphere(2, 0.02, 1).mesh;
    const Mesh b = transformed(a, 2.0, Vec3::Zero());
    CompareOptions o;
    o.distance = false;
    o.local = false;
    o.profile.levels = {1};
    for (NormalizeMethod n : {NormalizeMethod::Paper, NormalizeMethod::Area}) {
        o.profile.normalize = n;
        const Comparison c = compare_meshes(loaded(a), loaded(b), o);
        EXPECT_NEAR(c.processed_profile->levels[0].sigma, c.original_profile->levels[0].sigma,
                    1e-9 * c.original_profile->levels[0].sigma);
        EXPECT_EQ(c.processed_profile->normalization.method, n);
    }
    o.profile.normalize = NormalizeMethod::Original;
    const Comparison c = compare_meshes(loaded(a), loaded(b), o);
    EXPECT_EQ(c.original_profile->normalization.method, NormalizeMethod::Original);
    EXPECT_EQ(c.processed_profile->normalization.scale, c.original_profile->normalization.scale);
    EXPECT_NEAR(c.processed_profile->levels[0].sigma, 0.5 * c.original_profile->levels[0].sigma,
                1e-9 * c.original_profile->levels[0].sigma);
    // The original's own profile is the paper's, bit for bit.
    o.profile.normalize = NormalizeMethod::Paper;
    EXPECT_EQ(compare_meshes(loaded(a), loaded(b), o).original_profile->levels[0].sigma,
              c.original_profile->levels[0].sigma);
    // A profile alone has no original: refused.
    ProfileOptions po;
    po.normalize = NormalizeMethod::Original;
    EXPECT_THROW(roughness_profile(a, po), OptionError);
    // Corsini's angles take no scaling.
    o.measure = RoughnessMeasure::Corsini;
    o.profile.normalize = NormalizeMethod::Area;
    EXPECT_THROW(validate(o), OptionError);
}

// No data is no number: a level where a side has no vertex with a D gets
// no d_L, null in the JSON.
TEST(RoughnessDistance, NoDataIsNoNumber)
{
    const LevelDistance d = level_distance(LevelValue{3, 0.0, 1.5, true}, LevelValue{3, 0.0, 0.0, false}, 1e-4);
    EXPECT_FALSE(d.defined);
    EXPECT_FALSE(d.relative_change_defined);
    EXPECT_TRUE(d.original_data);
    EXPECT_FALSE(d.processed_data);
    const LevelDistance e = level_distance(LevelValue{3, 0.0, 1.5, true}, LevelValue{3, 0.0, 1.5, true}, 1e-4);
    EXPECT_TRUE(e.defined);
    EXPECT_EQ(e.distance, 0.0);

    // A radius far below the edge length of both meshes: no vertex has a
    // neighbourhood.
    const Mesh a = noisy_sphere(2, 0.02, 1).mesh, b = noisy_sphere(2, 0.03, 2).mesh;
    CompareOptions o;
    o.distance = false;
    o.profile.levels = {1};
    o.profile.radii = {0.001, 0.5};
    const Comparison c = compare_meshes(loaded(a), loaded(b), o);
    ASSERT_EQ(c.roughness->radii.size(), 2u);
    EXPECT_FALSE(c.roughness->radii[0].defined);
    EXPECT_TRUE(c.roughness->radii[1].defined);
    const nlohmann::json j = comparison_json(c);
    EXPECT_TRUE(j["roughness_distance"]["distance_radii"][0].is_null());
    EXPECT_TRUE(j["roughness_distance"]["distance_radii"][1].is_number());
    EXPECT_TRUE(j["original"]["sigma_radii"][0].is_null());
    EXPECT_TRUE(j["roughness_distance"]["local"]["rms_radii"][0].is_null());
    bool warned = false;
    for (const auto& w : j["original"]["warnings"]) warned = warned || w.get<std::string>().find("radius 0.001") == 0;
    EXPECT_TRUE(warned);
}

// Trimmed sigma: the share of largest |D| left out, by count; nothing moves
// without a trim.
TEST(TrimmedSigma, LeavesOutTheLargestValues)
{
    const std::vector<double> D = {1.0, -2.0, std::nan(""), 3.0, -10.0};
    std::size_t dropped = 0;
    EXPECT_EQ(trimmed_rms(D, 0.0, nullptr, &dropped), std::sqrt((1.0 + 4.0 + 9.0 + 100.0) / 4.0));
    EXPECT_EQ(dropped, 0u);
    EXPECT_EQ(trimmed_rms(D, 0.25, nullptr, &dropped), std::sqrt((1.0 + 4.0 + 9.0) / 3.0));  // ceil(0.25 x 4) = 1
    EXPECT_EQ(dropped, 1u);
    EXPECT_EQ(trimmed_rms(D, 0.26, nullptr, &dropped), std::sqrt((1.0 + 4.0) / 2.0));  // ceil(1.04) = 2
    const std::vector<double> w = {1.0, 1.0, 1.0, 3.0, 1.0};
    EXPECT_NEAR(trimmed_rms(D, 0.25, &w), std::sqrt((1.0 + 4.0 + 27.0) / 5.0), 1e-15);
    EXPECT_TRUE(std::isnan(trimmed_rms({std::nan("")}, 0.1)));

    const Mesh m = noisy_sphere(3, 0.02, 7).mesh;
    ProfileOptions o;
    o.levels = {1, 4};
    o.radii = {0.3};
    const RoughnessProfile plain = roughness_profile(m, o);
    EXPECT_EQ(plain.levels[0].trimmed, 0u);
    o.trim = 0.05;
    o.keep_vertex_data = true;
    const RoughnessProfile t = roughness_profile(m, o);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_LT(t.levels[k].sigma, plain.levels[k].sigma);
        EXPECT_EQ(t.levels[k].trimmed, std::size_t(std::ceil(0.05 * double(m.n_vertices()))));
        EXPECT_NEAR(t.levels[k].sigma, trimmed_rms(t.D[k], 0.05), 1e-13 * t.levels[k].sigma);  // as above
        EXPECT_EQ(t.levels[k].top_share, plain.levels[k].top_share);  // the diagnostic stays on all vertices
    }
    EXPECT_LT(t.global.sigma, plain.global.sigma);
    EXPECT_LT(t.radii[0].sigma, plain.radii[0].sigma);
    o.trim = 0.3;
    EXPECT_THROW(validate(o), OptionError);
    o.trim = -0.01;
    EXPECT_THROW(validate(o), OptionError);
}

TEST(LocalRoughness, TrimLeavesOutTheLargestDifferences)
{
    const Mesh a = noisy_sphere(2, 0.03, 1).mesh;
    const Mesh b = noisy_sphere(1, 0.01, 2).mesh;
    const RoughnessProfile pa = roughness_profile(a, with_data());
    const RoughnessProfile pb = roughness_profile(b, with_data());
    const ClosestPointIndex index(b);
    const LocalRoughnessDistance all = local_roughness_distance(a, pa, b, pb, index, 0.0, true);
    const LocalRoughnessDistance t = local_roughness_distance(a, pa, b, pb, index, 0.05);
    EXPECT_EQ(t.trim, 0.05);
    const std::vector<double> area = vertex_areas(apply_normalization(a, pa.normalization));
    for (std::size_t k = 0; k < 3; ++k) {
        // trimmed_rms() adds in vertex order, the comparison batch by batch
        // (folded, compensated): the same but for the rounding of the sums.
        EXPECT_NEAR(t.rms[k], trimmed_rms(all.vertex[k], 0.05, &area), 1e-13 * t.rms[k]);
        EXPECT_LT(t.rms[k], all.rms[k]);
    }
    EXPECT_THROW(local_roughness_distance(a, pa, b, pb, index, 0.3), OptionError);
    CompareOptions o;
    o.local_trim = -1.0;
    EXPECT_THROW(validate(o), OptionError);
}

// Issue 30, lever 5: without the per-vertex maps the levels are folded batch
// by batch (no levels x n means): the trimmed, area-weighted RMS of the
// stored path but for the rounding of its sums, the same counts, the same
// bits at any thread count.
TEST(LocalRoughness, FoldedLevelsAreTheStoredLevelsButForTheRoundingOfTheirSums)
{
    const Mesh a = noisy_sphere(3, 0.02, 1).mesh;
    const Mesh b = noisy_sphere(2, 0.01, 2).mesh;
    ProfileOptions o = with_data();
    o.levels = {1, 2, 5, 20};
    const RoughnessProfile pa = roughness_profile(a, o);
    const RoughnessProfile pb = roughness_profile(b, o);
    const ClosestPointIndex index(a);
    for (double trim : {0.0, 0.05, 0.2}) {
        SCOPED_TRACE(testing::Message() << "trim " << trim);
        const LocalRoughnessDistance stored = local_roughness_distance(b, pb, a, pa, index, trim, true);
        const int saved = omp_get_max_threads();
        omp_set_num_threads(1);
        const LocalRoughnessDistance one = local_roughness_distance(b, pb, a, pa, index, trim, false);
        omp_set_num_threads(2);
        const LocalRoughnessDistance folded = local_roughness_distance(b, pb, a, pa, index, trim, false);
        omp_set_num_threads(saved);
        ASSERT_EQ(folded.rms.size(), 4u);
        EXPECT_TRUE(folded.vertex.empty());
        EXPECT_EQ(folded.used, stored.used);
        for (std::size_t k = 0; k < 4; ++k) {
            EXPECT_GT(stored.rms[k], 0.0);
            EXPECT_NEAR(folded.rms[k], stored.rms[k], 1e-13 * stored.rms[k]) << "level " << folded.levels[k];
            EXPECT_EQ(one.rms[k], folded.rms[k]);
        }
    }
}

// compare_meshes() folds the local difference's ring levels in the processed
// mesh's profile's ring search (one search, not two): its levels, global
// level, counts and per-vertex maps are those of local_roughness_distance()
// on the same profiles to the last bit, and the processed profile is
// roughness_profile()'s, at 1 and 3 threads, on closed and open meshes.
TEST(LocalRoughness, ComparisonFoldsItsLevelsInTheProcessedProfilesRingSearch)
{
    struct Pair
    {
        const char* name;
        Mesh a, b;
    };
    Mesh cap_a = plane_grid(24, 20, 0.05).mesh, cap_b = plane_grid(17, 15, 0.07).mesh;
    for (Mesh* m : {&cap_a, &cap_b})
        for (auto& p : m->points) p.z() = 0.3 * std::sin(4.0 * p.x()) * std::cos(3.0 * p.y());
    const std::vector<Pair> pairs = {{"noisy spheres", noisy_sphere(3, 0.02, 1).mesh, noisy_sphere(2, 0.03, 2).mesh},
                                     {"open bumps", cap_a, cap_b}};
    for (const Pair& pair : pairs)
        for (const double trim : {0.0, 0.05})
            for (const int threads : {1, 3}) {
                SCOPED_TRACE(testing::Message() << pair.name << ", trim " << trim << ", " << threads << " threads");
                CompareOptions o;
                o.distance = false;
                o.profile.levels = {1, 2, 5, 9};
                o.profile.keep_vertex_data = true;
                o.vertex_distances = true;
                o.local_trim = trim;
                const int saved = omp_get_max_threads();
                omp_set_num_threads(threads);
                const Comparison c = compare_meshes(loaded(pair.a), loaded(pair.b), o);
                omp_set_num_threads(saved);
                ASSERT_TRUE(c.local_roughness);
                const RoughnessProfile &pa = *c.original_profile, &pb = *c.processed_profile;
                const LocalRoughnessDistance alone =
                    local_roughness_distance(pair.b, pb, pair.a, pa, ClosestPointIndex(pair.a), trim, true);
                const LocalRoughnessDistance& l = *c.local_roughness;
                EXPECT_EQ(l.levels, alone.levels);
                ASSERT_EQ(l.rms.size(), 4u);
                for (std::size_t k = 0; k < l.rms.size(); ++k) {
                    EXPECT_GT(l.rms[k], 0.0);
                    EXPECT_EQ(l.rms[k], alone.rms[k]) << "level " << l.levels[k];
                    EXPECT_EQ(l.used[k], alone.used[k]) << "level " << l.levels[k];
                    ASSERT_EQ(l.vertex.size(), 4u);
                    for (std::size_t i = 0; i < pair.b.n_vertices(); ++i)
                        ASSERT_TRUE(l.vertex[k][i] == alone.vertex[k][i] ||
                                    (std::isnan(l.vertex[k][i]) && std::isnan(alone.vertex[k][i])))
                            << "vertex " << i << ", level " << l.levels[k];
                }
                EXPECT_TRUE(l.has_global);
                EXPECT_EQ(l.global, alone.global);
                EXPECT_EQ(l.vertices, alone.vertices);
                EXPECT_EQ(l.vertices_radii, 0u);
                const RoughnessProfile own = roughness_profile(pair.b, o.profile);
                for (std::size_t k = 0; k < own.levels.size(); ++k)
                    EXPECT_EQ(pb.levels[k].sigma, own.levels[k].sigma) << "level " << own.levels[k].level;
                EXPECT_EQ(pb.global.sigma, own.global.sigma);
            }
}
