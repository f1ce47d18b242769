// Benchmark of the roughness profile: wall time per stage and peak memory.
// Usage: meshdiff_bench [--repeat N] [--kernels vector|scalar|both] [MESH ...] [--generated N_VERTICES]
// Prints one line per run and the median over N runs (default 3). The
// machine is noisy: compare medians and ratios, not single runs. --kernels
// both alternates runs with the AVX-512 kernels (where the CPU has them) and
// with the baseline ones, and prints both medians and their ratio.
#include "bench_common.h"

#include "meshdiff/geometry/normals.h"
#include "meshdiff/io/facts.h"
#include "meshdiff/io/io.h"
#include "meshdiff/roughness/curvature.h"
#include "meshdiff/roughness/neighborhood.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/studies/shapes.h"

#include "geometry/simd.h"

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

using namespace meshdiff::timing;

namespace {

double seconds_since(Clock::time_point t0)
{
    return std::chrono::duration<double>(Clock::now() - t0).count();
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

enum class Kernels
{
    vector,
    scalar,
    both
};

void bench(const std::string& label, const std::string& path, const Mesh* generated, int repeat, Kernels kernels)
{
    std::vector<Stages> runs[2];  // [0]: the vector kernels, [1]: the scalar ones
    for (int r = 0; r < repeat; ++r)
        for (int k = 0; k < 2; ++k) {
            const bool scalar = k == 1;
            if ((kernels == Kernels::vector && scalar) || (kernels == Kernels::scalar && !scalar)) continue;
            detail::allow_vector_kernels(!scalar);
            runs[k].push_back(run_once(path, generated));
            const auto& s = runs[k].back();
            fmt::print(
                "  run {}{}: read {:.3f}  facts {:.3f}  normals {:.3f}  curvature {:.3f}  rings {:.3f} (cpu {:.3f})  "
                "| end-to-end {:.3f} s\n",
                r + 1, kernels == Kernels::both ? (scalar ? " scalar" : " vector") : "", s.read, s.facts,
                s.normalize_normals, s.curvature, s.rings, s.rings_cpu, s.total);
        }
    detail::allow_vector_kernels(true);
    auto med = [&](int k, double Stages::*m) {
        std::vector<double> v;
        for (const auto& s : runs[k]) v.push_back(s.*m);
        return median(v);
    };
    for (int k = 0; k < 2; ++k) {
        if (runs[k].empty()) continue;
        fmt::print(
            "{}{}: median end-to-end {:.3f} s (read {:.3f}, facts {:.3f}, normals {:.3f}, curvature {:.3f}, rings "
            "{:.3f}, rings cpu {:.3f}); peak RSS so far {:.0f} MB; threads {}\n",
            label, k == 1 ? " [scalar kernels]" : (detail::cpu_has_avx512() ? " [AVX-512 kernels]" : ""),
            med(k, &Stages::total), med(k, &Stages::read), med(k, &Stages::facts), med(k, &Stages::normalize_normals),
            med(k, &Stages::curvature), med(k, &Stages::rings), med(k, &Stages::rings_cpu), peak_rss_mib(),
            omp_get_max_threads());
    }
    if (!runs[0].empty() && !runs[1].empty())
        fmt::print("{}: scalar / vector kernels: rings {:.2f}x, end-to-end {:.2f}x\n", label,
                   med(1, &Stages::rings) / med(0, &Stages::rings), med(1, &Stages::total) / med(0, &Stages::total));
}

}  // namespace

int main(int argc, char** argv)
{
    int repeat = 3;
    std::vector<std::string> meshes;
    std::size_t generated = 0;
    Kernels kernels = Kernels::vector;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::stoi(argv[++i]));
        else if (a == "--kernels" && i + 1 < argc) {
            const std::string k = argv[++i];
            if (k != "vector" && k != "scalar" && k != "both") {
                fmt::print(stderr, "meshdiff_bench: --kernels takes vector, scalar or both, not '{}'\n", k);
                return 2;
            }
            kernels = k == "vector" ? Kernels::vector : k == "scalar" ? Kernels::scalar : Kernels::both;
        } else if (a == "--generated" && i + 1 < argc)
            generated = std::stoull(argv[++i]);
        else
            meshes.push_back(a);
    }
    fmt::print(
        "meshdiff_bench: full default profile (levels 1..20 + global, Goldfeather cubic), {} runs each; this CPU {} "
        "AVX-512\n",
        repeat, detail::cpu_has_avx512() ? "has" : "has no");
    for (const auto& m : meshes) bench(m, m, nullptr, repeat, kernels);
    if (generated) {
        const auto t = Clock::now();
        const Shape s = torus_irregular(generated, 1.0, 0.3, 1);
        fmt::print("generated irregular torus: {} vertices, {} faces in {:.2f} s\n", s.mesh.n_vertices(),
                   s.mesh.n_faces(), seconds_since(t));
        bench(fmt::format("irregular torus {} vertices", s.mesh.n_vertices()), "", &s.mesh, repeat, kernels);
    }
    return 0;
}
