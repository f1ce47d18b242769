#include "meshdiff/core/topology.h"

#include "meshdiff/core/mesh_data.h"
#include "meshdiff/core/progress.h"
#include "meshdiff/error.h"

#include "core/derivations.h"
#include "core/edge_map_parts.h"
#include "core/union_find.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numeric>

namespace meshdiff {

using detail::UnionFind;

namespace {

// Sorts a small range by insertion, a large one (around a hub) by std::sort.
void sort_bucket(std::uint64_t* b, std::uint64_t* e)
{
    if (e - b > 32) return std::sort(b, e);
    for (std::uint64_t* i = b + 1; i < e; ++i) {
        const std::uint64_t x = *i;
        std::uint64_t* j = i;
        for (; j > b && *(j - 1) > x; --j) *j = *(j - 1);
        *j = x;
    }
}

// Throws InvalidMeshError when a half-edge's number 3 f + k does not fit
// below EdgeMap::kNone.
void check_half_edges(const Mesh& mesh)
{
    if (3 * std::uint64_t(mesh.n_faces()) >= EdgeMap::kNone)
        throw InvalidMeshError(fmt::format("a mesh of {} faces has too many half-edges for an EdgeMap (at most {})",
                                           mesh.n_faces(), EdgeMap::kNone - 1));
}

// The half-edges of a mesh sorted by edge: a counting sort on the lower end,
// then a sort per bucket. Per half-edge (upper end << 33) | (3 f + k) << 1 |
// (it starts at the lower end): in a bucket, the order of (edge, face,
// corner). A vertex index is below 2^31 (Face), 3 f + k below 2^32.
struct SortedHalfEdges
{
    std::vector<std::uint32_t> start;  // per lower end, into he
    std::unique_ptr<std::uint64_t[]> he;

    // With \p vertex_faces (the mesh's vertex-face incidence), the buckets
    // are found and sorted one vertex at a time, in parallel; the same
    // buckets (the keys are distinct, so sorted they are the same).
    explicit SortedHalfEdges(const Mesh& mesh, const Adjacency* vertex_faces = nullptr)
    {
        const std::size_t n = mesh.n_vertices(), nf = mesh.n_faces();
        check_half_edges(mesh);
        if (vertex_faces) {
            by_vertex(mesh, *vertex_faces);
            return;
        }
        start.assign(n + 1, 0);
        for (const Face& t : mesh.faces)
            for (int k = 0; k < 3; ++k) {
                const auto a = std::uint32_t(t[k]), b = std::uint32_t(t[(k + 1) % 3]);
                if (a != b) ++start[std::min(a, b) + 1];
            }
        for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
        he.reset(new std::uint64_t[start[n]]);
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::size_t f = 0; f < nf; ++f) {
            const Face& t = mesh.faces[f];
            for (std::uint32_t k = 0; k < 3; ++k) {
                const auto a = std::uint32_t(t[k]), b = std::uint32_t(t[(k + 1) % 3]);
                if (a == b) continue;
                const std::uint64_t h = 3 * std::uint32_t(f) + k;
                he[fill[std::min(a, b)]++] = (std::uint64_t(std::max(a, b)) << 33) | (h << 1) | (a < b ? 1 : 0);
            }
        }
        for (std::size_t v = 0; v < n; ++v) sort_bucket(he.get() + start[v], he.get() + start[v + 1]);
    }
    // The half-edges whose lower end is v, each once: f(key).
    template <class F>
    static void bucket_of(std::size_t v, const Mesh& mesh, const Adjacency& vertex_faces, F&& f)
    {
        std::uint32_t previous = EdgeMap::kNone;
        for (const std::uint32_t* it = vertex_faces.begin(v); it != vertex_faces.end(v); ++it) {
            if (*it == previous) continue;  // a face that repeats v: its row lists it at each corner
            previous = *it;
            const Face& t = mesh.faces[*it];
            for (std::uint32_t k = 0; k < 3; ++k) {
                const auto a = std::uint32_t(t[k]), b = std::uint32_t(t[(k + 1) % 3]);
                if (a == b || std::min(a, b) != v) continue;
                const std::uint64_t h = 3 * std::uint64_t(*it) + k;
                f((std::uint64_t(std::max(a, b)) << 33) | (h << 1) | (a < b ? 1 : 0));
            }
        }
    }

