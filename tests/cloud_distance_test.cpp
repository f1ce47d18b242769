// Point clouds as inputs of compare (issue 11): the k-d tree against brute
// force, cloud-to-mesh distances against closed forms, the reading of a
// faceless file, and the comparison and its reports.
#include "meshdiff/distance/cloud_distance.h"

#include <gtest/gtest.h>

#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

using namespace meshdiff;
namespace fs = std::filesystem;

namespace {

std::string data(const std::string& name)
{
    return std::string(MESHDIFF_TEST_DATA_DIR) + "/" + name;
}

fs::path write_text(const std::string& name, const std::string& text)
{
    const fs::path dir = fs::temp_directory_path() / "meshdiff_cloud_test";
    fs::create_directories(dir);
    const fs::path p = dir / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
}

template <class E>
std::string error_of(const fs::path& p, bool cloud)
{
    try {
        if (cloud)
            read_mesh_or_cloud(p);
        else
            read_mesh(p);
    } catch (const E& e) {
        return e.what();
    }
    return "(no error)";
}

std::vector<Vec3> random_points(std::size_t n, std::uint64_t seed, double scale = 1.0)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-scale, scale);
    std::vector<Vec3> p(n);
    for (auto& x : p) x = Vec3(u(rng), u(rng), u(rng));
    return p;
}

double brute_nearest(const Vec3& q, const std::vector<Vec3>& cloud)
{
    double best = std::numeric_limits<double>::infinity();
    for (const Vec3& c : cloud) best = std::min(best, (q - c).squaredNorm());
    return std::sqrt(best);
}

// The unit square [0, 1]^2 in the plane z = 0, two triangles.
Mesh unit_square()
{
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    m.faces = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

// Distance of p to the unit square: the distance in the plane to the square,
// combined with the height.
double square_distance(const Vec3& p)
{
    const double dx = std::max({0.0, -p.x(), p.x() - 1.0});
    const double dy = std::max({0.0, -p.y(), p.y() - 1.0});
    return std::sqrt(dx * dx + dy * dy + p.z() * p.z());
}

LoadedMesh loaded(Mesh m, const std::string& path)
{
    LoadedMesh l;
    l.mesh = std::move(m);
    l.input.path = path;
    l.input.file_vertices = l.mesh.n_vertices();
    l.input.file_faces = l.mesh.n_faces();
    l.input.point_cloud = l.mesh.faces.empty();
    return l;
}

}  // namespace

TEST(PointCloudIndex, NearestDistancesEqualBruteForce)
{
    const auto cloud = random_points(3000, 1);
    const auto queries = random_points(700, 2, 1.5);
    const PointCloudIndex index(cloud);
    EXPECT_EQ(index.size(), cloud.size());
    const std::vector<double> d = index.distances(queries);
    ASSERT_EQ(d.size(), queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i) {
        EXPECT_DOUBLE_EQ(d[i], brute_nearest(queries[i], cloud)) << i;
        const auto n = index.nearest(queries[i]);
        EXPECT_EQ(n.distance, d[i]);
        EXPECT_EQ(n.distance, (queries[i] - cloud[n.index]).norm());
    }
    // A point of the cloud is at distance 0 from it.
    for (std::size_t i = 0; i < cloud.size(); i += 97) EXPECT_EQ(index.nearest(cloud[i]).distance, 0.0);
}

TEST(PointCloudIndex, RefusesEmptyAndNonFinite)
{
    EXPECT_THROW(PointCloudIndex(std::vector<Vec3>{}), InvalidMeshError);
    EXPECT_THROW(PointCloudIndex({Vec3(0, 0, 0), Vec3(std::nan(""), 0, 0)}), InvalidMeshError);
}

TEST(DistanceKind, EachCombination)
{
    EXPECT_EQ(distance_kind(false, false), DistanceKind::SurfaceToSurface);
    EXPECT_EQ(distance_kind(true, false), DistanceKind::PointToSurface);
    EXPECT_EQ(distance_kind(false, true), DistanceKind::SurfaceToPoint);
    EXPECT_EQ(distance_kind(true, true), DistanceKind::PointToPoint);
    EXPECT_EQ(to_string(DistanceKind::PointToSurface), "point-to-surface");
    EXPECT_EQ(to_string(DistanceKind::SurfaceToPoint), "surface-to-point");
    EXPECT_EQ(to_string(DistanceKind::PointToPoint), "point-to-point");
}

