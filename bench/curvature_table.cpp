// Prints the accuracy table of the mean curvature estimators (METHOD.md
// section 4) on analytic surfaces, and their stability on real meshes.
// Usage: meshdiff_curvature_table [MESH_DIR]   (MESH_DIR: ../shared/data/meshes)
#include "meshdiff/io/io.h"
#include "meshdiff/roughness/curvature.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/studies/shapes.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace meshdiff;

namespace {

struct Estimator
{
    std::string name;
    CurvatureOptions options;
};

std::vector<Estimator> estimators()
{
    std::vector<Estimator> e;
    CurvatureOptions o;
    e.push_back({"cubic", o});
    o.weighting = RowWeighting::InverseSquare;
    e.push_back({"cubic w", o});
    o.weighting = RowWeighting::None;
    o.method = CurvatureMethod::Quadric;
    e.push_back({"quadric", o});
    o.method = CurvatureMethod::MeyerCotangent;
    e.push_back({"meyer", o});
    return e;
}

CurvatureError error_of(const Shape& s, const CurvatureOptions& o, bool skip_boundary)
{
    return curvature_error(mean_curvature(s.mesh, o).H, s.exact_H,
                           skip_boundary ? boundary_vertex_mask(s.mesh) : std::vector<char>{});
}

}  // namespace

int main(int argc, char** argv)
{
    const std::string dir = argc > 1 ? argv[1] : "../shared/data/meshes";
    const auto ests = estimators();
    struct Case
    {
        std::string name;
        Shape shape;
        bool skip_boundary;
    };
    std::vector<Case> cases;
    for (int k = 2; k <= 5; ++k) cases.push_back({fmt::format("icosphere k={}", k), icosphere(k), false});
    for (int n : {16, 32, 64}) cases.push_back({fmt::format("uv sphere {}x{}", 2 * n, n), uv_sphere(2 * n, n), false});
    for (int n : {32, 64, 128})
        cases.push_back({fmt::format("torus {}x{}", n, n / 4 * 2), torus(n, n / 4 * 2, 1.0, 0.25), false});
    for (std::size_t n : {1000u, 4000u, 16000u})
        cases.push_back({fmt::format("torus irregular ~{}", n), torus_irregular(n, 1.0, 0.25, 1), false});
    for (int k = 2; k <= 5; ++k)
        cases.push_back({fmt::format("ellipsoid 1.5:1:1 k={}", k), ellipsoid(k, 1.5, 1.0, 1.0), false});
    for (int n : {33, 65, 129}) cases.push_back({fmt::format("height field {}^2", n), heightfield(n), true});
    for (std::size_t n : {1000u, 4000u, 16000u})
        cases.push_back({fmt::format("height field irregular ~{}", n), heightfield_irregular(n, 1), true});

    fmt::print("## H error on analytic surfaces (RMS / max of |H - H_exact|, interior vertices)\n\n");
    fmt::print("| surface | vertices |");
    for (const auto& e : ests) fmt::print(" {} |", e.name);
    fmt::print("\n|---|---|");
    for (std::size_t i = 0; i < ests.size(); ++i) fmt::print("---|");
    fmt::print("\n");
    for (const auto& c : cases) {
        fmt::print("| {} | {} |", c.name, c.shape.mesh.n_vertices());
        for (const auto& e : ests) {
            const CurvatureError err = error_of(c.shape, e.options, c.skip_boundary);
            fmt::print(" {:.2e} / {:.2e}{} |", err.rms, err.max,
                       err.undefined ? fmt::format(" ({} undef)", err.undefined) : "");
        }
        fmt::print("\n");
    }

    fmt::print("\n## Stability on real meshes (sigma_1 / max |H| / top-0.1% share of sigma_1^2, unit-scaled mesh)\n\n");
    fmt::print("| mesh | vertices |");
    for (const auto& e : ests) fmt::print(" {} |", e.name);
    fmt::print("\n|---|---|");
    for (std::size_t i = 0; i < ests.size(); ++i) fmt::print("---|");
    fmt::print("\n");
    for (const char* name :
         {"bunny_closed.ply", "bunny.ply", "igea.ply", "rocker_arm.ply", "fandisk.ply", "armadillo.ply",
          "camelhead.ply", "face_neutral.ply", "ogre.ply", "teapot.obj", "bunny_res2.ply", "bunny_scan_bun000.ply"}) {
        const auto path = std::filesystem::path(dir) / name;
        if (!std::filesystem::exists(path)) continue;
        const Mesh mesh = read_mesh(path).mesh;
        fmt::print("| {} | {} |", name, mesh.n_vertices());
        for (const auto& e : ests) {
            ProfileOptions po;
            po.levels = {1};
            po.global = false;
            po.curvature = e.options;
            po.keep_vertex_data = true;
            const auto p = roughness_profile(mesh, po);
            double hmax = 0;
            for (double h : p.H)
                if (!std::isnan(h)) hmax = std::max(hmax, std::abs(h));
            fmt::print(" {:.3g} / {:.3g} / {:.0f}%{} |", p.levels[0].sigma, hmax, 100 * p.levels[0].top_share,
                       p.curvature_undefined ? fmt::format(" ({} undef)", p.curvature_undefined) : "");
        }
        fmt::print("\n");
    }
    return 0;
}
