#include "meshdiff/distance/signed_distance.h"

#include "meshdiff/core/tolerances.h"
#include "meshdiff/core/topology.h"
#include "meshdiff/error.h"

#include "core/compensated_sum.h"
#include "core/edge_map_parts.h"
#include "core/face_corner.h"
#include "distance/signed_query.h"
#include "geometry/bvh_build.h"
#include "geometry/point_triangle_kernels.h"
#include "geometry/point_triangle_x4.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace meshdiff {

namespace {

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

// The feature of region r (detail::kRegionA ..., point_triangle_x4.h) at
// point q: the numbering of face_feature().
ClosestFeature kernel_feature(const Vec3& q, unsigned r)
{
    switch (r) {
        case detail::kRegionA:
            return feature(q, FeatureKind::Vertex, 0);
        case detail::kRegionB:
            return feature(q, FeatureKind::Vertex, 1);
        case detail::kRegionAB:
            return feature(q, FeatureKind::Edge, 0);
        case detail::kRegionC:
            return feature(q, FeatureKind::Vertex, 2);
        case detail::kRegionAC:
            return feature(q, FeatureKind::Edge, 2);
        case detail::kRegionBC:
            return feature(q, FeatureKind::Edge, 1);
        default:
            return feature(q, FeatureKind::Interior, 0);
    }
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

namespace {

// The facts that decide whether a mesh can be signed against, counted as
// topology_report() counts them, from the same EdgeMap (the non-manifold
// vertices only when the edges are fine), and the opposite half-edge of each
// half-edge of a closed, edge-manifold, consistently oriented mesh.
struct SignFacts
{
    std::size_t boundary_edges = 0, non_manifold_edges = 0, orientation_conflicts = 0, degenerate_faces = 0,
                non_manifold_vertices = 0;
    std::vector<std::uint32_t> opposite;  // per half-edge 3 f + k: the opposite half-edge 3 g + j (EdgeMap)
    bool ok() const
    {
        return !boundary_edges && !non_manifold_edges && !orientation_conflicts && !degenerate_faces &&
               !non_manifold_vertices;
    }
};

SignFacts sign_facts(const MeshData& data)
{
    const Mesh& mesh = data.mesh();
    SignFacts r;
    const std::vector<char>& degenerate = data.degenerate_faces();
    r.degenerate_faces = std::size_t(std::count(degenerate.begin(), degenerate.end(), 1));
    // The opposite half-edges and the counts only (not the edges' lists).
    EdgeMap edges = detail::build_edge_map(mesh, detail::EdgeMapParts::Opposite, &data.vertex_faces());
    r.boundary_edges = edges.boundary_edges;
    r.non_manifold_edges = edges.non_manifold_edges;
    r.orientation_conflicts = edges.misoriented_edges;
    r.opposite = std::move(edges.opposite);
    if (r.boundary_edges || r.non_manifold_edges || r.orientation_conflicts || r.degenerate_faces) return r;
    // Fans: around each vertex, the corners linked through the opposite
    // half-edges form cycles; more than one cycle is a non-manifold vertex.
    // One vertex at a time, in parallel, over its corners (one per face of
    // its incidence row: no face repeats a corner here).
    const Adjacency& vf = data.vertex_faces();
    const auto nv = std::int64_t(mesh.n_vertices());
    std::size_t non_manifold = 0;
#pragma omp parallel reduction(+ : non_manifold)
    {
        std::vector<char> visited;
#pragma omp for schedule(dynamic, 4096)
        for (std::int64_t i = 0; i < nv; ++i) {
            const auto u = std::size_t(i);
            const std::uint32_t* first = vf.begin(u);
            const std::size_t d = vf.degree(u);
            // Corner of u in face f; its place in u's row (rows ascend).
            const auto corner = [&](std::size_t f) {
                const Face& t = mesh.faces[f];
                return 3 * f + std::size_t(detail::corner_of(t, u));
            };
            const auto place = [&](std::size_t f) {
                const std::uint32_t* at = std::lower_bound(first, first + d, std::uint32_t(f));
                return at != first + d && *at == f ? std::size_t(at - first) : d;  // d: not a face of u
            };
            visited.assign(d, 0);
            std::size_t cycles = 0;
            for (std::size_t k0 = 0; k0 < d && cycles < 2; ++k0) {
                if (visited[k0]) continue;
                ++cycles;
                std::size_t k = k0;
                for (std::size_t steps = 0; steps < d && k < d && !visited[k]; ++steps) {
                    visited[k] = 1;
                    const std::size_t h = r.opposite[corner(first[k])];  // the half-edge into u in the next face
                    k = place(h / 3);
                }
            }
            non_manifold += cycles >= 2;
        }
    }
    r.non_manifold_vertices = non_manifold;
    return r;
}

std::string reason_of(const SignFacts& f, const std::string& name)
{
    if (f.ok()) return {};
    auto count = [](std::size_t n, const char* one, const char* many) {
        return fmt::format("{} {}", n, n == 1 ? one : many);
    };
    std::vector<std::string> why;
    if (f.boundary_edges) why.push_back(count(f.boundary_edges, "boundary edge", "boundary edges"));
    if (f.non_manifold_edges) why.push_back(count(f.non_manifold_edges, "non-manifold edge", "non-manifold edges"));
    if (f.orientation_conflicts)
        why.push_back(count(f.orientation_conflicts, "edge with inconsistent orientation",
                            "edges with inconsistent orientation"));
    if (f.degenerate_faces) why.push_back(count(f.degenerate_faces, "degenerate face", "degenerate faces"));
    if (f.non_manifold_vertices)
        why.push_back(count(f.non_manifold_vertices, "non-manifold vertex", "non-manifold vertices"));
    std::string s = name + " has ";
    for (std::size_t i = 0; i < why.size(); ++i) s += (i == 0 ? "" : (i + 1 == why.size() ? " and " : ", ")) + why[i];
    return s + " (the sign needs a closed, manifold, consistently oriented mesh without degenerate faces)";
}

// The corners of face g of \p mesh.
struct MeshCorners
{
    const Mesh& mesh;
    std::tuple<const Vec3&, const Vec3&, const Vec3&> operator()(std::uint32_t g) const
    {
        const Face& t = mesh.faces[g];
        return {mesh.points[std::size_t(t[0])], mesh.points[std::size_t(t[1])], mesh.points[std::size_t(t[2])]};
    }
};

}  // namespace

std::string sign_unavailable_reason(const Mesh& mesh, const std::string& name)
{
    return reason_of(sign_facts(MeshData(mesh)), name);
}

std::optional<PseudoNormals> pseudo_normals(const Mesh& mesh, const std::string& name, std::string* reason)
{
    return pseudo_normals(MeshData(mesh), name, reason);
}

namespace {

// pseudo_normals(), PseudoNormals::face filled with \p face_normals.
std::optional<PseudoNormals> make_pseudo_normals(const MeshData& data, const std::string& name, std::string* reason,
                                                 bool face_normals)
{
    const Mesh& mesh = data.mesh();
    if (3 * std::uint64_t(mesh.n_faces()) >= std::uint64_t(~0u)) {
        if (reason) *reason = fmt::format("{} has too many faces to be signed against ({})", name, mesh.n_faces());
        return std::nullopt;
    }
    SignFacts facts = sign_facts(data);
    std::string why = reason_of(facts, name);
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
        const double diag = data.box().diagonal();
        if (!(std::abs(n.volume) > 1e-12 * diag * diag * diag))
            why = fmt::format("{} encloses no volume (signed volume {:.6g})", name, n.volume);
    }
    if (!why.empty()) {
        if (reason) *reason = why;
        return std::nullopt;
    }
    n.flipped = n.volume < 0.0;
    const MeshCorners corners{mesh};
    auto face_normal = [&](std::uint32_t f) {
        const auto [a, b, c] = corners(f);
        return unit_face_normal(n.flipped, a, b, c);
    };
    if (face_normals) {
        n.face.resize(nf);
        const auto m = std::int64_t(nf);
#pragma omp parallel for schedule(static)
        for (std::int64_t i = 0; i < m; ++i) n.face[std::size_t(i)] = face_normal(std::uint32_t(i));
    }
    // Each vertex's angle-weighted sum over its faces in ascending order (the
    // order of a loop over the faces; no face repeats a corner here), one
    // vertex at a time in parallel: the same sums at any thread count.
    const Adjacency& vf = data.vertex_faces();
    const std::size_t nv = mesh.n_vertices();
    n.vertex.resize(nv);
    const auto mv = std::int64_t(nv);
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < mv; ++i) {
        const auto v = std::size_t(i);
        Vec3 sum = Vec3::Zero();
        for (const std::uint32_t* f = vf.begin(v); f != vf.end(v); ++f) {
            const Face& t = mesh.faces[*f];
            const auto k = std::size_t(detail::corner_of(t, v));
            const Vec3& p = mesh.points[v];
            const Vec3& q = mesh.points[std::size_t(t[(k + 1) % 3])];
            const Vec3& r = mesh.points[std::size_t(t[(k + 2) % 3])];
            sum += angle(q - p, r - p) * (face_normals ? n.face[*f] : face_normal(*f));
        }
        n.vertex[v] = sum;
    }
    n.opposite = std::move(facts.opposite);
    return n;
}

}  // namespace