    void by_vertex(const Mesh& mesh, const Adjacency& vertex_faces)
    {
        const std::size_t n = mesh.n_vertices();
        if (vertex_faces.size() != n)
            throw InvalidArgumentError("edge map: the vertex-face incidence is not this mesh's");
        start.assign(n + 1, 0);
#pragma omp parallel for schedule(static, 4096)
        for (std::ptrdiff_t v = 0; v < std::ptrdiff_t(n); ++v) {
            std::uint32_t count = 0;
            bucket_of(std::size_t(v), mesh, vertex_faces, [&](std::uint64_t) { ++count; });
            start[std::size_t(v) + 1] = count;
        }
        for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
        he.reset(new std::uint64_t[start[n]]);
#pragma omp parallel for schedule(static, 4096)
        for (std::ptrdiff_t v = 0; v < std::ptrdiff_t(n); ++v) {
            std::uint64_t* const b = he.get() + start[std::size_t(v)];
            std::uint64_t* e = b;
            bucket_of(std::size_t(v), mesh, vertex_faces, [&](std::uint64_t key) { *e++ = key; });
            sort_bucket(b, e);
        }
    }

    std::size_t size() const
    {
        return start.back();
    }
    std::uint32_t half_edge(std::size_t i) const
    {
        return std::uint32_t(he[i] >> 1);
    }
    // Two half-edges in the same direction.
    bool same_direction(std::size_t i, std::size_t j) const
    {
        return !((he[i] ^ he[j]) & 1);
    }

    // f(a, b, i, j) for every edge (a, b), a < b, in the order (a, b): its
    // half-edges are [i, j).
    template <class F>
    void for_each_edge(F&& f) const
    {
        for (std::size_t v = 0; v + 1 < start.size(); ++v) for_each_edge_of(v, f);
    }

    // The same for the edges whose lower end is v.
    template <class F>
    void for_each_edge_of(std::size_t v, F&& f) const
    {
        const std::uint32_t end = start[v + 1];
        for (std::uint32_t i = start[v], j = i; i < end; i = j) {
            const std::uint64_t b = he[i] >> 33;
            for (; j < end && he[j] >> 33 == b; ++j) {}
            f(std::uint32_t(v), std::uint32_t(b), i, j);
        }
    }
};

// The opposite half-edges and the three counts from the incidence alone,
// without sorting the half-edges (nor holding them: 8 bytes each). The
// half-edges of the edge {a, b} lie in the faces of a's row, and of b's: the
// shorter is read (each face once); a half-edge counts its edge when it is
// the lowest of them. The same values as the sorted half-edges give.
EdgeMap opposite_from_incidence(const Mesh& mesh, const Adjacency& vertex_faces)
{
    const std::size_t nf = mesh.n_faces();
    if (vertex_faces.size() != mesh.n_vertices())
        throw InvalidArgumentError("edge map: the vertex-face incidence is not this mesh's");
    EdgeMap m;
    m.opposite.assign(3 * nf, EdgeMap::kNone);
    std::size_t boundary = 0, non_manifold = 0, misoriented = 0;
#pragma omp parallel for schedule(static, 4096) reduction(+ : boundary, non_manifold, misoriented)
    for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(nf); ++i) {
        const auto f = std::uint32_t(i);
        const Face& t = mesh.faces[f];
        for (std::uint32_t k = 0; k < 3; ++k) {
            const auto a = std::uint32_t(t[k]), b = std::uint32_t(t[(k + 1) % 3]);
            if (a == b) continue;
            const std::uint32_t h = 3 * f + k;
            std::uint32_t count = 0, lowest = h, other = EdgeMap::kNone;
            bool same = false;  // another half-edge a -> b
            // The faces of the end with fewer: O(min degree) a half-edge, so
            // that a hub's many half-edges do not each walk its whole row.
            const std::uint32_t x = vertex_faces.degree(a) <= vertex_faces.degree(b) ? a : b;
            std::uint32_t previous = EdgeMap::kNone;
            for (const std::uint32_t* it = vertex_faces.begin(x); it != vertex_faces.end(x); ++it) {
                const std::uint32_t g = *it;
                if (g == previous) continue;  // a row lists a face at each corner its vertex holds
                previous = g;
                const Face& u = mesh.faces[g];
                for (std::uint32_t j = 0; j < 3; ++j) {
                    const auto p = std::uint32_t(u[j]), q = std::uint32_t(u[(j + 1) % 3]);
                    const bool forward = p == a && q == b, backward = p == b && q == a;
                    if (!forward && !backward) continue;
                    const std::uint32_t h2 = 3 * g + j;
                    ++count;
                    lowest = std::min(lowest, h2);
                    if (h2 == h) continue;
                    other = h2;
                    same = same || forward;
                }
            }
            if (count == 2 && !same) m.opposite[h] = other;
            if (lowest == h) {
                boundary += count == 1;
                non_manifold += count > 2;
                misoriented += count == 2 && same;
            }
        }
    }
    m.boundary_edges = boundary;
    m.non_manifold_edges = non_manifold;
    m.misoriented_edges = misoriented;
    return m;
}

