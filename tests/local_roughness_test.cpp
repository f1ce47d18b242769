#include "meshdiff/roughness/local_roughness.h"

#include <gtest/gtest.h>

#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/geometry/normalize.h"
#include "meshdiff/geometry/point_triangle.h"
#include "meshdiff/report/json.h"
#include "meshdiff/roughness/roughness_distance.h"
#include "meshdiff/studies/shapes.h"

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

// Every vertex of the original against a brute-force closest point on the
// processed surface and the interpolation written out.
TEST(LocalRoughness, EqualsABruteForcePoolOnSmallMeshes)
{
    const Mesh a = noisy_sphere(2, 0.03, 1).mesh;
    const Mesh b = noisy_sphere(1, 0.01, 2).mesh;  // coarser: a "decimation"
    const RoughnessProfile pa = roughness_profile(a, with_data());
    const RoughnessProfile pb = roughness_profile(b, with_data());
    const LocalRoughnessDistance d = local_roughness_distance(a, pa, b, pb, ClosestPointIndex(b), 0.0, true);
    ASSERT_EQ(d.levels.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        double total = 0.0;
        for (std::size_t i = 0; i < a.n_vertices(); ++i) {
            const ClosestPoint cp = closest_point_brute_force(b, a.points[i]);
            const Face& f = b.faces[cp.face];
            const Vec3 w = barycentric(cp.point, b.points[std::size_t(f[0])], b.points[std::size_t(f[1])],
                                       b.points[std::size_t(f[2])]);
            EXPECT_NEAR(w.sum(), 1.0, 1e-12);
            double at = 0.0;
            for (int c = 0; c < 3; ++c) at += w[c] * pb.D[k][std::size_t(f[std::size_t(c)])];
            const double diff = pa.D[k][i] - at;
            EXPECT_NEAR(d.vertex[k][i], diff, 1e-9 * (1.0 + std::abs(diff))) << i;
            total += diff * diff;
        }
        EXPECT_NEAR(d.rms[k], std::sqrt(total / double(a.n_vertices())), 1e-9 * d.rms[k]);
        EXPECT_GT(d.rms[k], 0.0);
    }
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
        EXPECT_EQ(t.levels[k].sigma, trimmed_rms(t.D[k], 0.05));
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
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(t.rms[k], trimmed_rms(all.vertex[k], 0.05));
        EXPECT_LT(t.rms[k], all.rms[k]);
    }
    EXPECT_THROW(local_roughness_distance(a, pa, b, pb, index, 0.3), OptionError);
    CompareOptions o;
    o.local_trim = -1.0;
    EXPECT_THROW(validate(o), OptionError);
}
