#include "meshdiff/signed_distance.h"

#include "meshdiff/error.h"
#include "meshdiff/topology.h"

#include "detail/compensated_sum.h"
#include "detail/point_triangle.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace meshdiff {

namespace {

constexpr double kPi = 3.14159265358979323846;

ClosestFeature feature(const Vec3& point, FeatureKind kind, int index)
{
    return {point, kind, std::uint8_t(index)};
}

// detail::segment_point() with the region: corner u, corner v or the edge.
ClosestFeature segment_feature(const Vec3& p, const Vec3& a, const Vec3& b, int ia, int ib, int edge)
{
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    if (!(len2 > 0.0)) return feature(a, FeatureKind::Vertex, ia);
    const double t = ab.dot(p - a) / len2;
    if (t <= 0.0) return feature(a, FeatureKind::Vertex, ia);
    if (t >= 1.0) return feature(b, FeatureKind::Vertex, ib);
    return feature(a + t * ab, FeatureKind::Edge, edge);
}

// detail::thin_triangle_point() with the region.
ClosestFeature thin_feature(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    ClosestFeature best = segment_feature(p, a, b, 0, 1, 0);
    double best_d2 = (p - best.point).squaredNorm();
    const ClosestFeature bc = segment_feature(p, b, c, 1, 2, 1);
    const double d_bc = (p - bc.point).squaredNorm();
    if (d_bc < best_d2) {
        best_d2 = d_bc;
        best = bc;
    }
    const ClosestFeature ca = segment_feature(p, c, a, 2, 0, 2);
    if ((p - ca.point).squaredNorm() < best_d2) best = ca;
    return best;
}

// detail::triangle_point() with the region, branch for branch.
ClosestFeature face_feature(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    const Vec3 ap = p - a;
    const double d1 = ab.dot(ap);
    const double d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return feature(a, FeatureKind::Vertex, 0);

    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp);
    const double d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return feature(b, FeatureKind::Vertex, 1);

    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return feature(a + (d1 / (d1 - d3)) * ab, FeatureKind::Edge, 0);

    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp);
    const double d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return feature(c, FeatureKind::Vertex, 2);

    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return feature(a + (d2 / (d2 - d6)) * ac, FeatureKind::Edge, 2);

    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return feature(b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b), FeatureKind::Edge, 1);

    const Vec3 n = ab.cross(ac);
    return feature(p - (n.dot(ap) / n.squaredNorm()) * n, FeatureKind::Interior, 0);
}

// Angle between u and v, stable for small and large angles.
double angle(const Vec3& u, const Vec3& v)
{
    return std::atan2(u.cross(v).norm(), u.dot(v));
}

}  // namespace

ClosestFeature closest_feature(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    return detail::is_thin_triangle(a, b, c) ? thin_feature(p, a, b, c) : face_feature(p, a, b, c);
}

std::string sign_unavailable_reason(const Mesh& mesh, const std::string& name)
{
    const TopologyReport t = topology_report(mesh);
    auto count = [](std::size_t n, const std::string& what) {
        if (n == 1) return fmt::format("1 {}", what);
        return what.size() > 6 && what.compare(what.size() - 6, 6, "vertex") == 0
                   ? fmt::format("{} {}ices", n, what.substr(0, what.size() - 2))
                   : fmt::format("{} {}s", n, what);
    };
    std::vector<std::string> why;
    if (t.boundary_edges) why.push_back(count(t.boundary_edges, "boundary edge"));
    if (t.non_manifold_edges) why.push_back(count(t.non_manifold_edges, "non-manifold edge"));
    if (t.non_manifold_vertices) why.push_back(count(t.non_manifold_vertices, "non-manifold vertex"));
    if (t.orientation_conflicts)
        why.push_back(count(t.orientation_conflicts, "edge") + " with inconsistent orientation");
    if (t.degenerate_faces) why.push_back(count(t.degenerate_faces, "degenerate face"));
    if (why.empty()) return {};
    std::string s = name + " has ";
    for (std::size_t i = 0; i < why.size(); ++i) s += (i == 0 ? "" : (i + 1 == why.size() ? " and " : ", ")) + why[i];
    return s + " (the sign needs a closed, manifold, consistently oriented mesh without degenerate faces)";
}