// Whether opposite_from_incidence() reads at most 64 faces a half-edge on
// average (the smaller degree of its ends): not so where many faces share
// an edge between two vertices of high degree (a "book" of pages), whose
// half-edges would each read all the pages; the sorted half-edges then.
bool incidence_work_is_linear(const Mesh& mesh, const Adjacency& vertex_faces)
{
    if (vertex_faces.size() != mesh.n_vertices()) return false;
    const auto nf = std::ptrdiff_t(mesh.n_faces());
    std::uint64_t work = 0;
#pragma omp parallel for schedule(static, 4096) reduction(+ : work)
    for (std::ptrdiff_t i = 0; i < nf; ++i) {
        const Face& t = mesh.faces[std::size_t(i)];
        for (std::size_t k = 0; k < 3; ++k)
            work += std::min(vertex_faces.degree(std::size_t(t[k])), vertex_faces.degree(std::size_t(t[(k + 1) % 3])));
    }
    return work <= 64 * 3 * std::uint64_t(nf);
}

}  // namespace

EdgeMap detail::build_edge_map(const Mesh& mesh, EdgeMapParts parts, const Adjacency* vertex_faces)
{
    if (parts == EdgeMapParts::Opposite && vertex_faces && incidence_work_is_linear(mesh, *vertex_faces)) {
        check_half_edges(mesh);
        return opposite_from_incidence(mesh, *vertex_faces);
    }
    const SortedHalfEdges s(mesh, vertex_faces);
    const std::size_t n = mesh.n_vertices(), nf = mesh.n_faces();
    const bool edges = parts != EdgeMapParts::Opposite, opposite = parts != EdgeMapParts::Edges;
    // The edges are numbered in (a, b) order: those of the lower ends before
    // v come first. Counted, then written, one lower end at a time in
    // parallel (the same map as a walk over all of them).
    std::vector<std::uint32_t> first(edges ? n + 1 : 0, 0);
    if (edges) {
#pragma omp parallel for schedule(static, 4096)
        for (std::ptrdiff_t v = 0; v < std::ptrdiff_t(n); ++v) {
            std::uint32_t count = 0;
            s.for_each_edge_of(std::size_t(v),
                               [&](std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t) { ++count; });
            first[std::size_t(v) + 1] = count;
        }
        for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    }
    EdgeMap m;
    if (edges) {
        m.half_edge.resize(s.size());
        m.edges.resize(first[n]);
        m.offset.resize(std::size_t(first[n]) + 1);
        m.offset.back() = std::uint32_t(s.size());
    }
    if (parts == EdgeMapParts::All) m.edge_of.assign(3 * nf, EdgeMap::kNone);
    if (opposite) m.opposite.assign(3 * nf, EdgeMap::kNone);
    std::size_t boundary = 0, non_manifold = 0, misoriented = 0;
#pragma omp parallel for schedule(static, 4096) reduction(+ : boundary, non_manifold, misoriented)
    for (std::ptrdiff_t v = 0; v < std::ptrdiff_t(n); ++v) {
        std::uint32_t e = edges ? first[std::size_t(v)] : 0;
        s.for_each_edge_of(std::size_t(v), [&](std::uint32_t a, std::uint32_t b, std::uint32_t i, std::uint32_t j) {
            if (edges) {
                for (std::uint32_t k = i; k < j; ++k) {
                    m.half_edge[k] = s.half_edge(k);
                    if (parts == EdgeMapParts::All) m.edge_of[m.half_edge[k]] = e;
                }
                m.offset[e] = i;
                m.edges[e] = {a, b, s.half_edge(i) / 3};
                ++e;
            }
            boundary += j - i == 1;
            non_manifold += j - i > 2;
            if (j - i != 2) return;
            if (s.same_direction(i, i + 1)) {
                ++misoriented;
            } else if (opposite) {
                m.opposite[s.half_edge(i)] = s.half_edge(i + 1);
                m.opposite[s.half_edge(i + 1)] = s.half_edge(i);
            }
        });
    }
    m.boundary_edges = boundary;
    m.non_manifold_edges = non_manifold;
    m.misoriented_edges = misoriented;
    return m;
}

