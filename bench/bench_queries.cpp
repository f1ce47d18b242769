// Benchmark of the closest-point queries alone (ClosestPointIndex::distances()),
// the surface distance's per-sample step, without reading, sampling, signs or
// statistics: the time per query of each direction of a pair, and what the
// order of the queries does to it.
//
// Usage:
//   meshdiff_bench_queries [--runs N] [--threads N] [--morton [--chunk N]] A B
//
// For each direction (the samples of A against B's index, then B's against
// A's) the samples are those of the surface distance at its default budget
// (10 x the larger face count, vertices, edges and faces), made once; the
// median wall time of N calls of distances() over all of them (default 5) is
// printed per query, with the minimum. --morton also times the same queries
// sorted by the Morton code of their position (the sort not timed) and checks
// that every distance is the same to the last bit: the answer of a query does
// not depend on the ones before it, only its cost does (each query starts from
// the previous one's triangle). With --chunk N, the Morton order only within
// consecutive parts of N queries (as the surface distance, which makes and
// queries its samples a chunk at a time, could sort them).
//
// Each run also builds the index it queries, timed apart; the last line sums
// the directions' medians per sample of both: the queries alone, and the
// index builds with them (what bench/anchors.py charges Open3D: its scene
// build and its queries, on points made beforehand).
//
//   meshdiff_bench_queries --threads 1 --morton ../shared/data/meshes/igea.ply /tmp/meshdiff-targets/igea_dec10.ply
//
// It compiles against the library as it was before the headers moved into
// folders (edfd398, issue 30's baseline) too, so that both are timed alike:
//   g++ -O2 -std=c++17 -fopenmp -I bench -I /tmp/edfd398/include -I /tmp/edfd398/build/include
//       -isystem /usr/include/eigen3 bench/bench_queries.cpp /tmp/edfd398/build/libmeshdiff.a
//       -lOpenMeshCore -lfmt -o /tmp/edfd398/build/meshdiff_bench_queries   (one line)
#include "bench_common.h"

#if __has_include("meshdiff/geometry/closest_point.h")
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/geometry/sampling.h"
#include "meshdiff/io/io.h"
#else  // the flat headers of edfd398
#include "meshdiff/closest_point.h"
#include "meshdiff/io.h"
#include "meshdiff/sampling.h"
#endif

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

