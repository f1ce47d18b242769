#include "meshdiff/report/vertex_maps.h"

#include <gtest/gtest.h>

#include "support/data.h"

#include "meshdiff/distance/signed_distance.h"
#include "meshdiff/error.h"
#include "meshdiff/geometry/normalize.h"
#include "meshdiff/geometry/point_triangle.h"
#include "meshdiff/geometry/vertex_areas.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

using namespace meshdiff;
using meshdiff::test::data;
namespace fs = std::filesystem;

namespace {

const Rgb kRed = {255, 0, 0};
const Rgb kBlue = {0, 0, 255};

// Distances of the stretched sphere (x scaled by 1.5, same connectivity) to the
// unit icosphere: its vertices with x = 0 lie on the sphere (distance 0).
const LoadedMesh& sphere()
{
    static const LoadedMesh m = read_mesh(data("sphere_ico_2562.ply"));
    return m;
}
const LoadedMesh& ellipsoid()
{
    static const LoadedMesh m = read_mesh(data("ellipsoid_150_100_100.ply"));
    return m;
}
const Comparison& distance_comparison()
{
    static const Comparison c = [] {
        CompareOptions o;
        o.roughness = false;
        o.sampling.samples = 20000;
        o.vertex_distances = true;
        return compare_meshes(sphere(), ellipsoid(), o);
    }();
    return c;
}

ProfileOptions kept_profile_options()
{
    ProfileOptions o;
    o.levels = {1, 3};
    o.keep_vertex_data = true;
    return o;
}

bool same_or_both_nan(double a, double b)
{
    return a == b || (std::isnan(a) && std::isnan(b));
}

}  // namespace

TEST(DistanceMap, DistanceIsTheBruteForceDistanceOfEveryProcessedVertex)
{
    const VertexMap m = distance_map(distance_comparison());
    ASSERT_EQ(m.scalars.size(), 3u);
    EXPECT_EQ(m.scalars[0].name, "distance");
    EXPECT_EQ(m.scalars[1].name, "signed_distance");
    // MeshLab's per-vertex quality: the distance again.
    EXPECT_EQ(m.scalars[2].name, "quality");
    EXPECT_EQ(m.scalars[2].values, m.scalars[0].values);
    const auto& d = m.scalars[0].values;
    const auto& s = m.scalars[1].values;
    ASSERT_EQ(d.size(), ellipsoid().mesh.n_vertices());
    ASSERT_EQ(s.size(), d.size());
    int outside = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        const Vec3& p = ellipsoid().mesh.points[i];
        const double want = closest_point_brute_force(sphere().mesh, p).distance;
        EXPECT_NEAR(d[i], want, 1e-15 * want) << i;
        // The stretched sphere (x scaled by 1.5) is outside the unit sphere
        // wherever it has moved (|x| > 0): the signed distance is +distance.
        EXPECT_EQ(s[i], d[i]) << i;
        outside += s[i] > 0.0;
    }
    EXPECT_GT(outside, 2000);
    EXPECT_EQ(m.comments.back().rfind("signed_distance: positive outside", 0), 0u) << m.comments.back();
}

TEST(DistanceMap, OriginalSideIsTheBruteForceDistanceOfEveryOriginalVertex)
{
    const Comparison& c = distance_comparison();
    const VertexMap m = distance_map(c, MapSide::Original);
    ASSERT_EQ(m.scalars.size(), 3u);
    EXPECT_EQ(m.scalars[2].name, "quality");
    EXPECT_EQ(m.scalars[2].values, m.scalars[0].values);
    const auto& d = m.scalars[0].values;
    ASSERT_EQ(d.size(), sphere().mesh.n_vertices());
    int n_inside = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        const double want = closest_point_brute_force(ellipsoid().mesh, sphere().mesh.points[i]).distance;
        EXPECT_NEAR(d[i], want, 1e-15 * want) << i;
        // Signed: inside (-) or outside (+) the stretched sphere by the winding number (brute force).
        if (d[i] > 1e-9) {
            const bool inside = winding_number(ellipsoid().mesh, sphere().mesh.points[i]) > 0.5;
            EXPECT_EQ(m.scalars[1].values[i], inside ? -d[i] : d[i]) << i;
            n_inside += inside;
        } else {
            EXPECT_EQ(std::abs(m.scalars[1].values[i]), d[i]);
        }
    }
    EXPECT_GT(n_inside, 2000);
    // The comments name this side; the Hausdorff distance from the original
    // is attained at a point of it (the forward location).
    EXPECT_NE(m.comments[0].find("per-vertex distance of " + c.original.input.path), std::string::npos);
    ASSERT_GE(m.comments.size(), 4u);
    EXPECT_NE(m.comments[2].find("hausdorff original->processed"), std::string::npos) << m.comments[2];
    // The processed side is distance_map(c), unchanged.
    EXPECT_EQ(distance_map(c, MapSide::Processed).comments, distance_map(c).comments);
}

