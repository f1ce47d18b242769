#include "meshdiff/studies/shapes.h"

#include "meshdiff/core/tolerances.h"
#include "meshdiff/error.h"
#include "studies/random.h"

#include <fmt/format.h>
#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <string>
#include <unordered_map>

namespace meshdiff {

namespace {

// Uniform in [-1, 1) from one raw output (studies/random.h, shared with noise.cpp).
using detail::uniform_pm1;

void require(bool ok, const char* function, const char* field, const std::string& what)
{
    if (!ok) throw InvalidArgumentError(fmt::format("{}: {} {}", function, field, what));
}

void require_positive(double value, const char* function, const char* field)
{
    require(std::isfinite(value) && value > 0, function, field, fmt::format("must be > 0 (got {})", value));
}

void require_subdivisions(int subdivisions, const char* function)
{
    require(subdivisions >= 0 && subdivisions <= 8, function, "subdivisions",
            fmt::format("must be in 0..8 (got {})", subdivisions));
}

// Unit icosphere, faces counter-clockwise seen from outside.
Mesh unit_icosphere(int subdivisions)
{
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    Mesh m;
    m.points = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (auto& p : m.points) p.normalize();
    m.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
               {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    // Make the orientation outward whatever the table says.
    for (auto& f : m.faces) {
        const Vec3& a = m.points[std::size_t(f[0])];
        const Vec3& b = m.points[std::size_t(f[1])];
        const Vec3& c = m.points[std::size_t(f[2])];
        if ((b - a).cross(c - a).dot(a + b + c) < 0) std::swap(f[1], f[2]);
    }
    for (int s = 0; s < subdivisions; ++s) {
        std::unordered_map<std::uint64_t, std::int32_t> midpoint;
        midpoint.reserve(m.faces.size() * 2);
        auto mid = [&](std::int32_t a, std::int32_t b) {
            const auto lo = std::uint64_t(std::min(a, b)), hi = std::uint64_t(std::max(a, b));
            const std::uint64_t key = (lo << 32) | hi;
            auto it = midpoint.find(key);
            if (it != midpoint.end()) return it->second;
            const auto idx = std::int32_t(m.points.size());
            m.points.push_back((m.points[std::size_t(a)] + m.points[std::size_t(b)]).normalized());
            midpoint.emplace(key, idx);
            return idx;
        };
        std::vector<Face> faces;
        faces.reserve(4 * m.faces.size());
        for (const Face& f : m.faces) {
            const std::int32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
            faces.push_back({f[0], ab, ca});
            faces.push_back({f[1], bc, ab});
            faces.push_back({f[2], ca, bc});
            faces.push_back({ab, bc, ca});
        }
        m.faces = std::move(faces);
    }
    return m;
}

// Unit geodesic sphere of class I and the given frequency f: every face of
// the icosahedron of unit_icosphere(0) is cut into f^2 triangles by a regular
// barycentric grid whose points are projected onto the sphere. Edge points are
// shared between the two faces of an edge, so the mesh is closed.
Mesh unit_geodesic_sphere(int f)
{
    const Mesh ico = unit_icosphere(0);
    Mesh m;
    m.points = ico.points;
    // Points inside the icosahedron's edges: f - 1 per edge, from the lower index to the higher.
    std::unordered_map<std::uint64_t, std::int32_t> edge_base;
    auto key = [](std::int32_t a, std::int32_t b) {
        return (std::uint64_t(std::min(a, b)) << 32) | std::uint64_t(std::max(a, b));
    };
    for (const Face& t : ico.faces)
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
            if (!edge_base.emplace(key(a, b), std::int32_t(m.points.size())).second) continue;
            const std::int32_t lo = std::min(a, b), hi = std::max(a, b);
            for (int i = 1; i < f; ++i)
                m.points.push_back(
                    ((f - i) * ico.points[std::size_t(lo)] + i * ico.points[std::size_t(hi)]).normalized());
        }
    // Index of the point i steps from u towards v on edge (u, v).
    auto on_edge = [&](std::int32_t u, std::int32_t v, int i) -> std::int32_t {
        if (i == 0) return u;
        if (i == f) return v;
        const std::int32_t base = edge_base.at(key(u, v));
        return u < v ? base + i - 1 : base + (f - i) - 1;
    };
    for (const Face& t : ico.faces) {
        const Vec3 &A = ico.points[std::size_t(t[0])], &B = ico.points[std::size_t(t[1])],
                   &C = ico.points[std::size_t(t[2])];
        // Grid point (i, j) = ((f - i - j) A + i B + j C) / f.
        std::vector<std::int32_t> interior(std::size_t(f + 1) * std::size_t(f + 1), -1);
        auto id = [&](int i, int j) -> std::int32_t {
            if (j == 0) return on_edge(t[0], t[1], i);
            if (i == 0) return on_edge(t[0], t[2], j);
            if (i + j == f) return on_edge(t[1], t[2], j);
            std::int32_t& slot = interior[std::size_t(i) * std::size_t(f + 1) + std::size_t(j)];
            if (slot < 0) {
                slot = std::int32_t(m.points.size());
                m.points.push_back(((f - i - j) * A + i * B + j * C).normalized());
            }
            return slot;
        };
        for (int i = 0; i < f; ++i)
            for (int j = 0; i + j < f; ++j) {
                m.faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
                if (i + j + 2 <= f) m.faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            }
    }
    return m;
}

// A grid of nu x nv parameter points (s, t), vertex index i * nv + j, with
// quads (i, j) (i+1, j) (i+1, j+1) (i, j+1) counter-clockwise in the (s, t)
// plane. Periodic directions wrap around (then the grid has nu, resp. nv,
// cells in that direction instead of nu - 1). When \p rng is given, quads are
// split along a random diagonal, otherwise always along (i, j)-(i+1, j+1).
std::vector<Face> grid_faces(int nu, int nv, bool periodic_u, bool periodic_v, std::mt19937_64* rng)
{
    const int cu = periodic_u ? nu : nu - 1;
    const int cv = periodic_v ? nv : nv - 1;
    std::vector<Face> faces;
    faces.reserve(2 * std::size_t(cu) * std::size_t(cv));
    for (int i = 0; i < cu; ++i)
        for (int j = 0; j < cv; ++j) {
            const int i1 = (i + 1) % nu, j1 = (j + 1) % nv;
            const std::int32_t a = i * nv + j, b = i1 * nv + j, c = i1 * nv + j1, d = i * nv + j1;
            const bool other = rng && ((*rng)() >> 63) != 0;
            if (!other) {
                faces.push_back({a, b, c});
                faces.push_back({a, c, d});
            } else {
                faces.push_back({a, b, d});
                faces.push_back({b, c, d});
            }
        }
    return faces;
}

// Torus point and exact H at parameters (u, v).
Vec3 torus_point(double u, double v, double R, double r)
{
    const double w = R + r * std::cos(v);
    return {w * std::cos(u), w * std::sin(u), r * std::sin(v)};
}

double torus_mean_curvature(double v, double R, double r)
{
    const double c = std::cos(v);
    return (R + 2 * r * c) / (2 * r * (R + r * c));
}

void require_torus(double R, double r, const char* function)
{
    require_positive(R, function, "R");
    require_positive(r, function, "r");
    require(r < R, function, "r", fmt::format("must be < R (got r = {}, R = {})", r, R));
}

// Gaussian g(x, y; s) = exp(-(x^2 + y^2) / (2 s^2)) with derivatives.
struct Jet
{
    double f = 0, fx = 0, fy = 0, fxx = 0, fxy = 0, fyy = 0;
    void add(const Jet& o, double w)
    {
        f += w * o.f;
        fx += w * o.fx;
        fy += w * o.fy;
        fxx += w * o.fxx;
        fxy += w * o.fxy;
        fyy += w * o.fyy;
    }
};

Jet gaussian(double x, double y, double s)
{
    const double s2 = s * s, s4 = s2 * s2;
    const double g = std::exp(-(x * x + y * y) / (2 * s2));
    Jet j;
    j.f = g;
    j.fx = -x / s2 * g;
    j.fy = -y / s2 * g;
    j.fxx = (x * x / s4 - 1 / s2) * g;
    j.fyy = (y * y / s4 - 1 / s2) * g;
    j.fxy = x * y / s4 * g;
    return j;
}

Jet height_jet(double x, double y, double amplitude)
{
    Jet h;
    h.add(gaussian(x - 0.3, y - 0.2, 0.35), 0.3);
    h.add(gaussian(x + 0.4, y + 0.35, 0.25), -0.2);
    Jet w;
    const double s2 = std::sin(2 * x), c2 = std::cos(2 * x), s3 = std::sin(3 * y), c3 = std::cos(3 * y);
    w.f = s2 * c3;
    w.fx = 2 * c2 * c3;
    w.fy = -3 * s2 * s3;
    w.fxx = -4 * s2 * c3;
    w.fyy = -9 * s2 * c3;
    w.fxy = -6 * c2 * s3;
    h.add(w, 0.05);
    Jet out;
    out.add(h, amplitude);
    return out;
}

Shape lift_heightfield(std::vector<Vec3> xy, std::vector<Face> faces, double amplitude)
{
    Shape s;
    s.exact_H.resize(xy.size());
    for (std::size_t k = 0; k < xy.size(); ++k) {
        xy[k].z() = heightfield_z(xy[k].x(), xy[k].y(), amplitude);
        s.exact_H[k] = heightfield_H(xy[k].x(), xy[k].y(), amplitude);
    }
    s.mesh.points = std::move(xy);
    s.mesh.faces = std::move(faces);
    return s;
}

void require_amplitude(double amplitude, const char* function)
{
    require(std::isfinite(amplitude), function, "amplitude", fmt::format("must be finite (got {})", amplitude));
}

}  // namespace

Shape icosphere(int subdivisions, double radius)
{
    require_subdivisions(subdivisions, "icosphere");
    require_positive(radius, "icosphere", "radius");
    Shape s;
    s.mesh = unit_icosphere(subdivisions);
    for (auto& p : s.mesh.points) p *= radius;
    s.exact_H.assign(s.mesh.n_vertices(), 1.0 / radius);
    return s;
}

Shape geodesic_sphere(int frequency, double radius)
{
    require(frequency >= 1 && frequency <= 1024, "geodesic_sphere", "frequency",
            fmt::format("must be in 1..1024 (got {})", frequency));
    require_positive(radius, "geodesic_sphere", "radius");
    Shape s;
    s.mesh = unit_geodesic_sphere(frequency);
    for (auto& p : s.mesh.points) p *= radius;
    s.exact_H.assign(s.mesh.n_vertices(), 1.0 / radius);
    return s;
}

Shape uv_sphere(int n_longitude, int n_latitude, double radius)
{
    require(n_longitude >= 3, "uv_sphere", "n_longitude", fmt::format("must be >= 3 (got {})", n_longitude));
    require(n_latitude >= 2, "uv_sphere", "n_latitude", fmt::format("must be >= 2 (got {})", n_latitude));
    require_positive(radius, "uv_sphere", "radius");
    Shape s;
    Mesh& m = s.mesh;
    const int rings = n_latitude - 1;
    m.points.reserve(std::size_t(n_longitude) * std::size_t(rings) + 2);
    m.points.emplace_back(0.0, 0.0, radius);  // north pole, index 0
    for (int k = 1; k <= rings; ++k) {
        const double theta = kPi * k / n_latitude;
        for (int j = 0; j < n_longitude; ++j) {
            const double phi = 2 * kPi * j / n_longitude;
            m.points.emplace_back(radius * std::sin(theta) * std::cos(phi), radius * std::sin(theta) * std::sin(phi),
                                  radius * std::cos(theta));
        }
    }
    const auto south = std::int32_t(m.points.size());
    m.points.emplace_back(0.0, 0.0, -radius);
    auto ring = [&](int k, int j) { return std::int32_t(1 + (k - 1) * n_longitude + (j % n_longitude)); };
    // (east, north) is counter-clockwise seen from outside.
    for (int j = 0; j < n_longitude; ++j) m.faces.push_back({0, ring(1, j), ring(1, j + 1)});
    for (int k = 1; k < rings; ++k)
        for (int j = 0; j < n_longitude; ++j) {
            const std::int32_t a = ring(k, j), b = ring(k, j + 1), c = ring(k + 1, j), d = ring(k + 1, j + 1);
            m.faces.push_back({c, d, b});
            m.faces.push_back({c, b, a});
        }
    for (int j = 0; j < n_longitude; ++j) m.faces.push_back({south, ring(rings, j + 1), ring(rings, j)});
    s.exact_H.assign(m.n_vertices(), 1.0 / radius);
    return s;
}

Shape torus(int n_major, int n_minor, double R, double r)
{
    require(n_major >= 3, "torus", "n_major", fmt::format("must be >= 3 (got {})", n_major));
    require(n_minor >= 3, "torus", "n_minor", fmt::format("must be >= 3 (got {})", n_minor));
    require_torus(R, r, "torus");
    Shape s;
    s.mesh.points.reserve(std::size_t(n_major) * std::size_t(n_minor));
    s.exact_H.reserve(std::size_t(n_major) * std::size_t(n_minor));
    for (int i = 0; i < n_major; ++i)
        for (int j = 0; j < n_minor; ++j) {
            const double u = 2 * kPi * i / n_major, v = 2 * kPi * j / n_minor;
            s.mesh.points.push_back(torus_point(u, v, R, r));
            s.exact_H.push_back(torus_mean_curvature(v, R, r));
        }
    s.mesh.faces = grid_faces(n_major, n_minor, true, true, nullptr);
    return s;
}

Shape ellipsoid(int subdivisions, double a, double b, double c)
{
    require_subdivisions(subdivisions, "ellipsoid");
    return ellipsoid(unit_icosphere(subdivisions), a, b, c);
}

Shape ellipsoid(const Mesh& unit_sphere, double a, double b, double c)
{
    require_positive(a, "ellipsoid", "a");
    require_positive(b, "ellipsoid", "b");
    require_positive(c, "ellipsoid", "c");
    Shape s;
    s.mesh = unit_sphere;
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    s.exact_H.reserve(s.mesh.n_vertices());
    for (auto& p : s.mesh.points) {
        p = Vec3(a * p.x(), b * p.y(), c * p.z());
        const double x = p.x(), y = p.y(), z = p.z();
        const double q = x * x / (a2 * a2) + y * y / (b2 * b2) + z * z / (c2 * c2);
        s.exact_H.push_back(std::abs(x * x + y * y + z * z - a2 - b2 - c2) / (2 * a2 * b2 * c2 * q * std::sqrt(q)));
    }
    return s;
}

Shape plane_grid(int nx, int ny, double spacing)
{
    require(nx >= 2, "plane_grid", "nx", fmt::format("must be >= 2 (got {})", nx));
    require(ny >= 2, "plane_grid", "ny", fmt::format("must be >= 2 (got {})", ny));
    require_positive(spacing, "plane_grid", "spacing");
    Shape s;
    // grid_faces indexes i * nv + j; with i along y and j along x we get the
    // documented index j_y * nx + i_x, but then (s, t) = (y, x) is clockwise
    // seen from +z, so the faces are reversed below.
    const double x0 = -0.5 * (nx - 1) * spacing, y0 = -0.5 * (ny - 1) * spacing;
    for (int iy = 0; iy < ny; ++iy)
        for (int ix = 0; ix < nx; ++ix) s.mesh.points.emplace_back(x0 + ix * spacing, y0 + iy * spacing, 0.0);
    s.mesh.faces = grid_faces(ny, nx, false, false, nullptr);
    for (auto& f : s.mesh.faces) std::swap(f[1], f[2]);
    s.exact_H.assign(s.mesh.n_vertices(), 0.0);
    return s;
}

Shape noisy_sphere(int subdivisions, double noise_fraction, std::uint64_t seed, double radius)
{
    require_subdivisions(subdivisions, "noisy_sphere");
    require_positive(radius, "noisy_sphere", "radius");
    return noisy_sphere(icosphere(subdivisions, radius), noise_fraction, seed);
}

Shape noisy_sphere(Shape sphere, double noise_fraction, std::uint64_t seed)
{
    require(std::isfinite(noise_fraction) && noise_fraction >= 0 && noise_fraction < 1, "noisy_sphere",
            "noise_fraction", fmt::format("must be in [0, 1) (got {})", noise_fraction));
    std::mt19937_64 rng(seed);
    for (auto& p : sphere.mesh.points) p *= 1.0 + noise_fraction * uniform_pm1(rng);
    return sphere;
}

Shape torus_irregular(std::size_t approx_vertices, double R, double r, std::uint64_t seed)
{
    require(approx_vertices >= 9 && approx_vertices <= (std::size_t(1) << 26), "torus_irregular", "approx_vertices",
            fmt::format("must be in 9..2^26 (got {})", approx_vertices));
    require_torus(R, r, "torus_irregular");
    const double n = double(approx_vertices);
    const int n_minor = std::max(3, int(std::lround(std::sqrt(n * r / R))));
    const int n_major = std::max(3, int(std::lround(n / n_minor)));
    std::mt19937_64 rng(seed);
    Shape s;
    const std::size_t count = std::size_t(n_major) * std::size_t(n_minor);
    s.mesh.points.reserve(count);
    s.exact_H.reserve(count);
    constexpr double jitter = 0.2;  // cells; keeps each parameter quad convex
    for (int i = 0; i < n_major; ++i)
        for (int j = 0; j < n_minor; ++j) {
            const double du = jitter * uniform_pm1(rng), dv = jitter * uniform_pm1(rng);
            const double u = 2 * kPi * (i + du) / n_major, v = 2 * kPi * (j + dv) / n_minor;
            s.mesh.points.push_back(torus_point(u, v, R, r));
            s.exact_H.push_back(torus_mean_curvature(v, R, r));
        }
    s.mesh.faces = grid_faces(n_major, n_minor, true, true, &rng);
    return s;
}

double heightfield_z(double x, double y, double amplitude)
{
    return height_jet(x, y, amplitude).f;
}

double heightfield_H(double x, double y, double amplitude)
{
    const Jet h = height_jet(x, y, amplitude);
    const double w2 = 1 + h.fx * h.fx + h.fy * h.fy;
    return -((1 + h.fy * h.fy) * h.fxx - 2 * h.fx * h.fy * h.fxy + (1 + h.fx * h.fx) * h.fyy) /
           (2 * w2 * std::sqrt(w2));
}

Shape heightfield(int n, double amplitude)
{
    require(n >= 2, "heightfield", "n", fmt::format("must be >= 2 (got {})", n));
    require_amplitude(amplitude, "heightfield");
    Shape grid = plane_grid(n, n, 2.0 / (n - 1));
    return lift_heightfield(std::move(grid.mesh.points), std::move(grid.mesh.faces), amplitude);
}

Shape heightfield_irregular(std::size_t approx_vertices, std::uint64_t seed, double amplitude)
{
    require(approx_vertices >= 4 && approx_vertices <= (std::size_t(1) << 26), "heightfield_irregular",
            "approx_vertices", fmt::format("must be in 4..2^26 (got {})", approx_vertices));
    require_amplitude(amplitude, "heightfield_irregular");
    const int n = std::max(2, int(std::lround(std::sqrt(double(approx_vertices)))));
    const double h = 2.0 / (n - 1);
    constexpr double jitter = 0.2;  // cells; keeps each quad convex
    std::mt19937_64 rng(seed);
    std::vector<Vec3> xy;
    xy.reserve(std::size_t(n) * std::size_t(n));
    // Index iy * n + ix as plane_grid; faces from grid_faces(i = iy, j = ix), reversed.
    for (int iy = 0; iy < n; ++iy)
        for (int ix = 0; ix < n; ++ix) {
            const double dx = jitter * uniform_pm1(rng), dy = jitter * uniform_pm1(rng);
            const bool inner_x = ix > 0 && ix<n - 1, inner_y = iy> 0 && iy < n - 1;
            const double x = -1.0 + h * (ix + (inner_x ? dx : 0.0));
            const double y = -1.0 + h * (iy + (inner_y ? dy : 0.0));
            xy.emplace_back(ix == n - 1 ? 1.0 : x, iy == n - 1 ? 1.0 : y, 0.0);
        }
    std::vector<Face> faces = grid_faces(n, n, false, false, &rng);
    for (auto& f : faces) std::swap(f[1], f[2]);
    return lift_heightfield(std::move(xy), std::move(faces), amplitude);
}

}  // namespace meshdiff
