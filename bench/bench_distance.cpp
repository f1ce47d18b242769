// Benchmark of the Metro-style surface distance (surface_distance.h).
//
// Usage:
//   meshdiff_bench_distance [--runs N] [--samples N] [--threads N]
//                           [--igea IGEA.ply --igea-decimated DEC.ply]
//                           [--large] [--large-faces N]
//                           [--pair A B ...] [--one-sided]
//                           [--no-vertex-samples] [--no-edge-samples] [--no-face-samples]
//                           [--face-sampling similar|montecarlo] [--seed N]
//
// Each case prints the median wall time of N runs of surface_distance() (both
// directions, default budget 10 x max #faces unless --samples), the sample
// counts, the statistics, and the peak resident memory of the process so far
// (getrusage ru_maxrss; run one case per process for per-case peaks).
//
// Cases:
//   --igea A --igea-decimated B   igea.ply against a 10% decimation made with
//                                 OpenMesh-commandlineDecimater -M Q -n 0.1 -i igea.ply -o DEC.ply
//   --large                       a generated torus of about --large-faces faces
//                                 (default 1,000,000) against a perturbed torus
//                                 with a different grid of about the same size
//   --pair A B                    any two mesh files (repeatable)
//   --one-sided                   for --pair: only A -> B (samples on A), timed
//                                 from the loaded meshes (index build, sampling,
//                                 queries, statistics); one line
//                                 "one-sided samples N v N e N f N min X max X
//                                 mean X rms X time_s T cpu_s C threads N
//                                 peak_rss_mib M" for scripts (T: median wall
//                                 time, C: median CPU time of all threads)
#include "bench_common.h"

#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/io/io.h"

#include <fmt/format.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

using namespace meshdiff::timing;

