#include "meshdiff/sampling.h"

#include "meshdiff/error.h"

#include <Eigen/Geometry>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

namespace meshdiff {

namespace {

struct Edge
{
    std::uint32_t a, b, face;
};

// Unique undirected edges (a < b), sorted by (a, b); each with the lowest face
// that has it. Edges of faces with a repeated corner are skipped if a == b.
std::vector<Edge> unique_edges(const Mesh& mesh)
{
    std::vector<Edge> edges;
    edges.reserve(3 * mesh.n_faces());
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const Face& t = mesh.faces[f];
        for (int k = 0; k < 3; ++k) {
            auto a = std::uint32_t(t[std::size_t(k)]);
            auto b = std::uint32_t(t[std::size_t((k + 1) % 3)]);
            if (a == b) continue;
            if (a > b) std::swap(a, b);
            edges.push_back({a, b, std::uint32_t(f)});
        }
    }
    std::sort(edges.begin(), edges.end(),
              [](const Edge& x, const Edge& y) { return std::tie(x.a, x.b, x.face) < std::tie(y.a, y.b, y.face); });
    edges.erase(
        std::unique(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) { return x.a == y.a && x.b == y.b; }),
        edges.end());
    return edges;
}

// Uniform double in [0, 1) from the top 53 bits (the same on every platform,
// unlike std::uniform_real_distribution).
double unit_double(std::mt19937_64& rng)
{
    return double(rng() >> 11) * 0x1.0p-53;
}

// Largest k with k (k + 1) / 2 <= n.
std::size_t lattice_order(std::size_t n)
{
    auto k = std::size_t((std::sqrt(8.0 * double(n) + 1.0) - 1.0) / 2.0);
    while (k * (k + 1) / 2 > n) --k;
    while ((k + 1) * (k + 2) / 2 <= n) ++k;
    return k;
}

}  // namespace

void validate(const SamplingOptions& options)
{
    if (!options.vertices && !options.edges && !options.faces)
        throw InvalidArgumentError("SamplingOptions: vertices, edges and faces are all off; enable at least one");
    if (options.samples && options.density)
        throw InvalidArgumentError("SamplingOptions: samples and density are both set; set at most one");
    if (options.samples && *options.samples == 0)
        throw InvalidArgumentError("SamplingOptions: samples must be positive, got 0");
    if (options.density && !(std::isfinite(*options.density) && *options.density > 0.0))
        throw InvalidArgumentError(
            fmt::format("SamplingOptions: density must be finite and positive, got {}", *options.density));
}

std::size_t sample_target(const Mesh& mesh, const SamplingOptions& options, std::size_t default_target)
{
    if (options.samples) return *options.samples;
    if (options.density) {
        const auto degenerate = degenerate_face_mask(mesh);
        double area = 0.0;
        for (std::size_t f = 0; f < mesh.n_faces(); ++f)
            if (!degenerate[f]) area += 0.5 * face_cross(mesh, f).norm();
        return std::size_t(std::llround(*options.density * area));
    }
    return default_target;
}

SurfaceSamples sample_surface(const Mesh& mesh, const SamplingOptions& options)
{
    validate(options);
    validate(mesh, "sample_surface");

    SurfaceSamples s;
    s.target = sample_target(mesh, options, 10 * mesh.n_faces());

    const auto degenerate = degenerate_face_mask(mesh);
    std::vector<double> face_area(mesh.n_faces(), 0.0);
    double area = 0.0;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        if (!degenerate[f]) area += face_area[f] = 0.5 * face_cross(mesh, f).norm();

    auto add = [&s](const Vec3& p, SampleKind kind, std::size_t element) {
        s.points.push_back(p);
        s.kind.push_back(kind);
        s.element.push_back(std::uint32_t(element));
    };

    // Vertices: every referenced one, in index order.
    if (options.vertices) {
        std::vector<char> referenced(mesh.n_vertices(), 0);
        for (const Face& t : mesh.faces)
            for (auto v : t) referenced[std::size_t(v)] = 1;
        for (std::size_t v = 0; v < mesh.n_vertices(); ++v)
            if (referenced[v]) add(mesh.points[v], SampleKind::OnVertex, v);
        s.n_vertex = s.points.size();
    }
    if (s.n_vertex >= s.target) return s;
    double remaining = double(s.target - s.n_vertex);

    // Edges: density sqrt(face density) per unit length, with carry-over.
    if (options.edges) {
        const auto edges = unique_edges(mesh);
        double length = 0.0;
        for (const Edge& e : edges) length += (mesh.points[e.b] - mesh.points[e.a]).norm();
        // Never more than the remaining budget (Metro would overshoot here).
        const double cap = length > 0.0 ? remaining / length : 0.0;
        s.edge_density = options.faces && area > 0.0 ? std::min(std::sqrt(remaining / area), cap) : cap;
        double carry = 0.0;
        for (const Edge& e : edges) {
            const Vec3& p0 = mesh.points[e.a];
            const Vec3& p1 = mesh.points[e.b];
            carry += (p1 - p0).norm() * s.edge_density;
            const auto n = std::size_t(carry);
            const Vec3 step = (p1 - p0) / double(n + 1);
            for (std::size_t i = 1; i <= n; ++i) add(p0 + step * double(i), SampleKind::OnEdge, e.face);
            carry -= double(n);
        }
        s.n_edge = s.points.size() - s.n_vertex;
        remaining = std::max(0.0, remaining - double(s.n_edge));
    }

    // Faces.
    if (options.faces && area > 0.0 && remaining > 0.0) {
        s.face_density = remaining / area;
        s.points.reserve(s.points.size() + std::size_t(remaining) + 1);
        s.kind.reserve(s.points.capacity());
        s.element.reserve(s.points.capacity());
        std::mt19937_64 rng(options.seed);
        double carry = 0.0;
        for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
            if (degenerate[f]) continue;
            carry += face_area[f] * s.face_density;
            const auto due = std::size_t(carry);
            if (due == 0) continue;
            const Face& t = mesh.faces[f];
            const Vec3& v0 = mesh.points[std::size_t(t[0])];
            const Vec3& v1 = mesh.points[std::size_t(t[1])];
            const Vec3& v2 = mesh.points[std::size_t(t[2])];
            if (options.face_scheme == FaceSampling::SimilarTriangles) {
                // Interior points of the lattice of step 1/(k+2) along both edges.
                const std::size_t k = lattice_order(due);
                const Vec3 e1 = (v1 - v0) / double(k + 2);
                const Vec3 e2 = (v2 - v0) / double(k + 2);
                for (std::size_t i = 1; i <= k; ++i)
                    for (std::size_t j = 1; i + j <= k + 1; ++j)
                        add(v0 + e1 * double(i) + e2 * double(j), SampleKind::OnFace, f);
                carry -= double(k * (k + 1) / 2);
            } else {
                const Vec3 e1 = v1 - v0;
                const Vec3 e2 = v2 - v0;
                for (std::size_t i = 0; i < due; ++i) {
                    double r1 = unit_double(rng);
                    double r2 = unit_double(rng);
                    if (r1 + r2 > 1.0) {
                        r1 = 1.0 - r1;
                        r2 = 1.0 - r2;
                    }
                    add(v0 + e1 * r1 + e2 * r2, SampleKind::OnFace, f);
                }
                carry -= double(due);
            }
        }
        s.n_face = s.points.size() - s.n_vertex - s.n_edge;
    }
    return s;
}

}  // namespace meshdiff
