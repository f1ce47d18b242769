// Benchmark of the certified Hausdorff distance (hausdorff.h).
//
// Usage:
//   meshdiff_bench_hausdorff [--runs N] [--threads N] [--diag-tolerance X] [--certified-only] A B
//
// Prints, each the median wall time of N runs (default 3) on the loaded meshes:
//  1. surface_distance() sampled (Metro defaults, both directions): the cost
//     of `meshdiff A B --hausdorff sampled`'s distance half;
//  2. the same with both directions certified at the default tolerance (1e-4
//     of the value), and the ratio 2 / 1 (issue 10's target: <= 1.3 including
//     the roughness half, so this ratio is an upper bound of that one);
//  3. both directions certified alone (index build included) at an absolute
//     tolerance of X times A's bounding-box diagonal (default 1e-6), the case
//     reference/cgal_hausdorff times with CGAL's bounded_error_Hausdorff_distance.
// Each line gives the intervals, their widths, the evaluations and rounds.
// --certified-only runs case 3 alone (for CPU-time measurements with time(1)).
#include "bench_common.h"

#include "meshdiff/distance/hausdorff.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/io/io.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

using namespace meshdiff::timing;

namespace {

void print_interval(const char* name, const meshdiff::CertifiedHausdorff& h)
{
    fmt::print("    {:8s} [{:.10g}, {:.10g}] width {:.3g} (asked {:.3g}) certified {} bounds {} points {} rounds {}\n",
               name, h.lower, h.upper, h.upper - h.lower, h.tolerance, h.certified, h.bound_evaluations,
               h.point_evaluations, h.rounds);
}

[[noreturn]] void usage()
{
    fmt::print(stderr, "usage: meshdiff_bench_hausdorff [--runs N] [--threads N] [--diag-tolerance X] A B\n");
    std::exit(2);
}

}  // namespace

int main(int argc, char** argv)
{
    int runs = 3;
    double diag_tolerance = 1e-6;
    bool certified_only = false;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) usage();
            return argv[++i];
        };
        if (arg == "--runs")
            runs = std::max(1, std::atoi(next().c_str()));
        else if (arg == "--threads")
            omp_set_num_threads(std::max(1, std::atoi(next().c_str())));
        else if (arg == "--certified-only")
            certified_only = true;
        else if (arg == "--diag-tolerance")
            diag_tolerance = std::atof(next().c_str());
        else if (!arg.empty() && arg[0] == '-')
            usage();
        else
            files.push_back(arg);
    }
    if (files.size() != 2) usage();
    const meshdiff::Mesh a = meshdiff::read_mesh(files[0]).mesh;
    const meshdiff::Mesh b = meshdiff::read_mesh(files[1]).mesh;
    const double diag = meshdiff::bounding_box(a).diagonal();
    fmt::print("A {} ({} vertices, {} faces), B {} ({} vertices, {} faces), threads {}, {} runs\n", files[0],
               a.n_vertices(), a.n_faces(), files[1], b.n_vertices(), b.n_faces(), omp_get_max_threads(), runs);

    meshdiff::SurfaceDistance sampled, certified;
    meshdiff::DistanceOptions certify;
    certify.hausdorff = meshdiff::HausdorffOptions{};
    if (!certified_only) {
        const double t_sampled = median_seconds(runs, [&] { sampled = meshdiff::surface_distance(a, b); });
        fmt::print("  sampled            {:.3f} s  hausdorff {:.10g} (forward {:.10g}, backward {:.10g})\n", t_sampled,
                   sampled.hausdorff, sampled.forward.max, sampled.backward.max);
        const double t_certified = median_seconds(runs, [&] { certified = meshdiff::surface_distance(a, b, certify); });
        fmt::print("  sampled+certified  {:.3f} s  ratio {:.3f} (relative tolerance 1e-4)\n", t_certified,
                   t_certified / t_sampled);
        print_interval("forward", *certified.forward_hausdorff);
        print_interval("backward", *certified.backward_hausdorff);
    }
    meshdiff::HausdorffOptions tight;
    tight.relative_tolerance = 0.0;
    tight.absolute_tolerance = diag_tolerance * diag;
    meshdiff::CertifiedHausdorff f, g;
    const double t_tight = median_seconds(runs, [&] {
        f = meshdiff::certified_hausdorff(a, b, tight);
        g = meshdiff::certified_hausdorff(b, a, tight);
    });
    fmt::print("  certified alone    {:.3f} s  both directions, tolerance {:g} x diagonal = {:.6g}\n", t_tight,
               diag_tolerance, tight.absolute_tolerance);
    print_interval("forward", f);
    print_interval("backward", g);
    return 0;
}
