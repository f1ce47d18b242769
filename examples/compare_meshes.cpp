// Compares a processed mesh with its original through the meshdiff library:
// the roughness profiles, the per-level roughness distance d_L and the
// Metro-style surface distance. Usage: compare_meshes ORIGINAL PROCESSED
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/roughness/roughness_distance.h"
#include "meshdiff/version.h"

#include <cstdio>
#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::cerr << "usage: " << argv[0] << " ORIGINAL PROCESSED\n";
        return 2;
    }
    try {
        const meshdiff::LoadedMesh a = meshdiff::read_mesh(argv[1]);
        const meshdiff::LoadedMesh b = meshdiff::read_mesh(argv[2]);
        std::cout << "meshdiff " << MESHDIFF_VERSION << ": " << a.mesh.n_faces() << " vs " << b.mesh.n_faces()
                  << " faces\n";

        // Roughness at ring levels 1..20 and globally (the defaults).
        const meshdiff::RoughnessProfile pa = meshdiff::roughness_profile(a.mesh);
        const meshdiff::RoughnessProfile pb = meshdiff::roughness_profile(b.mesh);
        const meshdiff::RoughnessDistance rd = meshdiff::roughness_distance(pa, pb);
        std::cout << "levels: " << rd.levels.size() << (rd.has_global ? " + global" : "") << "\n";
        for (const meshdiff::LevelDistance& d : rd.levels) {
            if (d.level == 1 || d.level % 5 == 0) std::printf("  d_%-2d = %.4f\n", d.level, d.distance);
        }
        if (rd.has_global) std::printf("  d_G  = %.4f\n", rd.global.distance);

        // Surface distance, in the meshes' own length unit.
        const meshdiff::SurfaceDistance sd = meshdiff::surface_distance(a.mesh, b.mesh);
        std::printf("forward max:  %.6g (%zu samples)\n", sd.forward.max, sd.forward.n_samples());
        std::printf("backward max: %.6g (%zu samples)\n", sd.backward.max, sd.backward.n_samples());
        std::printf("Hausdorff:    %.6g = %.4f%% of the diagonal %.6g\n", sd.hausdorff, 100.0 * sd.relative_hausdorff(),
                    sd.diagonal);
    } catch (const meshdiff::Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
