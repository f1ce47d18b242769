// Cross-check of meshdiff's certified Hausdorff distance (issue 10) against
// CGAL's Polygon_mesh_processing::bounded_error_Hausdorff_distance (CGAL 5.5,
// Debian libcgal-dev, header-only). Built only for reference/: see
// reference/cgal_hausdorff.sh.
//
// Usage: cgal_hausdorff A B ERROR_BOUND
// Prints two lines, "forward VALUE SECONDS" (A -> B: points of A, distance to
// B) and "backward VALUE SECONDS", VALUE being CGAL's estimate, within
// ERROR_BOUND (absolute, in the meshes' unit) of the true one-sided distance,
// and SECONDS the wall time of that call (the meshes already read).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
    if (argc != 4) {
        std::cerr << "usage: cgal_hausdorff A B ERROR_BOUND\n";
        return 2;
    }
    Mesh a, b;
    if (!PMP::IO::read_polygon_mesh(argv[1], a) || !PMP::IO::read_polygon_mesh(argv[2], b)) {
        std::cerr << "cgal_hausdorff: cannot read " << argv[1] << " or " << argv[2] << "\n";
        return 3;
    }
    const double bound = std::atof(argv[3]);
    for (int dir = 0; dir < 2; ++dir) {
        const auto t0 = std::chrono::steady_clock::now();
        const double h = dir == 0 ? PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(a, b, bound)
                                  : PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(b, a, bound);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("%s %.17g %.4f\n", dir == 0 ? "forward" : "backward", h, s);
    }
    return 0;
}