std::optional<PseudoNormals> pseudo_normals(const MeshData& data, const std::string& name, std::string* reason)
{
    return make_pseudo_normals(data, name, reason, true);
}

std::optional<PseudoNormals> detail::pseudo_normals_without_faces(const MeshData& data, const std::string& name,
                                                                  std::string* reason)
{
    return make_pseudo_normals(data, name, reason, false);
}

namespace {

// distance_sign() from the closest feature \p c of face's triangle; the
// unit normal of a face g is normals.face[g], or corners(g) (the triangle's
// corners in order) made into unit_face_normal() when normals.face is empty.
template <typename Corners>
int sign_at(const Mesh& mesh, const PseudoNormals& normals, const Vec3& p, std::uint32_t face, const ClosestFeature& c,
            const Corners& corners)
{
    const Vec3 d = p - c.point;
    if (d.isZero(0.0)) return 0;
    auto normal = [&](std::uint32_t g) {
        if (!normals.face.empty()) return normals.face[g];
        const auto [a, b, cc] = corners(g);
        return unit_face_normal(normals.flipped, a, b, cc);
    };
    double s = 0.0;
    if (c.kind == FeatureKind::Vertex) {
        s = d.dot(normals.vertex[std::size_t(mesh.faces[face][c.index])]);
    } else if (c.kind == FeatureKind::Interior && normals.face.empty()) {
        const auto [a, b, cc] = corners(face);
        return detail::interior_sign(normals.flipped, d, a, b, cc);
    } else {
        const Vec3 nf = normal(face);
        s = c.kind == FeatureKind::Interior ? d.dot(nf)
                                            : d.dot(nf + normal(normals.opposite[3 * std::size_t(face) + c.index] / 3));
    }
    return detail::sign_of(s);
}

}  // namespace