TEST(DistanceMap, TheProcessedMapCarriesTheLocalRoughnessDifferencePerLevel)
{
    // issue 29: the local roughness difference as a per-vertex map on the
    // processed mesh (PREFIX_processed.ply of --distance-maps): local_L = F(i)
    // - mean of F over its N_L(i), F = H' - H(cp) (local_roughness.h), whose
    // RMS weighted by the processed mesh's vertex areas (untrimmed here) is
    // roughness_distance.local.
    CompareOptions o;
    o.profile.levels = {1, 3};
    o.sampling.samples = 5000;
    o.vertex_distances = true;
    o.local_trim = 0.0;
    const Comparison c = compare_meshes(sphere(), ellipsoid(), o);
    ASSERT_TRUE(c.local_roughness);
    const VertexMap m = distance_map(c, MapSide::Processed);
    ASSERT_EQ(m.scalars.size(), 5u);
    for (std::size_t k = 0; k < 2; ++k) {
        const VertexScalar& s = m.scalars[3 + k];
        EXPECT_EQ(s.name, k == 0 ? "local_1" : "local_3");
        ASSERT_EQ(s.values.size(), ellipsoid().mesh.n_vertices());
        const std::vector<double> area =
            vertex_areas(apply_normalization(ellipsoid().mesh, c.processed_profile->normalization));
        double sum = 0.0, weight = 0.0;
        std::size_t n = 0;
        for (std::size_t i = 0; i < s.values.size(); ++i)
            if (!std::isnan(s.values[i])) {
                sum += area[i] * s.values[i] * s.values[i];
                weight += area[i];
                ++n;
            }
        EXPECT_EQ(n, c.local_roughness->used[k]);
        EXPECT_NEAR(std::sqrt(sum / weight), c.local_roughness->rms[k], 1e-12 * c.local_roughness->rms[k]);
    }
    EXPECT_NE(m.comments.back().find("local_L (L = 1, 3)"), std::string::npos) << m.comments.back();
    // The original's map has no such property (the ring levels pool over the processed mesh's vertices).
    EXPECT_EQ(distance_map(c, MapSide::Original).scalars.size(), 3u);
    // Without vertex data kept, none either.
    o.vertex_distances = false;
    o.local = true;
    EXPECT_TRUE(compare_meshes(sphere(), ellipsoid(), o).local_roughness->vertex.empty());
}

TEST(DistanceMap, BothSidesShareOneRangeWhenAsked)
{
    const Comparison& c = distance_comparison();
    const auto range = distance_map_range(c);
    double hi = 0.0;
    for (double x : c.original_vertex_distance) hi = std::max(hi, x);
    for (double x : c.processed_vertex_distance) hi = std::max(hi, x);
    EXPECT_EQ(range.first, 0.0);
    EXPECT_EQ(range.second, hi);
    const VertexMap a = distance_map(c, MapSide::Original, range);
    const VertexMap b = distance_map(c, MapSide::Processed, range);
    EXPECT_EQ(a.comments[1], b.comments[1]);
    // One colour means one distance: both ramps run over [0, hi].
    EXPECT_EQ(a.colors, sequential_colors(a.scalars[0].values, 0.0, hi));
    EXPECT_EQ(b.colors, sequential_colors(b.scalars[0].values, 0.0, hi));
    EXPECT_NE(a.colors, distance_map(c, MapSide::Original).colors);  // its own maximum is below hi
    CompareOptions o;
    o.roughness = false;
    EXPECT_THROW(distance_map_range(compare_meshes(sphere(), ellipsoid(), o)), InvalidArgumentError);
}

TEST(DistanceMap, DefaultRangeIsZeroToTheMaximumFromBlueToRed)
{
    const VertexMap m = distance_map(distance_comparison());
    const auto& d = m.scalars[0].values;
    ASSERT_EQ(m.colors.size(), d.size());
    const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
    ASSERT_EQ(*lo, 0.0);  // an x = 0 vertex of the stretched sphere
    EXPECT_NEAR(*hi, 0.5, 0.01);
    EXPECT_EQ(m.colors[std::size_t(hi - d.begin())], kRed);
    EXPECT_EQ(m.colors[std::size_t(lo - d.begin())], kBlue);
    for (std::size_t i = 0; i < d.size(); ++i)
        if (d[i] == 0.0) {
            EXPECT_EQ(m.colors[i], kBlue) << i;
        }
    EXPECT_EQ(m.colors, sequential_colors(d, 0.0, *hi));
    // Two comments, two more that mark where the certified Hausdorff
    // distances are attained, and the sign convention.
    ASSERT_EQ(m.comments.size(), 5u);
    EXPECT_EQ(m.comments[2].rfind("hausdorff processed->original in [", 0), 0u) << m.comments[2];
    EXPECT_EQ(m.comments[3].rfind("hausdorff original->processed in [", 0), 0u) << m.comments[3];
    EXPECT_NE(m.comments[0].find(ellipsoid().input.path), std::string::npos) << m.comments[0];
    EXPECT_NE(m.comments[0].find(sphere().input.path), std::string::npos) << m.comments[0];
}

