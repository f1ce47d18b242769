#include "meshdiff/compare.h"

#include <gtest/gtest.h>

#include "meshdiff/error.h"
#include "meshdiff/geometry/normalize.h"

#include "core/derivations.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

using namespace meshdiff;

namespace {

std::string data(const std::string& name)
{
    return std::string(MESHDIFF_TEST_DATA_DIR) + "/" + name;
}

const LoadedMesh& sphere()
{
    static const LoadedMesh m = read_mesh(data("sphere_ico_2562.ply"));
    return m;
}
const LoadedMesh& irregular()
{
    static const LoadedMesh m = read_mesh(data("sphere_irregular_3072.ply"));
    return m;
}

CompareOptions small_options()
{
    CompareOptions o;
    o.profile.levels = {1, 2, 5};
    o.sampling.samples = 20000;
    return o;
}

void expect_same_level(const LevelRoughness& a, const LevelRoughness& b)
{
    EXPECT_EQ(a.level, b.level);
    EXPECT_EQ(a.sigma, b.sigma) << a.level;
    EXPECT_EQ(a.vertices_used, b.vertices_used);
    EXPECT_EQ(a.no_neighborhood, b.no_neighborhood);
    EXPECT_EQ(a.top_share, b.top_share);
    EXPECT_EQ(a.worst_vertices, b.worst_vertices);
}

void expect_same_profile(const RoughnessProfile& a, const RoughnessProfile& b)
{
    EXPECT_EQ(a.normalization.center, b.normalization.center);
    EXPECT_EQ(a.normalization.scale, b.normalization.scale);
    EXPECT_EQ(a.curvature_undefined, b.curvature_undefined);
    EXPECT_EQ(a.curvature_widened, b.curvature_widened);
    EXPECT_EQ(a.curvature_fallback, b.curvature_fallback);
    ASSERT_EQ(a.levels.size(), b.levels.size());
    for (std::size_t k = 0; k < a.levels.size(); ++k) expect_same_level(a.levels[k], b.levels[k]);
    ASSERT_EQ(a.has_global, b.has_global);
    expect_same_level(a.global, b.global);
}

void expect_same_stats(const DistanceStats& a, const DistanceStats& b)
{
    const double fa[] = {a.min, a.max, a.mean, a.rms, a.stddev, a.p50, a.p95, a.p99};
    const double fb[] = {b.min, b.max, b.mean, b.rms, b.stddev, b.p50, b.p95, b.p99};
    for (int i = 0; i < 8; ++i) EXPECT_EQ(fa[i], fb[i]) << i;
    EXPECT_EQ(a.n_vertex, b.n_vertex);
    EXPECT_EQ(a.n_edge, b.n_edge);
    EXPECT_EQ(a.n_face, b.n_face);
}

void expect_same_comparison(const Comparison& a, const Comparison& b)
{
    expect_same_profile(*a.original_profile, *b.original_profile);
    expect_same_profile(*a.processed_profile, *b.processed_profile);
    ASSERT_EQ(a.roughness->levels.size(), b.roughness->levels.size());
    for (std::size_t k = 0; k < a.roughness->levels.size(); ++k)
        EXPECT_EQ(a.roughness->levels[k].distance, b.roughness->levels[k].distance);
    EXPECT_EQ(a.roughness->global.distance, b.roughness->global.distance);
    expect_same_stats(a.distance->forward, b.distance->forward);
    expect_same_stats(a.distance->backward, b.distance->backward);
    EXPECT_EQ(a.distance->hausdorff, b.distance->hausdorff);
    EXPECT_EQ(a.processed_vertex_distance, b.processed_vertex_distance);
}

}  // namespace

TEST(CompareMeshes, AMeshWithItselfHasZeroRoughnessDistanceAndRoundingLevelHausdorff)
{
    const Comparison c = compare_meshes(irregular(), irregular(), small_options());
    ASSERT_TRUE(c.roughness && c.distance);
    ASSERT_EQ(c.roughness->levels.size(), 3u);
    for (const auto& l : c.roughness->levels) {
        EXPECT_EQ(l.distance, 0.0) << l.level;
        EXPECT_EQ(l.relative_change, 0.0) << l.level;
    }
    ASSERT_TRUE(c.roughness->has_global);
    EXPECT_EQ(c.roughness->global.distance, 0.0);
    EXPECT_LT(c.distance->hausdorff, 1e-15 * c.distance->diagonal);
    EXPECT_EQ(c.distance->forward.min, 0.0);  // vertex samples are exact
}

TEST(CompareMeshes, HausdorffIsTheLargerOneSidedMaximum)
{
    const Comparison c = compare_meshes(sphere(), irregular(), small_options());
    EXPECT_EQ(c.distance->hausdorff, std::max(c.distance->forward.max, c.distance->backward.max));
    EXPECT_NE(c.distance->forward.max, c.distance->backward.max);
    EXPECT_EQ(c.distance->diagonal, bounding_box(sphere().mesh).diagonal());
    EXPECT_GT(c.distance->hausdorff, 0.0);
    EXPECT_LT(c.distance->hausdorff, 0.05);  // two tessellations of the unit sphere
}