EdgeMap edge_map(const Mesh& mesh)
{
    return detail::build_edge_map(mesh, detail::EdgeMapParts::All);
}

EdgeMap edge_map(const MeshData& data)
{
    return detail::build_edge_map(data.mesh(), detail::EdgeMapParts::All, &data.vertex_faces());
}

namespace {

// CSR from a row-count pass and a fill pass (counting sort), then each row
// sorted and deduplicated: O(entries) plus small sorts, no global sort.
template <class ForEachEntry>
Adjacency build_csr(std::size_t n, ForEachEntry&& for_each_entry, bool dedupe)
{
    Adjacency adj;
    adj.offset.assign(n + 1, 0);
    for_each_entry([&](std::uint32_t row, std::uint32_t) { ++adj.offset[row + 1]; });
    for (std::size_t i = 0; i < n; ++i) adj.offset[i + 1] += adj.offset[i];
    adj.index.resize(adj.offset[n]);
    std::vector<std::uint32_t> fill(adj.offset.begin(), adj.offset.end() - 1);
    for_each_entry([&](std::uint32_t row, std::uint32_t col) { adj.index[fill[row]++] = col; });
    if (!dedupe) return adj;
    std::uint32_t out = 0;
    std::uint32_t row_start = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t b = row_start, e = adj.offset[i + 1];
        std::sort(adj.index.begin() + b, adj.index.begin() + e);
        row_start = e;
        adj.offset[i] = out;
        for (std::uint32_t k = b; k < e; ++k)
            if (k == b || adj.index[k] != adj.index[k - 1]) adj.index[out++] = adj.index[k];
    }
    adj.offset[n] = out;
    adj.index.resize(out);
    adj.index.shrink_to_fit();
    return adj;
}

}  // namespace