int distance_sign(const Mesh& mesh, const PseudoNormals& normals, const Vec3& p, std::uint32_t face)
{
    const MeshCorners corners{mesh};
    const auto [a, b, c] = corners(face);
    return sign_at(mesh, normals, p, face, closest_feature(p, a, b, c), corners);
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

void signed_query(const Mesh& mesh, const ClosestPointIndex& index, const PseudoNormals& normals, const Vec3* queries,
                  std::size_t n, double* distances, std::int8_t* signs)
{
    detail::signed_query(mesh, index, normals, queries, n, distances, signs, {});
}

void detail::signed_query(const Mesh& mesh, const ClosestPointIndex& index, const PseudoNormals& normals,
                          const Vec3* queries, std::size_t n, double* distances, std::int8_t* signs,
                          const std::function<void()>& beside, const std::uint32_t* order)
{
    // The feature from the index's copy of the triangle, which the query has
    // just read (the same corners, in the same order, and the same thinness
    // as closest_feature() finds from the mesh): no second fetch of the face
    // and its corners.
    // Where the four-lane kernel chose the closest point, its Voronoi region
    // comes with it (the same tests, the same point as face_feature()'s).
    // Face normals not kept are made from the index's copy of the corners
    // too: the closest triangle's at the position the query found it (just
    // read), its neighbour's across an edge by its face.
    const detail::Bvh& bvh = detail::bvh_of(index);
    detail::distances_with_regions(
        index, queries, n, distances,
        [&](std::size_t i, const ClosestPoint& c, unsigned r, std::uint32_t position) {
            if (!(c.distance > 0.0)) {
                signs[i] = 0;
                return;
            }
            const Vec3& p = queries[i];
            auto corners = [&](std::uint32_t g) {
                const detail::Tri t = bvh.tris[g == c.face ? position : bvh.position_of[g]];
                return std::tuple<const Vec3&, const Vec3&, const Vec3&>(t.a, t.b, t.c);
            };
            ClosestFeature f;
            if (r == detail::kRegionUnknown) {
                const detail::Tri t = bvh.tris[position];
                f = t.thin ? thin_feature(p, t.a, t.b, t.c) : face_feature(p, t.a, t.b, t.c);
            } else {
                f = kernel_feature(c.point, r);
            }
            signs[i] = std::int8_t(sign_at(mesh, normals, p, c.face, f, corners));
        },
        beside, order);
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
