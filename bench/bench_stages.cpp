// Benchmark of the stages every profile and comparison starts with: reading a
// mesh file, the profile's work before its curvature fits (the normalised
// copy, the vertex adjacency, the derived data and the vertex normals), the
// topology report, the edge map and the pseudo-normals of a comparison, and
// building the closest-point index of the mesh read.
//
// Usage: meshdiff_bench_stages [--runs N] MESH ...
//
// For each mesh: the wall time of each of N runs (default 5) of read_mesh(),
// of each step of the profile's preamble and of ClosestPointIndex's
// construction, and their medians, with the process's peak resident memory
// so far. The machine is noisy: compare medians of builds alternated in one
// run (docs/performance.md), not single runs.
#include "bench_common.h"

#include "meshdiff/core/mesh_data.h"
#include "meshdiff/core/topology.h"
#include "meshdiff/distance/signed_distance.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/geometry/normalize.h"
#include "meshdiff/geometry/normals.h"
#include "meshdiff/io/io.h"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

using namespace meshdiff;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string list(const std::vector<double>& v)
{
    std::string s;
    for (double x : v) s += fmt::format("{}{:.3f}", s.empty() ? "" : " ", x);
    return s;
}

}  // namespace

int main(int argc, char** argv)
{
    int runs = 5;
    std::vector<std::string> meshes;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc) {
            runs = std::max(1, std::atoi(argv[++i]));
        } else if (a == "--help" || a == "-h" || (!a.empty() && a[0] == '-')) {
            fmt::print(stderr, "usage: meshdiff_bench_stages [--runs N] MESH ...\n");
            return a == "--help" || a == "-h" ? 0 : 2;
        } else {
            meshes.push_back(a);
        }
    }
    if (meshes.empty()) {
        fmt::print(stderr, "usage: meshdiff_bench_stages [--runs N] MESH ...\n");
        return 2;
    }
    fmt::print("threads {}\n", omp_get_max_threads());
    for (const std::string& path : meshes) {
        std::vector<double> read_s, normalise_s, adjacency_s, normals_s, topology_s, edges_s, pseudo_s, index_s;
        std::size_t nv = 0, nf = 0;
        for (int k = 0; k < runs; ++k) {
            auto t0 = std::chrono::steady_clock::now();
            const LoadedMesh m = read_mesh(path);
            read_s.push_back(seconds_since(t0));
            nv = m.mesh.n_vertices();
            nf = m.mesh.n_faces();
            t0 = std::chrono::steady_clock::now();
            {
                const Mesh unit = apply_normalization(m.mesh, unit_normalization(m.mesh));
                normalise_s.push_back(seconds_since(t0));
                t0 = std::chrono::steady_clock::now();
                const Adjacency adj = vertex_adjacency(unit);
                adjacency_s.push_back(seconds_since(t0));
                t0 = std::chrono::steady_clock::now();
                const MeshData unit_data(unit);
                const std::vector<Vec3> normals = vertex_normals(unit_data);
                normals_s.push_back(seconds_since(t0));
            }
            const MeshData data(m.mesh);
            {
                t0 = std::chrono::steady_clock::now();
                (void)topology_report(data);
                topology_s.push_back(seconds_since(t0));
                t0 = std::chrono::steady_clock::now();
                (void)edge_map(data);
                edges_s.push_back(seconds_since(t0));
                t0 = std::chrono::steady_clock::now();
                std::string why;
                (void)pseudo_normals(data, "mesh", &why);
                pseudo_s.push_back(seconds_since(t0));
            }
            t0 = std::chrono::steady_clock::now();
            {
                const ClosestPointIndex index(data);
                index_s.push_back(seconds_since(t0));
            }
        }
        fmt::print("{}: {} vertices, {} faces\n", path, nv, nf);
        fmt::print("  read      median {:.3f} s (runs: {})\n", timing::median(read_s), list(read_s));
        fmt::print("  normalise median {:.3f} s (runs: {})\n", timing::median(normalise_s), list(normalise_s));
        fmt::print("  adjacency median {:.3f} s (runs: {})\n", timing::median(adjacency_s), list(adjacency_s));
        fmt::print("  normals   median {:.3f} s (runs: {})\n", timing::median(normals_s), list(normals_s));
        fmt::print("  topology  median {:.3f} s (runs: {})\n", timing::median(topology_s), list(topology_s));
        fmt::print("  edges     median {:.3f} s (runs: {})\n", timing::median(edges_s), list(edges_s));
        fmt::print("  pseudo-normals median {:.3f} s (runs: {})\n", timing::median(pseudo_s), list(pseudo_s));
        fmt::print("  index     median {:.3f} s (runs: {})\n", timing::median(index_s), list(index_s));
        fmt::print("  peak_rss_mib {:.0f}\n", timing::peak_rss_mib());
    }
    return 0;
}