namespace {

using meshdiff::Mesh;
using meshdiff::Vec3;

// One-minute load average of the machine (other processes compete for cores).
double load1()
{
    double l[1] = {0.0};
    return getloadavg(l, 1) == 1 ? l[0] : -1.0;
}

// Torus (axis z, centre radius R, tube radius r) on an nu x nv grid, with a
// radial perturbation of the tube of relative amplitude `wave`.
Mesh torus(int nu, int nv, double R, double r, double wave)
{
    Mesh m;
    const double pi = std::acos(-1.0);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * pi * i / nu;
            const double v = 2 * pi * j / nv;
            const double rr = r * (1.0 + wave * std::sin(7 * u) * std::sin(5 * v));
            m.points.emplace_back((R + rr * std::cos(v)) * std::cos(u), (R + rr * std::cos(v)) * std::sin(u),
                                  rr * std::sin(v));
        }
    auto id = [&](int i, int j) { return std::int32_t((i % nu) * nv + (j % nv)); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

void print_stats(const char* name, const meshdiff::DistanceStats& s, double diag)
{
    fmt::print(
        "  {:8s} samples {} (v {} e {} f {})  min {:.6g} max {:.6g} mean {:.6g} rms {:.6g} p95 {:.6g}"
        "  [max/diag {:.6g} mean/diag {:.6g} rms/diag {:.6g}]\n",
        name, s.n_samples(), s.n_vertex, s.n_edge, s.n_face, s.min, s.max, s.mean, s.rms, s.p95, s.max / diag,
        s.mean / diag, s.rms / diag);
}

void run_one_sided(const Mesh& a, const Mesh& b, int runs, const meshdiff::SamplingOptions& options)
{
    std::vector<double> times, cpu;
    meshdiff::DistanceStats s;
    for (int k = 0; k < runs; ++k) {
        const double c0 = cpu_seconds();
        const auto t0 = std::chrono::steady_clock::now();
        const meshdiff::ClosestPointIndex index(b);
        s = meshdiff::one_sided_distance(a, index, options);
        const auto t1 = std::chrono::steady_clock::now();
        times.push_back(std::chrono::duration<double>(t1 - t0).count());
        cpu.push_back(cpu_seconds() - c0);
    }
    std::sort(times.begin(), times.end());
    std::sort(cpu.begin(), cpu.end());
    fmt::print(
        "one-sided samples {} v {} e {} f {} min {:.17g} max {:.17g} mean {:.17g} rms {:.17g} time_s {:.4f} "
        "cpu_s {:.4f} threads {} peak_rss_mib {:.1f}\n",
        s.n_samples(), s.n_vertex, s.n_edge, s.n_face, s.min, s.max, s.mean, s.rms, times[times.size() / 2],
        cpu[cpu.size() / 2], omp_get_max_threads(), peak_rss_mib());
}

void run_case(const std::string& label, const Mesh& a, const Mesh& b, int runs,
              const meshdiff::SamplingOptions& options)
{
    fmt::print("{}: A {} vertices {} faces, B {} vertices {} faces, threads {}\n", label, a.n_vertices(), a.n_faces(),
               b.n_vertices(), b.n_faces(), omp_get_max_threads());
    std::vector<double> times, cpu;
    meshdiff::DistanceOptions distance_options;
    distance_options.sampling = options;
    meshdiff::SurfaceDistance r;
    for (int k = 0; k < runs; ++k) {
        const double c0 = cpu_seconds();
        const auto t0 = std::chrono::steady_clock::now();
        r = meshdiff::surface_distance(a, b, distance_options);
        const auto t1 = std::chrono::steady_clock::now();
        times.push_back(std::chrono::duration<double>(t1 - t0).count());
        cpu.push_back(cpu_seconds() - c0);
    }
    std::sort(times.begin(), times.end());
    std::sort(cpu.begin(), cpu.end());
    print_stats("forward", r.forward, r.diagonal);
    print_stats("backward", r.backward, r.diagonal);
    fmt::print("  hausdorff {:.6g} (diag A {:.6g}, metro diag {:.6g})\n", r.hausdorff, r.diagonal, r.metro_diagonal);
    fmt::print(
        "  time median {:.3f} s (min {:.3f}, max {:.3f}, {} runs), CPU median {:.3f} s, load {:.2f}"
        "  peak RSS so far {:.1f} MiB\n",
        times[times.size() / 2], times.front(), times.back(), runs, cpu[cpu.size() / 2], load1(), peak_rss_mib());
}

[[noreturn]] void usage()
{
    fmt::print(stderr,
               "usage: meshdiff_bench_distance [--runs N] [--samples N] [--threads N] [--igea A --igea-decimated B]"
               " [--large] [--large-faces N] [--pair A B]... [--one-sided] [--no-vertex-samples] [--no-edge-samples]"
               " [--no-face-samples] [--face-sampling similar|montecarlo] [--seed N]\n");
    std::exit(2);
}

}  // namespace

int main(int argc, char** argv)
{
    int runs = 3;
    meshdiff::SamplingOptions options;
    std::string igea, igea_dec;
    bool large = false;
    bool one_sided = false;
    long large_faces = 1000000;
    std::vector<std::pair<std::string, std::string>> pairs;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) usage();
            return argv[++i];
        };
        if (arg == "--runs")
            runs = std::max(1, std::atoi(next().c_str()));
        else if (arg == "--samples")
            options.samples = std::size_t(std::atoll(next().c_str()));
        else if (arg == "--threads")
            omp_set_num_threads(std::max(1, std::atoi(next().c_str())));
        else if (arg == "--igea")
            igea = next();
        else if (arg == "--igea-decimated")
            igea_dec = next();
        else if (arg == "--large")
            large = true;
        else if (arg == "--one-sided")
            one_sided = true;
        else if (arg == "--no-vertex-samples")
            options.vertices = false;
        else if (arg == "--no-edge-samples")
            options.edges = false;
        else if (arg == "--no-face-samples")
            options.faces = false;
        else if (arg == "--face-sampling")
            options.face_scheme = meshdiff::parse_enum<meshdiff::FaceSampling>(next());
        else if (arg == "--seed")
            options.seed = std::stoull(next());
        else if (arg == "--large-faces")
            large_faces = std::atol(next().c_str());
        else if (arg == "--pair") {
            std::string a = next();
            pairs.emplace_back(a, next());
        } else
            usage();
    }
    if (igea.empty() != igea_dec.empty()) usage();
    if (igea.empty() && !large && pairs.empty()) usage();

    try {
        if (!igea.empty())
            run_case("igea vs decimation", meshdiff::read_mesh(igea).mesh, meshdiff::read_mesh(igea_dec).mesh, runs,
                     options);
        for (const auto& [a, b] : pairs) {
            if (one_sided) {
                run_one_sided(meshdiff::read_mesh(a).mesh, meshdiff::read_mesh(b).mesh, runs, options);
                continue;
            }
            run_case(fmt::format("{} vs {}", a, b), meshdiff::read_mesh(a).mesh, meshdiff::read_mesh(b).mesh, runs,
                     options);
        }
        if (large) {
            // About large_faces faces each: 2 nu nv with nu = 2 nv, and a
            // 0.8 : 1.25 aspect for the second grid.
            const int nv = int(std::sqrt(double(large_faces) / 4.0));
            const Mesh a = torus(2 * nv, nv, 1.0, 0.3, 0.0);
            const Mesh b = torus(int(1.6 * nv), int(1.25 * nv), 1.0, 0.3, 0.01);
            run_case("generated tori", a, b, runs, options);
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
    return 0;
}
