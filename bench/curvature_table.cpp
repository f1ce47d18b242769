// Prints the accuracy of the mean curvature estimators (METHOD.md section 4)
// on analytic surfaces under refinement (about 1K to 256K vertices, interior
// and boundary vertices apart, with convergence rates; docs/accuracy.md), and
// their stability on real meshes.
// Usage: meshdiff_curvature_table [--steps 1..5] [MESH_DIR]   (MESH_DIR: ../shared/data/meshes;
//        --steps 3 stops at about 16K vertices)
#include "meshdiff/io/io.h"
#include "meshdiff/roughness/curvature.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/studies/shapes.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <random>
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
    o.method = CurvatureMethod::GoldfeatherCubic;
    e.push_back({"cubic", o});
    o.weighting = RowWeighting::InverseSquare;
    e.push_back({"cubic w", o});
    o.weighting = RowWeighting::None;
    o.method = CurvatureMethod::Quadric;
    e.push_back({"quadric", o});
    o.method = CurvatureMethod::MeyerCotangent;
    e.push_back({"meyer", o});
    o.method = CurvatureMethod::Jet;
    e.push_back({"jet", o});
    return e;
}

// The geodesic sphere of frequency f with every vertex moved tangentially by
// up to 0.2 of the mean edge length along each of two tangent directions
// (uniform, seeded; as torus_irregular's jitter, small enough that no
// triangle folds) and put back on the unit sphere: irregular triangle shapes
// and sizes on the same connectivity, exact H still 1.
Mesh jittered_sphere(int f, std::uint64_t seed)
{
    Mesh m = geodesic_sphere(f).mesh;
    double edge = 0.0;
    for (const auto& t : m.faces) edge += (m.points[t[0]] - m.points[t[1]]).norm();
    edge /= double(m.faces.size());
    std::mt19937_64 rng(seed);
    const auto uniform = [&rng] { return double(rng() >> 11) * 0x1.0p-53 * 2.0 - 1.0; };  // [-1, 1)
    for (auto& p : m.points) {
        const Vec3 n = p.normalized();
        const Vec3 u = n.cross(std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY()).normalized();
        const Vec3 w = n.cross(u);
        const double a = uniform(), b = uniform();
        p = (p + 0.2 * edge * (a * u + b * w)).normalized();
    }
    for (const auto& t : m.faces) {
        const Vec3 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
        if (!((b - a).cross(c - a).dot(a + b + c) > 0.0)) {
            fmt::print(stderr, "jittered sphere f = {}: a triangle folded\n", f);
            std::exit(1);
        }
    }
    return m;
}

Shape sphere_from(Mesh m)
{
    Shape s;
    s.exact_H.assign(m.n_vertices(), 1.0);
    s.mesh = std::move(m);
    return s;
}

// One refinement series: a surface at about 1K, 4K, 16K, 64K, 256K vertices.
struct Series
{
    std::string name;
    std::function<Shape(int step)> make;  // step 0..4
};

std::vector<Series> series()
{
    const int geodesic[] = {10, 20, 40, 80, 160};   // 10 f^2 + 2 vertices
    const int torus_n[] = {44, 88, 176, 352, 704};  // n x n / 2 vertices
    const int grid[] = {33, 65, 129, 257, 513};     // n^2 vertices
    const std::size_t approx[] = {1000, 4000, 16000, 64000, 256000};
    return {
        {"sphere, geodesic (regular)", [=](int k) { return geodesic_sphere(geodesic[k]); }},
        {"sphere, icosphere (midpoint subdivision)", [](int k) { return icosphere(k + 3); }},
        {"sphere, jittered geodesic (irregular)", [=](int k) { return sphere_from(jittered_sphere(geodesic[k], 7)); }},
        {"torus R 1 r 0.25, regular grid", [=](int k) { return torus(torus_n[k], torus_n[k] / 2); }},
        {"torus R 1 r 0.25, irregular", [=](int k) { return torus_irregular(approx[k], 1.0, 0.25, 1); }},
        {"ellipsoid 1.5:1:1 of the geodesic sphere (regular)",
         [=](int k) { return ellipsoid(geodesic_sphere(geodesic[k]).mesh, 1.5, 1.0, 1.0); }},
        {"ellipsoid 1.5:1:1 of the jittered sphere (irregular)",
         [=](int k) { return ellipsoid(jittered_sphere(geodesic[k], 7), 1.5, 1.0, 1.0); }},
        {"height field, regular grid", [=](int k) { return heightfield(grid[k]); }},
        {"height field, irregular", [=](int k) { return heightfield_irregular(approx[k], 1); }},
    };
}