TEST(CloudSurfaceDistance, CloudToPlaneMatchesClosedForm)
{
    Mesh cloud;
    // Above, below, in and beside the square: distances 0.5, 0.25, 0, 1, 0.5 (corner: sqrt(0.5^2 + 0^2 + 0)).
    cloud.points = {Vec3(0.25, 0.25, 0.5), Vec3(0.75, 0.5, -0.25), Vec3(0.5, 0.5, 0.0), Vec3(2.0, 0.5, 0.0),
                    Vec3(1.3, 1.4, 0.0)};
    DistanceOptions o;
    o.vertex_distances = true;
    o.hausdorff = HausdorffOptions{};
    o.keep_samples = true;
    const SurfaceDistance d = cloud_surface_distance(cloud, unit_square(), o);
    const SampledDirection &fwd = d.forward_samples, &bwd = d.backward_samples;
    const double want[] = {0.5, 0.25, 0.0, 1.0, 0.5};
    ASSERT_EQ(fwd.distances.size(), 5u);
    double sum = 0.0, sum2 = 0.0;
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_NEAR(fwd.distances[i], want[i], 1e-15) << i;
        EXPECT_EQ(fwd.samples.kind[i], SampleKind::OnPoint);
        EXPECT_EQ(fwd.samples.element[i], i);
        sum += want[i];
        sum2 += want[i] * want[i];
    }
    EXPECT_EQ(d.forward.n_point, 5u);
    EXPECT_EQ(d.forward.n_samples(), 5u);
    EXPECT_EQ(d.forward.n_vertex + d.forward.n_edge + d.forward.n_face, 0u);
    EXPECT_DOUBLE_EQ(d.forward.max, 1.0);
    EXPECT_EQ(d.forward.min, 0.0);
    EXPECT_NEAR(d.forward.mean, sum / 5, 1e-15);
    // The summary weights every point equally: the plain mean.
    ASSERT_TRUE(d.forward.area_weighted);
    EXPECT_NEAR(d.forward.area_weighted->mean, sum / 5, 1e-15);
    EXPECT_NEAR(d.forward.area_weighted->mean_square, sum2 / 5, 1e-15);
    // Exact over the points: a certified interval [max, max] at point 3.
    ASSERT_TRUE(d.forward_hausdorff);
    EXPECT_TRUE(d.forward_hausdorff->certified);
    EXPECT_EQ(d.forward_hausdorff->lower, d.forward.max);
    EXPECT_EQ(d.forward_hausdorff->upper, d.forward.max);
    EXPECT_EQ(d.forward_hausdorff->location.face, 3u);
    EXPECT_NEAR((d.forward_hausdorff->location.closest_point - Vec3(1.0, 0.5, 0.0)).norm(), 0.0, 1e-15);
    // The mesh sampled against the cloud: sampled only; each sample's
    // distance is the brute-force nearest-point distance.
    EXPECT_FALSE(d.backward_hausdorff);
    ASSERT_GT(bwd.distances.size(), 0u);
    for (std::size_t i = 0; i < bwd.distances.size(); ++i)
        EXPECT_DOUBLE_EQ(bwd.distances[i], brute_nearest(bwd.samples.points[i], cloud.points)) << i;
    EXPECT_EQ(d.backward.n_point, 0u);
    EXPECT_GT(d.backward.n_face, 0u);  // the default budget counts the 5 points: 50 samples
    // Per-vertex (point) distances: the points' own distances, and the square's corners to the cloud.
    ASSERT_EQ(d.original_vertex_distance.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(d.original_vertex_distance[i], fwd.distances[i]);
    ASSERT_EQ(d.processed_vertex_distance.size(), 4u);
    const Mesh sq = unit_square();
    for (std::size_t v = 0; v < 4; ++v)
        EXPECT_DOUBLE_EQ(d.processed_vertex_distance[v], brute_nearest(sq.points[v], cloud.points));
}