namespace {

// vertex_faces() without the note in the derivation log: a table made and
// freed inside one call, not a datum derived from the mesh.
Adjacency incidence(const Mesh& mesh)
{
    // Faces are visited in order, so each row comes out ascending.
    return build_csr(
        mesh.n_vertices(),
        [&](auto&& emit) {
            for (std::size_t f = 0; f < mesh.n_faces(); ++f)
                for (auto v : mesh.faces[f]) emit(std::uint32_t(v), std::uint32_t(f));
        },
        false);
}

// The other corners of the faces of v, ascending and each once, in \p out.
// In a triangle every two corners share an edge, so these are the ends of
// v's edges (a face that repeats a corner gives the corners that differ).
void neighbours_of(std::size_t v, const Mesh& mesh, const Adjacency& vertex_faces, std::vector<std::uint32_t>& out)
{
    out.clear();
    for (const std::uint32_t* f = vertex_faces.begin(v); f != vertex_faces.end(v); ++f)
        for (auto w : mesh.faces[*f])
            if (std::size_t(w) != v) out.push_back(std::uint32_t(w));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

// A table of one row per vertex made on the threads, in two passes over the
// vertices: row(v, buffer) fills a thread's buffer with v's row, first to
// count (the offsets returned, n + 1 of them), then, once allocate(total)
// has made room, to write it through put(v, buffer, its first entry). No
// table of every half-edge (8 bytes each) on the way; the same table as
// one serial walk.
template <class Buffer, class Row, class Allocate, class Put>
std::vector<std::uint32_t> rows_by_vertex(std::size_t n, Row&& row, Allocate&& allocate, Put&& put)
{
    std::vector<std::uint32_t> offset(n + 1, 0);
#pragma omp parallel
    {
        Buffer buffer;
#pragma omp for schedule(static, 4096)
        for (std::ptrdiff_t v = 0; v < std::ptrdiff_t(n); ++v) {
            row(std::size_t(v), buffer);
            offset[std::size_t(v) + 1] = std::uint32_t(buffer.size());
        }
    }
    for (std::size_t i = 0; i < n; ++i) offset[i + 1] += offset[i];
    allocate(std::size_t(offset[n]));
#pragma omp parallel
    {
        Buffer buffer;
#pragma omp for schedule(static, 4096)
        for (std::ptrdiff_t v = 0; v < std::ptrdiff_t(n); ++v) {
            row(std::size_t(v), buffer);
            put(std::size_t(v), buffer, offset[std::size_t(v)]);
        }
    }
    return offset;
}

}  // namespace

Adjacency vertex_adjacency(const Mesh& mesh)
{
    return vertex_adjacency(mesh, incidence(mesh));
}

Adjacency vertex_adjacency(const Mesh& mesh, const Adjacency& vertex_faces)
{
    // The rows in parallel (rows_by_vertex()): no table of every half-edge
    // (48 MB for 2M faces).
    const std::size_t n = mesh.n_vertices();
    if (vertex_faces.size() != n)
        throw InvalidArgumentError("vertex_adjacency: the vertex-face incidence is not this mesh's");
    Adjacency adj;
    adj.offset = rows_by_vertex<std::vector<std::uint32_t>>(
        n, [&](std::size_t v, std::vector<std::uint32_t>& row) { neighbours_of(v, mesh, vertex_faces, row); },
        [&](std::size_t total) { adj.index.resize(total); },
        [&](std::size_t, const std::vector<std::uint32_t>& row, std::uint32_t at) {
            std::copy(row.begin(), row.end(), adj.index.begin() + at);
        });
    return adj;
}

Adjacency vertex_faces(const Mesh& mesh)
{
    detail::note_derivation(detail::Derived::VertexFaces, mesh);
    return incidence(mesh);
}

std::vector<char> degenerate_face_mask(const Mesh& mesh)
{
    return degenerate_face_mask(mesh, bounding_box(mesh));
}

std::vector<char> degenerate_face_mask(const Mesh& mesh, const BoundingBox& box)
{
    detail::note_derivation(detail::Derived::DegenerateMask, mesh);
    const double diag = box.diagonal();
    const double eps = kDegenerateArea * diag * diag;
    std::vector<char> mask(mesh.n_faces(), 0);
    const auto nf = std::int64_t(mesh.n_faces());
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < nf; ++i) {
        const auto f = std::size_t(i);
        const Face& t = mesh.faces[f];
        mask[f] = (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !(face_cross(mesh, f).norm() > eps)) ? 1 : 0;
    }
    return mask;
}

std::vector<Edge> unique_edges(const Mesh& mesh)
{
    EdgeMap m = detail::build_edge_map(mesh, detail::EdgeMapParts::Edges);
    return std::move(m.edges);
}