// "RMS / max" of a part, with the rates against the previous size
// (log(e_prev / e) / log(h_prev / h), h ~ n^-1/2).
std::string cell(const CurvatureError& e, const CurvatureError* prev, double n, double n_prev)
{
    if (e.compared == 0) return "-";
    std::string c = fmt::format("{:.2e} / {:.2e}", e.rms, e.max);
    if (prev && prev->compared && e.rms > 0 && e.max > 0) {
        const double lh = 0.5 * std::log(n / n_prev);
        c += fmt::format(" ({:.1f}, {:.1f})", std::log(prev->rms / e.rms) / lh, std::log(prev->max / e.max) / lh);
    }
    if (e.undefined) c += fmt::format(" [{} undef]", e.undefined);
    return c;
}

}  // namespace

int main(int argc, char** argv)
{
    std::string dir = "../shared/data/meshes";
    int steps = 5;  // 1K .. 256K
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--steps" && i + 1 < argc)
            steps = std::clamp(std::atoi(argv[++i]), 1, 5);
        else
            dir = a;
    }
    const auto ests = estimators();
    fmt::print(
        "## H error under refinement (RMS / max of |H - H_exact|; in brackets the rates of RMS and max\n"
        "## against the previous row, as powers of h ~ n^-1/2: 2.0 is O(h^2), 0.0 a plateau)\n");
    for (const auto& s : series()) {
        struct Row
        {
            std::size_t n;
            std::vector<CurvatureError> interior, boundary;
        };
        std::vector<Row> rows;
        for (int k = 0; k < steps; ++k) {
            const Shape shape = s.make(k);
            const auto boundary = boundary_vertex_mask(shape.mesh);
            auto interior_skip = boundary;
            for (char& b : interior_skip) b = b ? 0 : 1;
            Row r{shape.mesh.n_vertices(), {}, {}};
            for (const auto& e : ests) {
                const auto H = mean_curvature(shape.mesh, e.options).H;
                r.interior.push_back(curvature_error(H, shape.exact_H, boundary));
                r.boundary.push_back(curvature_error(H, shape.exact_H, interior_skip));
            }
            rows.push_back(std::move(r));
        }
        const bool has_boundary = rows.front().boundary.front().compared + rows.front().boundary.front().undefined > 0;
        for (const bool part_boundary : {false, true}) {
            if (part_boundary && !has_boundary) continue;
            fmt::print("\n### {}{}\n\n| vertices |", s.name,
                       has_boundary ? (part_boundary ? ": boundary vertices" : ": interior vertices") : "");
            for (const auto& e : ests) fmt::print(" {} |", e.name);
            fmt::print("\n|---|");
            for (std::size_t i = 0; i < ests.size(); ++i) fmt::print("---|");
            fmt::print("\n");
            for (std::size_t k = 0; k < rows.size(); ++k) {
                fmt::print("| {} |", rows[k].n);
                for (std::size_t i = 0; i < ests.size(); ++i) {
                    const auto& part = part_boundary ? rows[k].boundary : rows[k].interior;
                    const auto* prev = k ? &(part_boundary ? rows[k - 1].boundary : rows[k - 1].interior)[i] : nullptr;
                    fmt::print(" {} |", cell(part[i], prev, double(rows[k].n), k ? double(rows[k - 1].n) : 0.0));
                }
                fmt::print("\n");
            }
        }
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