TEST(CompareMeshes, ASwitchedOffHalfIsAnEmptyOptional)
{
    CompareOptions o = small_options();
    o.roughness = false;
    Comparison c = compare_meshes(sphere(), irregular(), o);
    EXPECT_FALSE(c.original_profile || c.processed_profile || c.roughness);
    EXPECT_TRUE(c.distance.has_value());
    EXPECT_TRUE(c.processed_vertex_distance.empty());
    o.roughness = true;
    o.distance = false;
    c = compare_meshes(sphere(), irregular(), o);
    EXPECT_FALSE(c.distance.has_value());
    EXPECT_TRUE(c.original_profile && c.processed_profile && c.roughness);
    EXPECT_TRUE(c.processed_vertex_distance.empty());
}

TEST(CompareMeshes, ThrowsForBothHalvesOffBadKAndBadSampling)
{
    CompareOptions o = small_options();
    o.roughness = o.distance = false;
    EXPECT_THROW(compare_meshes(sphere(), sphere(), o), InvalidArgumentError);
    for (const double k :
         {0.0, -1e-4, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        o = small_options();
        o.k = k;
        EXPECT_THROW(compare_meshes(sphere(), sphere(), o), InvalidArgumentError) << k;
    }
    o = small_options();
    o.sampling.samples = 0;
    EXPECT_THROW(compare_meshes(sphere(), sphere(), o), InvalidArgumentError);
    o.sampling.samples = 100;
    o.sampling.density = 10.0;
    EXPECT_THROW(compare_meshes(sphere(), sphere(), o), InvalidArgumentError);
    o = small_options();
    o.sampling.vertices = o.sampling.edges = o.sampling.faces = false;
    EXPECT_THROW(compare_meshes(sphere(), sphere(), o), InvalidArgumentError);
    // Sampling is checked even when the distance half is off.
    o.distance = false;
    EXPECT_THROW(compare_meshes(sphere(), sphere(), o), InvalidArgumentError);
}

TEST(CompareMeshes, EachPartEqualsItsFunctionRunSeparately)
{
    const CompareOptions o = small_options();
    const Comparison c = compare_meshes(sphere(), irregular(), o);
    const RoughnessProfile pa = roughness_profile(sphere().mesh, o.profile);
    const RoughnessProfile pb = roughness_profile(irregular().mesh, o.profile);
    expect_same_profile(*c.original_profile, pa);
    expect_same_profile(*c.processed_profile, pb);
    const RoughnessDistance d = roughness_distance(pa, pb, o.k);
    for (std::size_t k = 0; k < d.levels.size(); ++k) {
        EXPECT_EQ(c.roughness->levels[k].distance, d.levels[k].distance);
        EXPECT_EQ(c.roughness->levels[k].relative_change, d.levels[k].relative_change);
    }
    EXPECT_EQ(c.roughness->global.distance, d.global.distance);
    DistanceOptions distance;
    distance.sampling = o.sampling;
    const SurfaceDistance s = surface_distance(sphere().mesh, irregular().mesh, distance);
    expect_same_stats(c.distance->forward, s.forward);
    expect_same_stats(c.distance->backward, s.backward);
    EXPECT_EQ(c.distance->metro_diagonal, s.metro_diagonal);
    EXPECT_EQ(c.original.topology.edges, mesh_facts(sphere()).topology.edges);
    EXPECT_EQ(c.processed.area, mesh_facts(irregular()).area);
    EXPECT_EQ(c.processed.input.path, irregular().input.path);
    EXPECT_EQ(c.options.k, o.k);
}

TEST(CompareMeshes, VertexDistancesCoverEveryProcessedVertex)
{
    CompareOptions o = small_options();
    o.roughness = false;
    o.vertex_distances = true;
    const Comparison c = compare_meshes(sphere(), irregular(), o);
    ASSERT_EQ(c.processed_vertex_distance.size(), irregular().mesh.n_vertices());
    const double largest = *std::max_element(c.processed_vertex_distance.begin(), c.processed_vertex_distance.end());
    EXPECT_LE(largest, c.distance->backward.max);                // vertices are among the backward samples
    EXPECT_TRUE(c.distance->processed_vertex_distance.empty());  // moved out, not copied
}

TEST(CompareMeshes, IdenticalForOneAndTwoThreads)
{
    CompareOptions o = small_options();
    o.vertex_distances = true;
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const Comparison one = compare_meshes(sphere(), irregular(), o);
    omp_set_num_threads(2);
    const Comparison two = compare_meshes(sphere(), irregular(), o);
    omp_set_num_threads(saved);
    expect_same_comparison(one, two);
}

TEST(CompareMeshes, CorsiniMeasureReplacesTheSigmaProfilesWithCorsinisRoughness)
{
    CompareOptions o = small_options();
    o.distance = false;
    o.measure = RoughnessMeasure::Corsini;
    const Comparison c = compare_meshes(sphere(), irregular(), o);
    EXPECT_FALSE(c.original_profile);
    EXPECT_FALSE(c.roughness);
    ASSERT_TRUE(c.original_corsini && c.processed_corsini && c.corsini);
    CorsiniOptions co;
    co.levels = o.profile.levels;
    const CorsiniProfile a = corsini_profile(sphere().mesh, co), b = corsini_profile(irregular().mesh, co);
    ASSERT_EQ(c.corsini->levels.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(c.original_corsini->levels[k].roughness, a.levels[k].roughness);
        EXPECT_EQ(c.corsini->levels[k].distance,
                  level_distance(co.levels[k], a.levels[k].roughness, b.levels[k].roughness, o.k).distance);
    }
    EXPECT_EQ(c.corsini->multiscale.distance, level_distance(0, a.multiscale, b.multiscale, o.k).distance);
    const Comparison self = compare_meshes(sphere(), sphere(), o);
    for (const auto& l : self.corsini->levels) EXPECT_EQ(l.distance, 0.0);
    o.profile.radii = {0.1};
    EXPECT_THROW(compare_meshes(sphere(), sphere(), o), InvalidArgumentError);
}

// One comparison derives the box, the degenerate-face mask, the vertex-face
// incidence and the validation of each mesh at most once (issue 27): the two
// inputs, and each normalised copy the profiles and the local difference
// work on; with metric levels, the distance maps and the local difference on.
// Meshes are told apart by the hash of their points: the one repeat is a
// normalised copy, which the profile makes and frees and the local
// difference makes again (the processed mesh's for the ring levels, the
// original's for the radii; keeping it from the profile would hold a copy of
// the points through the whole comparison); each copy derives its box once.
TEST(CompareMeshes, PerVertexDataNotAskedForIsFreed)
{
    // Without keep_vertex_data the profiles' per-vertex H and D are given
    // back, storage included (`v = {}` keeps a vector's capacity: 16 MB of H
    // for two 1M-vertex meshes stayed held through the surface distance).
    CompareOptions o = small_options();
    const Comparison c = compare_meshes(sphere(), irregular(), o);
    for (const RoughnessProfile* p : {&*c.original_profile, &*c.processed_profile}) {
        EXPECT_EQ(p->H.capacity(), 0u);
        EXPECT_EQ(p->D.capacity(), 0u);
        EXPECT_EQ(p->D_global.capacity(), 0u);
    }
    o.profile.keep_vertex_data = true;
    const Comparison k = compare_meshes(sphere(), irregular(), o);
    EXPECT_EQ(k.original_profile->H.size(), sphere().mesh.n_vertices());
}

TEST(CompareMeshes, DerivesEachDatumOncePerMeshAndTheIncidenceOncePerStage)
{
    CompareOptions with_radii;
    with_radii.profile.radii = {0.1, 0.3};
    with_radii.vertex_distances = true;
    for (const CompareOptions& o : {CompareOptions{}, with_radii}) {
        detail::start_derivation_log();
        const Comparison c = compare_meshes(sphere(), irregular(), o);
        const detail::DerivationCounts counts = detail::stop_derivation_log();
        ASSERT_TRUE(c.local_roughness.has_value() && c.original_profile.has_value());
        const std::size_t
            original = detail::mesh_key(sphere().mesh).second,
            processed = detail::mesh_key(irregular().mesh).second,
            original_unit =
                detail::mesh_key(apply_normalization(sphere().mesh, c.original_profile->normalization)).second,
            processed_unit =
                detail::mesh_key(apply_normalization(irregular().mesh, c.processed_profile->normalization)).second;
        std::map<std::pair<std::size_t, detail::Derived>, int> by_points;  // the same points, any address
        for (const auto& [key, n] : counts) by_points[{key.first.second, key.second}] += n;
        const char* names[] = {"box", "degenerate mask", "vertex-face incidence", "validation"};
        std::map<std::string, int> inputs;
        for (const auto& [key, n] : by_points) {
            const std::string who = key.first == original         ? "original"
                                    : key.first == processed      ? "processed"
                                    : key.first == original_unit  ? "the original's normalised copy"
                                    : key.first == processed_unit ? "the processed mesh's normalised copy"
                                                                  : "another derived copy";
            const bool input = key.first == original || key.first == processed;
            // An input's incidence is freed between stages and derived again
            // by each that reads it: the topology reports, then each
            // direction's plan and pseudo-normals (three times, no more:
            // none is freed while a stage still reads it).
            const int copies =
                (key.first == original_unit || key.first == processed_unit) && key.second == detail::Derived::Box ? 2
                : input && key.second == detail::Derived::VertexFaces                                             ? 3
                                                                                                                  : 1;
            EXPECT_LE(n, copies) << who << "'s " << names[int(key.second)] << " derived " << n << " times";
            if (input && key.second == detail::Derived::VertexFaces) {
                EXPECT_EQ(n, 3) << who << "'s incidence was not freed between the stages";
            }
            if (key.first == original || key.first == processed) ++inputs[who];
        }
        // The log saw both inputs, each with all four data (the test would
        // pass vacuously on an empty log).
        EXPECT_EQ(inputs["original"], 4);
        EXPECT_EQ(inputs["processed"], 4);
    }
}