TEST(CloudSurfaceDistance, RandomCloudToPlaneEveryPoint)
{
    const auto pts = random_points(2000, 7, 2.0);
    Mesh cloud;
    cloud.points = pts;
    // The deprecated positional overload (0.2): only the forward samples kept.
    SampledDirection fwd;
    const SurfaceDistance d = cloud_surface_distance(cloud, unit_square(), {}, false, std::nullopt, {}, &fwd);
    EXPECT_TRUE(d.forward_samples.distances.empty());
    EXPECT_TRUE(d.backward_samples.distances.empty());
    double max = 0.0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        EXPECT_NEAR(fwd.distances[i], square_distance(pts[i]), 1e-14) << i;
        max = std::max(max, square_distance(pts[i]));
    }
    EXPECT_NEAR(d.forward.max, max, 1e-14);
    EXPECT_FALSE(d.forward_hausdorff);  // not asked for
}

TEST(CloudSurfaceDistance, CloudToCloudEqualsBruteForceBothWays)
{
    Mesh a, b;
    a.points = random_points(1500, 11);
    b.points = random_points(900, 12, 1.2);
    SummaryOptions summary;
    summary.fscore_thresholds = {0.02, 0.05};
    DistanceOptions o;
    o.hausdorff = HausdorffOptions{};
    o.summary = summary;
    o.keep_samples = true;
    const SurfaceDistance d = cloud_surface_distance(a, b, o);
    const SampledDirection &fwd = d.forward_samples, &bwd = d.backward_samples;
    double fmax = 0.0, bmax = 0.0, fsum = 0.0, bsum = 0.0;
    std::vector<std::size_t> fbelow(2, 0), bbelow(2, 0);
    const double diag = bounding_box(a).diagonal();
    for (std::size_t i = 0; i < a.points.size(); ++i) {
        const double x = brute_nearest(a.points[i], b.points);
        EXPECT_DOUBLE_EQ(fwd.distances[i], x) << i;
        fmax = std::max(fmax, x);
        fsum += x;
        for (int k = 0; k < 2; ++k) fbelow[k] += x < summary.fscore_thresholds[k] * diag;
    }
    for (std::size_t i = 0; i < b.points.size(); ++i) {
        const double x = brute_nearest(b.points[i], a.points);
        EXPECT_DOUBLE_EQ(bwd.distances[i], x) << i;
        bmax = std::max(bmax, x);
        bsum += x;
        for (int k = 0; k < 2; ++k) bbelow[k] += x < summary.fscore_thresholds[k] * diag;
    }
    EXPECT_DOUBLE_EQ(d.forward.max, fmax);
    EXPECT_DOUBLE_EQ(d.backward.max, bmax);
    EXPECT_NEAR(d.forward.mean, fsum / 1500, 1e-12);
    EXPECT_NEAR(d.backward.mean, bsum / 900, 1e-12);
    EXPECT_EQ(d.hausdorff, std::max(d.forward.max, d.backward.max));
    EXPECT_EQ(d.diagonal, diag);
    ASSERT_TRUE(d.forward_hausdorff && d.backward_hausdorff);
    EXPECT_TRUE(d.forward_hausdorff->certified && d.backward_hausdorff->certified);
    EXPECT_EQ(d.backward_hausdorff->upper, d.backward.max);
    // Chamfer from the plain means; F-score from the point shares.
    ASSERT_TRUE(d.summary);
    EXPECT_NEAR(d.summary->chamfer_l1, fsum / 1500 + bsum / 900, 1e-12);
    ASSERT_EQ(d.fscore.size(), 2u);
    for (int k = 0; k < 2; ++k) {
        EXPECT_DOUBLE_EQ(d.fscore[k].recall, double(fbelow[k]) / 1500);
        EXPECT_DOUBLE_EQ(d.fscore[k].precision, double(bbelow[k]) / 900);
    }
    EXPECT_GT(d.fscore[1].fscore, 0.0);  // the thresholds are not vacuous
    EXPECT_LT(d.fscore[0].fscore, 1.0);
}