namespace {

// The edges of vertex v to higher ends, each once with its lowest face, in
// \p out ascending: from the faces of v's row (in a triangle every two
// corners that differ share an edge).
void edges_up_from(std::size_t v, const Mesh& mesh, const Adjacency& vertex_faces,
                   std::vector<std::pair<std::uint32_t, std::uint32_t>>& out)
{
    out.clear();
    for (const std::uint32_t* f = vertex_faces.begin(v); f != vertex_faces.end(v); ++f)
        for (auto w : mesh.faces[*f])
            if (std::size_t(w) > v) out.push_back({std::uint32_t(w), *f});
    std::sort(out.begin(), out.end());  // by end, then face: an end's first pair has its lowest face
    out.erase(std::unique(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
              out.end());
}

}  // namespace

std::vector<Edge> unique_edges(const MeshData& data)
{
    // From the incidence, one vertex at a time in parallel (a count, then
    // the edges): no sorted half-edges (8 bytes each) nor the edge map's
    // half-edge tables, which the edge list does not need. The same list as
    // unique_edges(mesh): sorted by (a, b), each edge's face the lowest of
    // its half-edges'.
    const Mesh& mesh = data.mesh();
    const Adjacency& vf = data.vertex_faces();
    check_half_edges(mesh);
    using Row = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
    std::vector<Edge> edges;
    rows_by_vertex<Row>(
        mesh.n_vertices(), [&](std::size_t v, Row& row) { edges_up_from(v, mesh, vf, row); },
        [&](std::size_t total) { edges.resize(total); },
        [&](std::size_t v, const Row& row, std::uint32_t at) {
            for (const auto& [w, f] : row) edges[at++] = {std::uint32_t(v), w, f};
        });
    return edges;
}

std::vector<char> boundary_vertex_mask(const Mesh& mesh)
{
    std::vector<char> mask(mesh.n_vertices(), 0);
    const EdgeMap m = detail::build_edge_map(mesh, detail::EdgeMapParts::Edges);
    for (std::size_t e = 0; e < m.size(); ++e)
        if (m.count(e) != 2) mask[m.edges[e].a] = mask[m.edges[e].b] = 1;
    return mask;
}

namespace {

// Isolated vertices (in no face) and the components of the others.
void count_components(const Mesh& mesh, UnionFind& comp, TopologyReport& r)
{
    const std::size_t n = mesh.n_vertices();
    std::vector<char> used(n, 0);
    for (const Face& t : mesh.faces)
        for (auto v : t) used[std::size_t(v)] = 1;
    std::size_t roots = 0;
    for (std::size_t v = 0; v < n; ++v) {
        if (!used[v]) {
            ++r.isolated_vertices;
            continue;
        }
        if (comp.find(std::uint32_t(v)) == v) ++roots;
    }
    r.components = roots;
}

// Boundary loops: connected components of the boundary-edge graph.
class BoundaryLoops
{
public:
    explicit BoundaryLoops(std::size_t n) : loops_(n), on_boundary_(n, 0) {}
    void add(std::uint32_t a, std::uint32_t b)
    {
        on_boundary_[a] = on_boundary_[b] = 1;
        loops_.unite(a, b);
    }
    std::size_t count()
    {
        std::size_t c = 0;
        for (std::size_t v = 0; v < on_boundary_.size(); ++v)
            if (on_boundary_[v] && loops_.find(std::uint32_t(v)) == v) ++c;
        return c;
    }

private:
    UnionFind loops_;
    std::vector<char> on_boundary_;
};

// Duplicate faces: same vertex set. The sorted corners of each face,
// bucketed by the smallest (a counting sort), then the other two sorted
// within each bucket: every face equal to the one before it counts.
void count_duplicate_faces(const Mesh& mesh, TopologyReport& r)
{
    const std::size_t n = mesh.n_vertices();
    std::vector<std::uint32_t> start(n + 1, 0);
    for (const Face& t : mesh.faces) ++start[std::size_t(std::min({t[0], t[1], t[2]})) + 1];
    for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    std::vector<std::uint64_t> rest(mesh.n_faces());  // the two larger corners, packed
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const Face& t : mesh.faces) {
        std::array<std::uint32_t, 3> c{std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])};
        std::sort(c.begin(), c.end());
        rest[fill[c[0]]++] = (std::uint64_t(c[1]) << 32) | c[2];
    }
    for (std::size_t v = 0; v < n; ++v) {
        const auto b = rest.begin() + start[v], e = rest.begin() + start[v + 1];
        std::sort(b, e);
        for (auto it = b; it != e; ++it)
            if (it != b && *it == *(it - 1)) ++r.duplicate_faces;
    }
}