TEST(DistanceMap, AGivenRangeColoursAndIsStatedInAComment)
{
    const VertexMap m = distance_map(distance_comparison(), std::make_pair(0.0, 0.25));
    const auto& d = m.scalars[0].values;
    EXPECT_EQ(m.colors, sequential_colors(d, 0.0, 0.25));
    for (std::size_t i = 0; i < d.size(); ++i)
        if (d[i] >= 0.25) {
            EXPECT_EQ(m.colors[i], kRed) << i;  // clamped above MAX
        }
    EXPECT_NE(m.comments[1].find("[0, 0.25]"), std::string::npos) << m.comments[1];
}

TEST(DistanceMap, ThrowsWithoutVertexDistancesOrForMinAboveMax)
{
    CompareOptions o;
    o.roughness = false;
    o.sampling.samples = 5000;
    EXPECT_THROW(distance_map(compare_meshes(sphere(), ellipsoid(), o)), InvalidArgumentError);
    EXPECT_THROW(distance_map(distance_comparison(), std::make_pair(0.2, 0.1)), InvalidArgumentError);
    EXPECT_THROW(distance_map(distance_comparison(), std::make_pair(0.0, HUGE_VAL)), InvalidArgumentError);
}

// Issue 33 (4): a mesh compared with itself has the range [0, 0]; it is a
// valid range, every vertex coloured as its low end.
TEST(DistanceMap, ADegenerateRangeIsValid)
{
    CompareOptions o;
    o.roughness = false;
    o.sampling.samples = 5000;
    o.vertex_distances = true;
    const Comparison c = compare_meshes(sphere(), sphere(), o);
    const auto range = distance_map_range(c);
    EXPECT_EQ(range, std::make_pair(0.0, 0.0));
    const VertexMap m = distance_map(c, MapSide::Processed, range);
    ASSERT_FALSE(m.colors.empty());
    for (const auto& rgb : m.colors) EXPECT_EQ(rgb, m.colors.front());
    EXPECT_NO_THROW(distance_map(distance_comparison(), std::make_pair(0.1, 0.1)));
}

TEST(DistanceMap, SameVertexDistancesWithoutTheSurfaceDistance)
{
    CompareOptions o;
    o.distance = false;
    o.profile.levels = {1};
    o.profile.global = false;
    o.vertex_distances = true;
    const Comparison c = compare_meshes(sphere(), ellipsoid(), o);
    EXPECT_FALSE(c.distance.has_value());
    EXPECT_EQ(c.processed_vertex_distance, distance_comparison().processed_vertex_distance);
    EXPECT_EQ(c.original_vertex_distance, distance_comparison().original_vertex_distance);
    EXPECT_EQ(distance_map(c).scalars[0].values, distance_map(distance_comparison()).scalars[0].values);
    EXPECT_EQ(c.processed_vertex_signed_distance, distance_comparison().processed_vertex_signed_distance);
    EXPECT_EQ(c.original_vertex_signed_distance, distance_comparison().original_vertex_signed_distance);
    EXPECT_EQ(distance_map(c).scalars[1].values, distance_map(distance_comparison()).scalars[1].values);
}

TEST(DistanceMap, NoSignedDistanceAgainstAnOpenMesh)
{
    CompareOptions o;
    o.roughness = false;
    o.sampling.samples = 5000;
    o.vertex_distances = true;
    const Comparison c = compare_meshes(sphere(), read_mesh(data("hemisphere.ply")), o);
    const VertexMap processed = distance_map(c);                    // distances to the closed sphere: signed
    ASSERT_EQ(processed.scalars.size(), 3u);                        // distance, signed_distance, quality
    const VertexMap original = distance_map(c, MapSide::Original);  // to the open hemisphere: none
    ASSERT_EQ(original.scalars.size(), 2u);                         // distance, quality
    EXPECT_EQ(original.scalars[1].name, "quality");
    EXPECT_EQ(original.comments.back().rfind("no signed_distance", 0), 0u) << original.comments.back();
}

