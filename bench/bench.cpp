// Benchmark of the roughness profile: wall time per stage and peak memory.
// Usage: meshdiff_bench [--repeat N] [MESH ...] [--generated N_VERTICES]
// Prints one line per run and the median over N runs (default 3). The
// machine is noisy: compare medians and ratios, not single runs.
#include "meshdiff/curvature.h"
#include "meshdiff/facts.h"
#include "meshdiff/io.h"
#include "meshdiff/neighborhood.h"
#include "meshdiff/normals.h"
#include "meshdiff/roughness.h"
#include "meshdiff/shapes.h"

#include <fmt/format.h>
#include <omp.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

using namespace meshdiff;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0)
{
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

double cpu_seconds()
{
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double peak_rss_mb()
{
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    return double(ru.ru_maxrss) / 1024.0;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Stages
{
    double read = 0, facts = 0, normalize_normals = 0, curvature = 0, rings = 0, total = 0;
    double rings_cpu = 0;  // CPU seconds of all threads in the ring stage
};

// The full default profile as `meshdiff profile` runs it, timed by stage.
Stages run_once(const std::string& path, const Mesh* generated)
{
    Stages s;
    const auto t0 = Clock::now();
    LoadedMesh loaded;
    if (generated) {
        loaded.mesh = *generated;
        loaded.input.path = "generated";
    } else {
        loaded = read_mesh(path);
    }
    s.read = seconds_since(t0);
    auto t = Clock::now();
    const MeshFacts facts = mesh_facts(loaded);
    s.facts = seconds_since(t);

    // The stages of roughness_profile(), timed one by one...
    t = Clock::now();
    const Normalization nz = unit_normalization(loaded.mesh);
    const Mesh unit = apply_normalization(loaded.mesh, nz);
    const Adjacency adj = vertex_adjacency(unit);
    const auto normals = vertex_normals(unit);
    s.normalize_normals = seconds_since(t);
    t = Clock::now();
    const auto field = mean_curvature(unit, adj, normals);
    s.curvature = seconds_since(t);
    t = Clock::now();
    const double c0 = cpu_seconds();
    const auto dm = disk_means(unit, adj, field.H, default_levels());
    s.rings = seconds_since(t);
    s.rings_cpu = cpu_seconds() - c0;
    // ...and the real call end to end (what the CLI does after reading).
    t = Clock::now();
    const RoughnessProfile p = roughness_profile(loaded.mesh);
    const double profile_time = seconds_since(t);
    s.total = s.read + s.facts + profile_time;
    if (p.levels.empty() || facts.topology.vertices == 0 || dm.mean.empty()) fmt::print("unexpected\n");
    return s;
}

void bench(const std::string& label, const std::string& path, const Mesh* generated, int repeat)
{
    std::vector<Stages> runs;
    for (int r = 0; r < repeat; ++r) {
        runs.push_back(run_once(path, generated));
        const auto& s = runs.back();
        fmt::print(
            "  run {}: read {:.3f}  facts {:.3f}  normals {:.3f}  curvature {:.3f}  rings {:.3f} (cpu {:.3f})  | "
            "end-to-end {:.3f} s\n",
            r + 1, s.read, s.facts, s.normalize_normals, s.curvature, s.rings, s.rings_cpu, s.total);
    }
    auto med = [&](double Stages::*m) {
        std::vector<double> v;
        for (const auto& s : runs) v.push_back(s.*m);
        return median(v);
    };
    fmt::print(
        "{}: median end-to-end {:.3f} s (read {:.3f}, facts {:.3f}, normals {:.3f}, curvature {:.3f}, rings "
        "{:.3f}); peak RSS so far {:.0f} MB; threads {}\n",
        label, med(&Stages::total), med(&Stages::read), med(&Stages::facts), med(&Stages::normalize_normals),
        med(&Stages::curvature), med(&Stages::rings), peak_rss_mb(), omp_get_max_threads());
}

}  // namespace

int main(int argc, char** argv)
{
    int repeat = 3;
    std::vector<std::string> meshes;
    std::size_t generated = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::stoi(argv[++i]));
        else if (a == "--generated" && i + 1 < argc)
            generated = std::stoull(argv[++i]);
        else
            meshes.push_back(a);
    }
    fmt::print("meshdiff_bench: full default profile (levels 1..20 + global, Goldfeather cubic), {} runs each\n",
               repeat);
    for (const auto& m : meshes) bench(m, m, nullptr, repeat);
    if (generated) {
        const auto t = Clock::now();
        const Shape s = torus_irregular(generated, 1.0, 0.3, 1);
        fmt::print("generated irregular torus: {} vertices, {} faces in {:.2f} s\n", s.mesh.n_vertices(),
                   s.mesh.n_faces(), seconds_since(t));
        bench(fmt::format("irregular torus {} vertices", s.mesh.n_vertices()), "", &s.mesh, repeat);
    }
    return 0;
}