// Non-manifold vertices: the faces around v, linked through shared edges
// (v, w), form more than one fan. Each incident face gives two "other"
// vertices (v itself standing in for a repeated corner); two faces are
// linked when they share one. Up to kPairwiseFanDegree faces every pair is
// tested; above (a hub) the faces are grouped by their other vertices
// (a sort), so a vertex costs O(deg log deg), not O(deg^2). Both give the
// same count: the number of classes does not depend on the union order.
void count_non_manifold_vertices(const Mesh& mesh, const Adjacency& vf, TopologyReport& r)
{
    const std::size_t n = mesh.n_vertices();
    constexpr std::size_t kPairwiseFanDegree = 16;
    std::vector<std::uint32_t> other;                         // the two other vertices per incident face
    std::vector<std::pair<std::uint32_t, std::uint32_t>> by;  // (other vertex, face slot), hubs only
    UnionFind fan;
    for (std::size_t v = 0; v < n; ++v) {
        const std::size_t deg = vf.degree(v);
        if (deg <= 1) continue;
        other.clear();
        for (auto it = vf.begin(v); it != vf.end(v); ++it) {
            const Face& t = mesh.faces[*it];
            const std::size_t start = other.size();
            for (auto w : t)
                if (std::size_t(w) != v) other.push_back(std::uint32_t(w));
            // A face with a repeated corner: v stands for the missing ones
            // (two of them if all three corners are v).
            while (other.size() < start + 2) other.push_back(std::uint32_t(v));
        }
        fan.reset(deg);
        std::size_t fans = deg;
        if (deg <= kPairwiseFanDegree) {
            for (std::size_t a = 0; a < deg; ++a)
                for (std::size_t b = a + 1; b < deg; ++b) {
                    const bool share = other[2 * a] == other[2 * b] || other[2 * a] == other[2 * b + 1] ||
                                       other[2 * a + 1] == other[2 * b] || other[2 * a + 1] == other[2 * b + 1];
                    if (share && fan.unite(std::uint32_t(a), std::uint32_t(b))) --fans;
                }
        } else {
            by.resize(2 * deg);
            for (std::size_t k = 0; k < 2 * deg; ++k) by[k] = {other[k], std::uint32_t(k / 2)};
            std::sort(by.begin(), by.end());
            for (std::size_t k = 1; k < by.size(); ++k)
                if (by[k].first == by[k - 1].first && fan.unite(by[k].second, by[k - 1].second)) --fans;
        }
        if (fans > 1) ++r.non_manifold_vertices;
    }
}

}  // namespace

TopologyReport topology_report(const Mesh& mesh)
{
    return topology_report(MeshData(mesh));
}

TopologyReport topology_report(const MeshData& data)
{
    const Mesh& mesh = data.mesh();
    TopologyReport r;
    const std::size_t n = mesh.n_vertices();
    r.vertices = n;
    r.faces = mesh.n_faces();

    // A Progress (progress.h) can stop the report between its serial steps.
    const Progress* progress = current_progress();
    // One walk over the sorted half-edges, without an EdgeMap (a 2M-face
    // mesh: 72 MB of edge tables it would hold beside the half-edges).
    UnionFind comp(n);
    {
        const SortedHalfEdges s(mesh);
        check_cancelled(progress);
        BoundaryLoops loops(n);
        s.for_each_edge([&](std::uint32_t a, std::uint32_t b, std::uint32_t i, std::uint32_t j) {
            ++r.edges;
            r.boundary_edges += j - i == 1;
            r.non_manifold_edges += j - i > 2;
            r.orientation_conflicts += j - i == 2 && s.same_direction(i, i + 1);
            comp.unite(a, b);
            if (j - i == 1) loops.add(a, b);
        });
        r.boundary_loops = loops.count();
    }
    count_components(mesh, comp, r);
    check_cancelled(progress);
    count_duplicate_faces(mesh, r);
    check_cancelled(progress);
    const auto& degenerate = data.degenerate_faces();
    r.degenerate_faces = std::size_t(std::count(degenerate.begin(), degenerate.end(), 1));
    check_cancelled(progress);
    count_non_manifold_vertices(mesh, data.vertex_faces(), r);
    return r;
}

double mean_edge_length(const Mesh& mesh, const Adjacency& adj)
{
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < adj.size(); ++i)
        for (auto j = adj.begin(i); j != adj.end(i); ++j)
            if (*j > i) {
                sum += (mesh.points[*j] - mesh.points[i]).norm();
                ++n;
            }
    return n ? sum / double(n) : 0.0;
}

}  // namespace meshdiff
