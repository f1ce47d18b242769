#include "meshdiff/core/progress.h"

#include <gtest/gtest.h>

#include "meshdiff/compare.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/error.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/studies/shapes.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <string>
#include <vector>

using namespace meshdiff;

namespace {

// Records every stage with its total and the largest count reported; cancelled
// once \p cancel_after_advances calls of advance() have arrived (0: never).
class Recorder : public Progress
{
public:
    struct Stage
    {
        std::string name;
        std::size_t total = 0;
        std::size_t done = 0;
        std::size_t advances = 0;
    };
    explicit Recorder(std::size_t cancel_after_advances = 0) : cancel_after_(cancel_after_advances) {}

    void stage(std::string_view name, std::size_t total) override
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stages.push_back({std::string(name), total, 0, 0});
    }
    void advance(std::size_t done) override
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        EXPECT_FALSE(stages.empty());
        if (stages.empty()) return;
        Stage& s = stages.back();
        if (s.total) {
            EXPECT_LE(done, s.total) << s.name;
        }
        s.done = std::max(s.done, done);
        ++s.advances;
        ++advances_;
    }
    bool cancelled() const override
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        return cancel_after_ > 0 && advances_ >= cancel_after_;
    }
    std::vector<std::string> names() const
    {
        std::vector<std::string> n;
        for (const auto& s : stages) n.push_back(s.name);
        return n;
    }
    std::vector<Stage> stages;

private:
    mutable std::mutex mutex_;
    std::size_t cancel_after_;
    std::size_t advances_ = 0;
};

// Cancelled from the start.
class Cancelling : public Progress
{
public:
    bool cancelled() const override { return true; }
};

const Shape& torus_mesh()
{
    static const Shape s = torus_irregular(20000, 1.0, 0.3, 5);
    return s;
}
const Shape& torus_other()
{
    static const Shape s = torus_irregular(15000, 1.0, 0.3, 6);
    return s;
}

ProfileOptions profile_options()
{
    ProfileOptions o;
    o.levels = {1, 3};
    o.radii = {0.1};
    return o;
}

bool contains(const std::vector<std::string>& v, const std::string& s)
{
    return std::find(v.begin(), v.end(), s) != v.end();
}

LoadedMesh loaded(const Shape& s)
{
    LoadedMesh m;
    m.mesh = s.mesh;
    return m;
}

}  // namespace

TEST(Progress, DefaultDoesNothingAndIsNeverCancelled)
{
    Progress p;
    p.stage("x", 10);
    p.advance(5);
    EXPECT_FALSE(p.cancelled());
    EXPECT_NO_THROW(check_cancelled(&p));
    EXPECT_NO_THROW(check_cancelled(nullptr));
    Cancelling c;
    EXPECT_THROW(check_cancelled(&c), Cancelled);
}

TEST(Progress, CancelledIsAMeshdiffError)
{
    try {
        throw Cancelled();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "cancelled");
    }
}

TEST(Progress, ScopesNestAndRestore)
{
    EXPECT_EQ(current_progress(), nullptr);
    Progress a, b;
    {
        const ProgressScope sa(&a);
        EXPECT_EQ(current_progress(), &a);
        {
            const ProgressScope sb(&b);
            EXPECT_EQ(current_progress(), &b);
            const ProgressScope off(nullptr);
            EXPECT_EQ(current_progress(), nullptr);
        }
        EXPECT_EQ(current_progress(), &a);
    }
    EXPECT_EQ(current_progress(), nullptr);
}

TEST(Progress, ProfileReportsEveryStageToTheEnd)
{
    Recorder rec;
    ProfileOptions o = profile_options();
    o.progress = &rec;
    const RoughnessProfile p = roughness_profile(torus_mesh().mesh, o);
    EXPECT_EQ(rec.names(), (std::vector<std::string>{"curvature", "rings", "metric levels"}));
    for (const auto& s : rec.stages) {
        EXPECT_GT(s.total, 0u) << s.name;
        EXPECT_EQ(s.done, s.total) << s.name;  // a final fraction of 1
    }
    // Curvature counts vertices; reports come about every 1/100 of a stage.
    EXPECT_EQ(rec.stages[0].total, torus_mesh().mesh.n_vertices());
    EXPECT_GE(rec.stages[0].advances, 50u);
    EXPECT_LE(rec.stages[0].advances, 102u);
    // The numbers do not depend on the Progress.
    const RoughnessProfile q = roughness_profile(torus_mesh().mesh, profile_options());
    ASSERT_EQ(p.levels.size(), q.levels.size());
    for (std::size_t k = 0; k < p.levels.size(); ++k) EXPECT_EQ(p.levels[k].sigma, q.levels[k].sigma);
    EXPECT_EQ(p.radii[0].sigma, q.radii[0].sigma);
    EXPECT_EQ(p.global.sigma, q.global.sigma);
}