std::optional<PseudoNormals> pseudo_normals(const Mesh& mesh, const std::string& name, std::string* reason)
{
    std::string why = sign_unavailable_reason(mesh, name);
    const std::size_t nf = mesh.n_faces();
    PseudoNormals n;
    if (why.empty()) {
        detail::CompensatedSum volume;
        for (std::size_t f = 0; f < nf; ++f) {
            const Face& t = mesh.faces[f];
            const Vec3& a = mesh.points[std::size_t(t[0])];
            volume.add(a.dot(face_cross(mesh, f)) / 6.0);
        }
        n.volume = volume.value();
        // A closed mesh of zero volume (two coinciding sheets, say) has no inside.
        const double diag = bounding_box(mesh).diagonal();
        if (!(std::abs(n.volume) > 1e-12 * diag * diag * diag))
            why = fmt::format("{} encloses no volume (signed volume {:.6g})", name, n.volume);
    }
    if (!why.empty()) {
        if (reason) *reason = why;
        return std::nullopt;
    }
    n.flipped = n.volume < 0.0;
    const double s = n.flipped ? -1.0 : 1.0;
    n.face.resize(nf);
    for (std::size_t f = 0; f < nf; ++f) n.face[f] = s * face_cross(mesh, f).normalized();
    n.vertex.assign(mesh.n_vertices(), Vec3::Zero());
    // Edges: the directed half-edges (a, b) of each face, sorted by their
    // undirected key; a closed manifold mesh has each key exactly twice.
    struct HalfEdge
    {
        std::uint32_t lo, hi, face;
        std::uint8_t slot;
    };
    std::vector<HalfEdge> half(3 * nf);
    for (std::size_t f = 0; f < nf; ++f) {
        const Face& t = mesh.faces[f];
        for (int k = 0; k < 3; ++k) {
            const auto u = std::uint32_t(t[std::size_t(k)]), v = std::uint32_t(t[std::size_t((k + 1) % 3)]);
            half[3 * f + std::size_t(k)] = {std::min(u, v), std::max(u, v), std::uint32_t(f), std::uint8_t(k)};
            const Vec3& p = mesh.points[u];
            const Vec3& q = mesh.points[v];
            const Vec3& r = mesh.points[std::size_t(t[std::size_t((k + 2) % 3)])];
            n.vertex[u] += angle(q - p, r - p) * n.face[f];
        }
    }
    std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return std::tie(x.lo, x.hi, x.face, x.slot) < std::tie(y.lo, y.hi, y.face, y.slot);
    });
    n.edge.resize(nf);
    for (std::size_t i = 0; i + 1 < half.size(); i += 2) {
        const HalfEdge& x = half[i];
        const HalfEdge& y = half[i + 1];
        if (x.lo != y.lo || x.hi != y.hi)
            throw std::logic_error(fmt::format("pseudo_normals: edge ({}, {}) has one face", x.lo, x.hi));
        const Vec3 e = n.face[x.face] + n.face[y.face];
        n.edge[x.face][x.slot] = e;
        n.edge[y.face][y.slot] = e;
    }
    return n;
}

int distance_sign(const Mesh& mesh, const PseudoNormals& normals, const Vec3& p, std::uint32_t face)
{
    const Face& t = mesh.faces[face];
    const ClosestFeature c = closest_feature(p, mesh.points[std::size_t(t[0])], mesh.points[std::size_t(t[1])],
                                             mesh.points[std::size_t(t[2])]);
    const Vec3 d = p - c.point;
    if (d.isZero(0.0)) return 0;
    const Vec3& n = c.kind == FeatureKind::Interior   ? normals.face[face]
                    : c.kind == FeatureKind::Edge ? normals.edge[face][c.index]
                                                  : normals.vertex[std::size_t(t[c.index])];
    const double s = d.dot(n);
    return s > 0.0 ? 1 : (s < 0.0 ? -1 : 0);
}

std::vector<double> signed_distances(const Mesh& mesh, const PseudoNormals& normals, const Vec3* queries,
                                     const double* distances, const std::uint32_t* faces, std::size_t n)
{
    std::vector<double> out(n);
    const auto m = std::int64_t(n);
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < m; ++i) {
        const auto k = std::size_t(i);
        const int s = distances[k] > 0.0 ? distance_sign(mesh, normals, queries[k], faces[k]) : 0;
        out[k] = s == 0 ? 0.0 : double(s) * distances[k];
    }
    return out;
}

double winding_number(const Mesh& mesh, const Vec3& p)
{
    detail::CompensatedSum sum;
    for (const Face& t : mesh.faces) {
        const Vec3 a = mesh.points[std::size_t(t[0])] - p;
        const Vec3 b = mesh.points[std::size_t(t[1])] - p;
        const Vec3 c = mesh.points[std::size_t(t[2])] - p;
        const double la = a.norm(), lb = b.norm(), lc = c.norm();
        const double num = a.dot(b.cross(c));
        const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
        sum.add(2.0 * std::atan2(num, den));
    }
    return sum.value() / (4.0 * kPi);
}

}  // namespace meshdiff