TEST(CloudSurfaceDistance, VerticesOfAMeshAsACloudAgainstTheMeshGiveZero)
{
    const LoadedMesh sphere = read_mesh(data("sphere_ico_2562.ply"));
    Mesh cloud;
    cloud.points = sphere.mesh.points;
    DistanceOptions o;
    o.hausdorff = HausdorffOptions{};
    const SurfaceDistance d = cloud_surface_distance(cloud, sphere.mesh, o);
    EXPECT_EQ(d.forward.max, 0.0);
    EXPECT_EQ(d.forward.n_point, cloud.points.size());
    ASSERT_TRUE(d.forward_hausdorff);
    EXPECT_EQ(d.forward_hausdorff->upper, 0.0);
    // Backward: the sphere's samples to its own vertices; its vertex samples are at 0.
    EXPECT_EQ(d.backward.min, 0.0);
    EXPECT_GT(d.backward.max, 0.0);
    // And the same pair the other way round.
    const SurfaceDistance r = cloud_surface_distance(sphere.mesh, cloud);
    EXPECT_EQ(r.backward.max, 0.0);
    EXPECT_EQ(r.backward.n_point, cloud.points.size());
}

TEST(CloudSurfaceDistance, TwoMeshesAreTheSurfaceDistance)
{
    const LoadedMesh sphere = read_mesh(data("sphere_ico_2562.ply"));
    DistanceOptions o;
    o.sampling.samples = 5000;
    const SurfaceDistance x = cloud_surface_distance(sphere.mesh, sphere.mesh, o);
    const SurfaceDistance y = surface_distance(sphere.mesh, sphere.mesh, o);
    EXPECT_EQ(x.forward.mean, y.forward.mean);
    EXPECT_EQ(x.backward.max, y.backward.max);
}