namespace {

using meshdiff::Mesh;
using meshdiff::Vec3;

// The Morton code of p's cell in a 2^21 grid over [lo, hi].
std::uint64_t morton(const Vec3& p, const Vec3& lo, const Vec3& hi)
{
    std::uint64_t code = 0;
    std::uint32_t q[3];
    for (int k = 0; k < 3; ++k) {
        const double extent = hi[k] - lo[k];
        const double t = extent > 0.0 ? (p[k] - lo[k]) / extent : 0.0;
        q[k] = std::uint32_t(std::clamp(t, 0.0, 1.0) * 2097151.0);
    }
    for (int bit = 20; bit >= 0; --bit)
        for (int k = 0; k < 3; ++k) code = (code << 1) | ((q[k] >> bit) & 1u);
    return code;
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Median and minimum seconds of `runs` calls of index.distances(points).
std::pair<double, double> time_queries(const meshdiff::ClosestPointIndex& index, const std::vector<Vec3>& points,
                                       int runs, std::vector<double>& out)
{
    std::vector<double> t;
    for (int r = 0; r < runs; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        out = index.distances(points);
        t.push_back(seconds_since(t0));
    }
    return {meshdiff::timing::median(t), *std::min_element(t.begin(), t.end())};
}

// Median seconds of `runs` builds of the index of `mesh`.
double time_builds(const Mesh& mesh, int runs)
{
    std::vector<double> t;
    for (int r = 0; r < runs; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        const meshdiff::ClosestPointIndex index(mesh);
        t.push_back(seconds_since(t0));
    }
    return meshdiff::timing::median(t);
}

constexpr const char* kUsage = "usage: meshdiff_bench_queries [--runs N] [--threads N] [--morton [--chunk N]] A B\n";

int run(int argc, char** argv)
{
    int runs = 5;
    bool sorted = false;
    std::size_t chunk = 0;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc) {
            runs = std::max(1, std::atoi(argv[++i]));
        } else if (a == "--threads" && i + 1 < argc) {
            omp_set_num_threads(std::max(1, std::atoi(argv[++i])));
        } else if (a == "--chunk" && i + 1 < argc) {
            chunk = std::size_t(std::max(1L, std::atol(argv[++i])));
        } else if (a == "--morton") {
            sorted = true;
        } else if (!a.empty() && a[0] != '-') {
            files.push_back(a);
        } else {
            fmt::print(stderr, "{}", kUsage);
            return 2;
        }
    }
    if (files.size() != 2) {
        fmt::print(stderr, "{}", kUsage);
        return 2;
    }
    const Mesh a = meshdiff::read_mesh(files[0]).mesh, b = meshdiff::read_mesh(files[1]).mesh;
    meshdiff::SamplingOptions options;
    options.samples = 10 * std::max(a.n_faces(), b.n_faces());
    double total_n = 0.0, total_queries = 0.0, total_builds = 0.0;  // medians summed over the directions
    for (int direction = 0; direction < 2; ++direction) {
        const Mesh& from = direction == 0 ? a : b;
        const Mesh& to = direction == 0 ? b : a;
        const meshdiff::SurfaceSamples s = meshdiff::sample_surface(from, options);
        const double build = time_builds(to, runs);
        const meshdiff::ClosestPointIndex index(to);
        const double n = double(s.size());
        std::vector<double> given;
        const auto [median, best] = time_queries(index, s.points, runs, given);
        total_n += n;
        total_queries += median;
        total_builds += build;
        fmt::print("{} -> {}: {} queries (v {} e {} f {}) against {} faces, threads {}\n", direction == 0 ? "A" : "B",
                   direction == 0 ? "B" : "A", s.size(), s.n_vertex, s.n_edge, s.n_face, to.n_faces(),
                   omp_get_max_threads());
        fmt::print("  index build: {:.4f} s (median of {})\n", build, runs);
        fmt::print("  order given:  {:.1f} ns per query (median of {}; min {:.1f})\n", 1e9 * median / n, runs,
                   1e9 * best / n);
        if (!sorted) continue;
        Vec3 lo = s.points.front(), hi = lo;
        for (const Vec3& p : s.points) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(s.size());
        for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = {morton(s.points[i], lo, hi), std::uint32_t(i)};
        const std::size_t part = chunk > 0 ? chunk : keys.size();
        for (std::size_t begin = 0; begin < keys.size(); begin += part)
            std::sort(keys.begin() + std::ptrdiff_t(begin),
                      keys.begin() + std::ptrdiff_t(std::min(keys.size(), begin + part)));
        std::vector<Vec3> points(keys.size());
        for (std::size_t i = 0; i < keys.size(); ++i) points[i] = s.points[keys[i].second];
        std::vector<double> morton_order;
        const auto [m_median, m_best] = time_queries(index, points, runs, morton_order);
        std::size_t differ = 0;
        for (std::size_t i = 0; i < keys.size(); ++i)
            differ += std::memcmp(&morton_order[i], &given[keys[i].second], sizeof(double)) != 0;
        fmt::print(
            "  order Morton{}: {:.1f} ns per query (median of {}; min {:.1f}); distances differing from the "
            "given order's: {}\n",
            chunk > 0 ? fmt::format(" within parts of {}", chunk) : std::string(), 1e9 * m_median / n, runs,
            1e9 * m_best / n, differ);
        if (differ != 0) return 1;
    }
    fmt::print("both directions, {} samples, per sample: queries alone {:.1f} ns, index builds and queries {:.1f} ns\n",
               total_n, 1e9 * total_queries / total_n, 1e9 * (total_queries + total_builds) / total_n);
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        fmt::print(stderr, "meshdiff_bench_queries: {}\n", e.what());
        return 1;
    }
}