TEST(Progress, CompareReportsEveryStageToTheEnd)
{
    Recorder rec;
    CompareOptions o;
    o.profile = profile_options();
    o.sampling.samples = 100000;
    o.progress = &rec;
    const Comparison c = compare_meshes(loaded(torus_mesh()), loaded(torus_other()), o);
    const auto names = rec.names();
    for (const char* stage : {"curvature", "rings", "metric levels", "index", "sampling", "distances", "certification"})
        EXPECT_TRUE(contains(names, stage)) << stage;
    // Each mesh's profile, then each direction: index, vertex distances,
    // sampling, sample distances, certification.
    EXPECT_EQ(std::count(names.begin(), names.end(), "curvature"), 2);
    EXPECT_EQ(std::count(names.begin(), names.end(), "certification"), 2);
    std::size_t samples_seen = 0;
    for (const auto& s : rec.stages) {
        if (s.total) {
            EXPECT_EQ(s.done, s.total) << s.name;
        } else {
            EXPECT_GT(s.done, 0u) << s.name;  // certification: the triangles bounded and split
        }
        if (s.name == "distances") samples_seen += s.total;
    }
    // The vertices' distances (for the certification) and the other samples',
    // and the closest points of the local roughness difference: of the
    // processed mesh's vertices (ring levels) and, with radii, of the
    // original's. The processed mesh's vertices are searched once: the local
    // difference's closest points serve the backward direction's vertex
    // samples (detail::HandedToDistance).
    ASSERT_TRUE(c.local_roughness);
    ASSERT_FALSE(c.local_roughness->radii.empty());
    EXPECT_EQ(c.distance->backward.n_vertex, c.local_roughness->vertices);
    EXPECT_EQ(samples_seen,
              c.distance->forward.n_samples() + c.distance->backward.n_samples() + c.local_roughness->vertices_radii);
    EXPECT_EQ(c.options.progress, nullptr);  // not kept in the result
    ASSERT_TRUE(c.distance && c.distance->forward_hausdorff);
    EXPECT_TRUE(c.distance->forward_hausdorff->certified);

    CompareOptions plain = o;
    plain.progress = nullptr;
    const Comparison d = compare_meshes(loaded(torus_mesh()), loaded(torus_other()), plain);
    EXPECT_EQ(c.distance->hausdorff, d.distance->hausdorff);
    EXPECT_EQ(c.distance->forward.mean, d.distance->forward.mean);
    EXPECT_EQ(c.distance->forward_hausdorff->upper, d.distance->forward_hausdorff->upper);
    EXPECT_EQ(c.roughness->global.distance, d.roughness->global.distance);
}

TEST(Progress, CancelledProgressStopsTheProfile)
{
    Cancelling cancel;
    ProfileOptions o = profile_options();
    o.progress = &cancel;
    EXPECT_THROW(roughness_profile(torus_mesh().mesh, o), Cancelled);
    // Through a scope as well.
    const ProgressScope scope(&cancel);
    EXPECT_THROW(roughness_profile(torus_mesh().mesh, profile_options()), Cancelled);
}

TEST(Progress, CancelledProgressStopsTheSurfaceDistance)
{
    Cancelling cancel;
    const ProgressScope scope(&cancel);
    EXPECT_THROW(surface_distance(torus_mesh().mesh, torus_other().mesh), Cancelled);
    EXPECT_THROW(certified_hausdorff(torus_mesh().mesh, torus_other().mesh), Cancelled);
    CompareOptions o;
    o.progress = &cancel;
    EXPECT_THROW(compare_meshes(loaded(torus_mesh()), loaded(torus_other()), o), Cancelled);
}

TEST(Progress, CancellingMidStageSkipsTheRestOfTheStage)
{
    // Cancelled at the 3rd report (3% of the curvature stage): the loop skips
    // the rest of its vertices, and no later stage starts.
    const int threads_before = omp_get_max_threads();
    for (const int threads : {1, 2}) {
        omp_set_num_threads(threads);
        Recorder rec(3);
        ProfileOptions o = profile_options();
        o.progress = &rec;
        EXPECT_THROW(roughness_profile(torus_mesh().mesh, o), Cancelled);
        ASSERT_EQ(rec.names(), std::vector<std::string>{"curvature"}) << threads;
        // At most a chunk (1024 vertices) per thread past the cancelling report.
        EXPECT_LT(rec.stages[0].done, rec.stages[0].total / 2) << threads;
        EXPECT_LE(rec.stages[0].advances, 3u + std::size_t(threads)) << threads;
    }
    omp_set_num_threads(threads_before);
}

TEST(Progress, CancellingDuringTheCertificationStopsIt)
{
    // Cancelled at the first report of the certification (after 4096
    // triangles): surface_distance throws instead of finishing.
    class AtCertification : public Progress
    {
    public:
        void stage(std::string_view name, std::size_t) override { in_ = name == "certification"; }
        void advance(std::size_t done) override
        {
            if (in_) seen_ = std::max(seen_.load(), done);
        }
        bool cancelled() const override { return in_ && seen_ > 0; }
        std::atomic<std::size_t> seen_{0};

    private:
        std::atomic<bool> in_{false};
    } p;
    const ProgressScope scope(&p);
    HausdorffOptions h;
    EXPECT_THROW(surface_distance(torus_mesh().mesh, torus_other().mesh, {}, false, h), Cancelled);
    EXPECT_GT(p.seen_.load(), 0u);
}