TEST(ReadMeshOrCloud, FacelessFilesAreCloudsOnlyThere)
{
    const auto ply = write_text("cloud.ply",
                                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nproperty float q\nend_header\n0 0 0 1\n1 0 0 2\n0 1 0.5 3\n");
    const LoadedMesh c = read_mesh_or_cloud(ply);
    EXPECT_TRUE(c.input.point_cloud);
    EXPECT_TRUE(is_point_cloud(c));
    ASSERT_EQ(c.mesh.n_vertices(), 3u);
    EXPECT_EQ(c.mesh.points[2], Vec3(0, 1, 0.5));
    ASSERT_EQ(c.vertex_scalars.size(), 1u);
    EXPECT_EQ(c.vertex_scalars[0].values[2], 3.0);
    const std::string e = error_of<InvalidMeshError>(ply, false);
    EXPECT_NE(e.find("cloud.ply"), std::string::npos) << e;
    EXPECT_NE(e.find("no faces: a point cloud"), std::string::npos) << e;
    EXPECT_NE(e.find("only compare accepts point clouds"), std::string::npos) << e;

    const auto off = write_text("cloud.off", "OFF\n2 0 0\n0 0 0\n1 2 3\n");
    EXPECT_EQ(read_mesh_or_cloud(off).mesh.n_vertices(), 2u);
    const auto obj = write_text("cloud.obj", "v 0 0 0\nv 1 2 3\nv 4 5 6\n");
    EXPECT_EQ(read_mesh_or_cloud(obj).mesh.n_vertices(), 3u);
    // A mesh stays a mesh: its unused vertices are dropped as by read_mesh().
    const auto mesh = write_text("mesh.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n5 5 5\n3 0 1 2\n");
    const LoadedMesh m = read_mesh_or_cloud(mesh);
    EXPECT_FALSE(m.input.point_cloud);
    EXPECT_EQ(m.mesh.n_vertices(), 3u);
    EXPECT_EQ(m.input.unreferenced_vertices, 1u);

    const auto nan = write_text("nan_cloud.ply",
                                "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                                "property float z\nend_header\n0 0 0\n1 nan 0\n");
    const std::string n = error_of<InvalidMeshError>(nan, true);
    EXPECT_NE(n.find("non-finite"), std::string::npos) << n;
    EXPECT_NE(n.find("nan_cloud.ply"), std::string::npos) << n;
    const auto empty = write_text("empty_cloud.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                  "property float z\nend_header\n");
    const std::string z = error_of<Error>(empty, true);
    EXPECT_NE(z.find("empty_cloud.ply"), std::string::npos) << z;
    EXPECT_NE(z.find("no vertices"), std::string::npos) << z;
}

TEST(CompareWithCloud, SkipsRoughnessAndReportsTheKinds)
{
    Mesh cloud;
    cloud.points = {Vec3(0.25, 0.25, 0.5), Vec3(0.75, 0.5, -0.25), Vec3(2.0, 0.5, 0.0)};
    const LoadedMesh a = loaded(unit_square(), "square.off");
    const LoadedMesh b = loaded(cloud, "cloud.ply");
    CompareOptions o;
    o.vertex_distances = true;
    const Comparison c = compare_meshes(a, b, o);
    EXPECT_FALSE(c.roughness);
    EXPECT_FALSE(c.original_profile);
    EXPECT_NE(c.roughness_unavailable.find("processed input is a point cloud"), std::string::npos);
    ASSERT_TRUE(c.distance);
    EXPECT_EQ(c.distance->forward_kind, DistanceKind::SurfaceToPoint);
    EXPECT_EQ(c.distance->backward_kind, DistanceKind::PointToSurface);
    EXPECT_DOUBLE_EQ(c.distance->backward.max, 1.0);
    EXPECT_DOUBLE_EQ(c.distance->diagonal, std::sqrt(2.0));  // the original's box
    EXPECT_FALSE(c.same_connectivity);
    EXPECT_NE(c.same_connectivity_unavailable.find("point cloud"), std::string::npos);
    EXPECT_TRUE(c.processed.input.point_cloud);
    EXPECT_EQ(c.processed.topology.vertices, 3u);
    EXPECT_EQ(c.processed_vertex_distance.size(), 3u);
    EXPECT_EQ(c.original_vertex_distance.size(), 4u);
    EXPECT_DOUBLE_EQ(c.processed_vertex_distance[2], 1.0);

    const nlohmann::json j = comparison_json(c);
    EXPECT_EQ(j["roughness_unavailable"], c.roughness_unavailable);
    EXPECT_TRUE(j["roughness_distance"].is_null());
    EXPECT_EQ(j["processed"]["mesh"]["point_cloud"], true);
    EXPECT_EQ(j["original"]["mesh"]["point_cloud"], false);
    const auto& sd = j["surface_distance"];
    EXPECT_EQ(sd["forward"]["distance_kind"], "surface-to-point");
    EXPECT_EQ(sd["backward"]["distance_kind"], "point-to-surface");
    EXPECT_EQ(sd["backward"]["samples_by_kind"]["point"], 3);
    EXPECT_EQ(sd["backward"]["hausdorff"]["exact_over_points"], true);
    EXPECT_EQ(sd["backward"]["hausdorff"]["location"]["point_index"], 2);
    EXPECT_TRUE(sd["forward"]["hausdorff"].is_null());
    EXPECT_TRUE(sd["forward"].contains("hausdorff_unavailable"));
    EXPECT_EQ(sd["hausdorff"]["method"], "sampled");
    EXPECT_EQ(sd["backward"]["area_weighted"]["points"], 3);
    EXPECT_TRUE(sd["backward"]["area_weighted"]["area"].is_null());
    const std::string t = comparison_text(c);
    EXPECT_NE(t.find("point cloud: 3 points"), std::string::npos) << t;
    EXPECT_NE(t.find("Roughness: skipped"), std::string::npos) << t;
    EXPECT_NE(t.find("Backward distance (M2 -> M1, point-to-surface)"), std::string::npos) << t;
    EXPECT_NE(t.find("exact over the points"), std::string::npos) << t;
    EXPECT_EQ(t.find("nan"), std::string::npos) << t;

    // Nothing left without the distance.
    CompareOptions nd;
    nd.distance = false;
    EXPECT_THROW(compare_meshes(a, b, nd), InvalidArgumentError);
}

TEST(CompareWithCloud, MeshReportsKeepSurfaceToSurface)
{
    const LoadedMesh a = loaded(unit_square(), "square.off");
    CompareOptions o;
    o.roughness = false;
    const Comparison c = compare_meshes(a, a, o);
    EXPECT_EQ(c.distance->forward_kind, DistanceKind::SurfaceToSurface);
    const nlohmann::json j = comparison_json(c);
    EXPECT_EQ(j["surface_distance"]["forward"]["distance_kind"], "surface-to-surface");
    EXPECT_EQ(j["surface_distance"]["forward"]["samples_by_kind"]["point"], 0);
    EXPECT_TRUE(j["roughness_unavailable"].is_null());
    EXPECT_FALSE(j["surface_distance"].contains("distance_kinds"));
    EXPECT_EQ(j["surface_distance"], surface_distance_json(*c.distance, o.sampling));
}