TEST(ProfileMap, PropertiesAreHThenDPerLevelThenGlobalThenWorst)
{
    const Mesh& mesh = ellipsoid().mesh;
    const RoughnessProfile p = roughness_profile(mesh, kept_profile_options());
    const VertexMap m = profile_map(p, "ellipsoid.ply");
    std::vector<std::string> names;
    for (const auto& s : m.scalars) {
        names.push_back(s.name);
        EXPECT_EQ(s.values.size(), mesh.n_vertices()) << s.name;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"H", "D_1", "D_3", "D_global", "worst"}));
    EXPECT_EQ(m.scalars[0].values, p.H);
    for (std::size_t k = 0; k < 2; ++k)
        for (std::size_t i = 0; i < mesh.n_vertices(); ++i)
            EXPECT_TRUE(same_or_both_nan(m.scalars[1 + k].values[i], p.D[k][i]));
    EXPECT_EQ(m.colors.size(), mesh.n_vertices());
    EXPECT_NE(m.comments[0].find("ellipsoid.ply"), std::string::npos) << m.comments[0];
}

TEST(ProfileMap, WorstIsOneExactlyAtTheWorstVerticesOfSomeLevel)
{
    const RoughnessProfile p = roughness_profile(read_mesh(data("bunny_res3.ply")).mesh, kept_profile_options());
    std::set<std::uint32_t> union_of_worst;
    for (const auto& l : p.levels) union_of_worst.insert(l.worst_vertices.begin(), l.worst_vertices.end());
    union_of_worst.insert(p.global.worst_vertices.begin(), p.global.worst_vertices.end());
    ASSERT_GT(union_of_worst.size(), 10u);  // the levels disagree on some
    const VertexMap m = profile_map(p, "bunny");
    ASSERT_EQ(m.scalars.back().name, "worst");
    const auto& worst = m.scalars.back().values;
    for (std::size_t i = 0; i < worst.size(); ++i)
        EXPECT_EQ(worst[i], union_of_worst.count(std::uint32_t(i)) ? 1.0 : 0.0) << i;
}

TEST(ProfileMap, ThrowsWithoutVertexData)
{
    ProfileOptions o = kept_profile_options();
    o.keep_vertex_data = false;
    EXPECT_THROW(profile_map(roughness_profile(ellipsoid().mesh, o), "x"), InvalidArgumentError);
}

TEST(WritePly, AMapComesBackAsVertexScalars)
{
    const RoughnessProfile p = roughness_profile(ellipsoid().mesh, kept_profile_options());
    const Mesh normalised = apply_normalization(ellipsoid().mesh, p.normalization);
    const VertexMap m = profile_map(p, "ellipsoid");
    const fs::path path = fs::temp_directory_path() / ("meshdiff_vertex_maps_" + std::to_string(::getpid()) + ".ply");
    write_ply(path, normalised, m);
    const LoadedMesh back = read_mesh(path);
    fs::remove(path);
    EXPECT_EQ(back.mesh.points, normalised.points);
    for (const auto& s : m.scalars) {
        const auto& got = vertex_scalar(back, s.name).values;
        ASSERT_EQ(got.size(), s.values.size()) << s.name;
        for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(same_or_both_nan(got[i], s.values[i])) << s.name;
    }
    for (int c = 0; c < 3; ++c) {
        const auto& channel = vertex_scalar(back, c == 0 ? "red" : c == 1 ? "green" : "blue").values;
        for (std::size_t i = 0; i < channel.size(); ++i) EXPECT_EQ(channel[i], double(m.colors[i][c]));
    }
}

TEST(DistanceColorRange, IsThePercentileOfBothMeshesVertexDistances)
{
    const Comparison& c = distance_comparison();
    std::vector<double> all = c.original_vertex_distance;
    all.insert(all.end(), c.processed_vertex_distance.begin(), c.processed_vertex_distance.end());
    std::sort(all.begin(), all.end());
    EXPECT_EQ(distance_color_range(c, 100.0), distance_map_range(c));
    EXPECT_EQ(distance_color_range(c, 100.0).second, all.back());
    const auto p90 = distance_color_range(c, 90.0);
    EXPECT_EQ(p90.first, 0.0);
    EXPECT_EQ(p90.second, all[std::size_t(std::llround(0.9 * double(all.size() - 1)))]);
    EXPECT_LT(p90.second, all.back());
    EXPECT_THROW(distance_color_range(c, 0.0), InvalidArgumentError);
    EXPECT_THROW(distance_color_range(c, 100.5), InvalidArgumentError);
}
