#include "meshdiff/distance/hausdorff.h"

#include "meshdiff/core/tolerances.h"
#include "meshdiff/error.h"
#include "meshdiff/geometry/point_triangle.h"

#include "core/release.h"
#include "core/stage_progress.h"
#include "distance/hausdorff_bounds.h"
#include "distance/hausdorff_seeded.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace meshdiff {

namespace {

using detail::Cell;
using detail::descend_point;
using detail::face_distance;
using detail::kMaxDepth;
using detail::kNone;
using detail::VertexClosest;

// A candidate for the lower bound: a point of A and its closest point of B.
struct Candidate
{
    double d = -1.0;
    Vec3 point = Vec3::Zero();
    std::uint32_t face = 0;
    Vec3 closest = Vec3::Zero();
    std::uint32_t closest_face = 0;
};

// Upper bounds of the distances of a cell's edge midpoints (edge k: corners
// k, k + 1) and the faces of B that give them.
struct Midpoints
{
    std::array<double, 3> d;
    std::array<std::uint32_t, 3> face;
};

// A cell is done with when its bound is within the threshold, or at the
// depth limit (its bound still enters the upper bound).
bool closed(const Cell& c, double threshold)
{
    return c.upper <= threshold || c.depth >= kMaxDepth;
}

double largest_coordinate(const Mesh& m)
{
    double s = 0.0;
    for (const Vec3& p : m.points) s = std::max(s, p.cwiseAbs().maxCoeff());
    return s;
}

}  // namespace

void validate(const HausdorffOptions& o)
{
    const double rel = o.relative_tolerance, abs = o.absolute_tolerance;
    if (!(std::isfinite(rel) && (rel == 0.0 || (rel >= kMinHausdorffTolerance && rel <= kMaxHausdorffTolerance))))
        throw OptionError("hausdorff.relative_tolerance", fmt::format("{} is outside [{}, {}] (0: none)", rel,
                                                                      kMinHausdorffTolerance, kMaxHausdorffTolerance));
    if (!(std::isfinite(abs) && abs >= 0.0))
        throw OptionError("hausdorff.absolute_tolerance", fmt::format("{} must be finite and > 0 (0: none)", abs));
    if (rel == 0.0 && abs == 0.0)
        throw OptionError("hausdorff.relative_tolerance",
                          "both tolerances are 0 ({hausdorff.absolute_tolerance} too): the interval would never stop");
    if (o.max_evaluations > kMaxHausdorffBudget)
        throw OptionError("hausdorff.max_evaluations",
                          fmt::format("{} is outside 1..{} (0: the default)", o.max_evaluations, kMaxHausdorffBudget));
    if (o.max_round_triangles < 4)
        throw OptionError("hausdorff.max_round_triangles", fmt::format("{} must be >= 4", o.max_round_triangles));
}

namespace {
void validate_inputs(const MeshData& a, const MeshData& b, const ClosestPointIndex& b_index,
                     const HausdorffOptions& options)
{
    validate(options);
    a.validate("certified_hausdorff: mesh A");
    b.validate("certified_hausdorff: mesh B");
    if (b_index.n_faces() != b.mesh().n_faces())
        throw InvalidArgumentError(fmt::format("certified_hausdorff: the index holds {} faces but mesh B has {}",
                                               b_index.n_faces(), b.mesh().n_faces()));
}

// One certification (detail::certified_hausdorff()), in its steps: the lower
// bound from the seed and A's vertices, the cells (A's faces) and B as the
// bounds use it, then rounds of splitting the open cells and bounding their
// parts, until every cell is closed or the budget is spent.
struct Certification
{
    Certification(const Mesh& mesh_a, const MeshData& data_b, const ClosestPointIndex& index_b,
                  const HausdorffOptions& opts)
        : a(mesh_a),
          b(data_b.mesh()),
          b_data(data_b),
          b_index(index_b),
          options(opts),
          floor(kHausdorffRoundingFloor * std::max(largest_coordinate(a), largest_coordinate(b))),
          budget(options.max_evaluations ? options.max_evaluations
                                         : 2'000'000 + 20 * (std::size_t(a.n_faces()) + b.n_faces())),
          target(b, b_index)
    {}

    double tolerance(double lower) const
    {
        return std::max({options.relative_tolerance * lower, options.absolute_tolerance, floor});
    }

    // The lower bound from the seed and from A's vertices.
    void set_up_lower_bound(const std::optional<HausdorffSeed>& seed, const std::vector<VertexClosest>& vq)
    {
        if (seed) {
            const ClosestPoint q = b_index.closest_point(seed->point);
            best = {std::max(seed->distance, q.distance), seed->point, seed->face, q.point, q.face};
            ++r.point_evaluations;
        }

        // Exact distances of the vertices that faces use; each vertex's face is
        // the lowest-index face using it.
        std::vector<std::uint32_t> first_face(a.n_vertices(), kNone);
        for (std::size_t f = a.n_faces(); f-- > 0;)
            for (auto v : a.faces[f]) first_face[std::size_t(v)] = std::uint32_t(f);
        std::size_t best_vertex = kNone;
        for (std::size_t v = 0; v < a.n_vertices(); ++v) {
            if (first_face[v] == kNone) continue;
            ++r.point_evaluations;
            if (vq[v].distance > best.d) {
                best = {vq[v].distance, a.points[v], first_face[v], Vec3::Zero(), vq[v].face};
                best_vertex = v;
            }
        }
        // Its closest point on B, found again: the same query, the same point.
        if (best_vertex != kNone) best.closest = b_index.closest_point(a.points[best_vertex]).point;
    }

    // The first round: a cell per face of A, its corners' distances from
    // \p vq, bounded, and kept open if its bound exceeds the lower bound plus
    // the tolerance. In chunks of A's faces, so that only the open cells are
    // held, not a cell per face (a 2M-face mesh: 256 MB): the lower bound
    // does not change within the round, so the open cells are those of one
    // pass over all faces, in the same order.
    void first_round(const std::vector<VertexClosest>& vq)
    {
        stage.check();  // the serial set-up is checked between its steps
        const double threshold = best.d + tolerance(best.d);
        constexpr std::size_t kChunk = std::size_t(1) << 16;
        std::vector<Cell> chunk;
        for (std::size_t first = 0; first < a.n_faces(); first += kChunk) {
            const std::size_t m = std::min(kChunk, a.n_faces() - first);
            chunk.assign(m, Cell{});
#pragma omp parallel for schedule(dynamic, 256)
            for (std::size_t i = 0; i < m; ++i) {
                if (!stage.tick()) continue;
                Cell& c = chunk[i];
                const std::size_t f = first + i;
                for (std::size_t k = 0; k < 3; ++k) {
                    const auto v = std::size_t(a.faces[f][k]);
                    c.corner[k] = a.points[v];
                    c.d[k] = vq[v].distance;
                    c.closest[k] = vq[v].face;
                }
                c.face = std::uint32_t(f);
                detail::bound_cell(c, threshold, target);
            }
            stage.check();
            r.bound_evaluations += m;
            for (const Cell& c : chunk) {
                if (closed(c, threshold))
                    upper_done = std::max(upper_done, c.upper);
                else
                    cells.push_back(c);
            }
        }
    }

    // B's longest edges, the neighbours across its edges (from \p opposite,
    // B's opposite half-edges, when given) and its triangles.
    void set_up_target(const std::vector<std::uint32_t>* opposite)
    {
        // The longest edge of B's triangles: a cell of A whose corners are
        // farther apart than 2 x threshold + that length has no triangle of B
        // within threshold of all its corners (|c_i - c_j| <= d(c_i, t) +
        // diam(t) + d(c_j, t)), so its bound cannot close it: it is split
        // without searching.
        stage.check();
        std::vector<double> diameter_b(b.n_faces(), 0.0);  // longest edge per face of B
#pragma omp parallel for schedule(static)
        for (std::size_t f = 0; f < b.n_faces(); ++f)
            for (std::size_t k = 0; k < 3; ++k)
                diameter_b[f] = std::max(
                    diameter_b[f],
                    (b.points[std::size_t(b.faces[f][k])] - b.points[std::size_t(b.faces[f][(k + 1) % 3])]).norm());
        target.longest = *std::max_element(diameter_b.begin(), diameter_b.end());
        target.diameter = std::move(diameter_b);
        stage.check();
        target.nbr = opposite ? detail::neighbours_across(*opposite) : detail::edge_neighbours(b_data);
        stage.check();
        target.tris = detail::Triangles(b_index);
    }

    // Takes the list of open cells set aside last, closing those that the
    // current lower bound closes; false if there is none.
    bool reopen_pending()
    {
        if (pending.empty()) return false;
        cells = std::move(pending.back());
        pending.pop_back();
        // Bounded against an earlier lower bound: close those that the
        // current one closes.
        const double threshold = best.d + tolerance(best.d);
        std::size_t kept = 0;
        for (Cell& c : cells) {
            if (c.upper <= threshold)
                upper_done = std::max(upper_done, c.upper);
            else
                cells[kept++] = c;
        }
        cells.resize(kept);
        return true;
    }

    // Splits and bounds the open cells round by round (setting lists aside
    // when a round would be too large) until none is left or the budget is
    // spent.
    void search()
    {
        const std::size_t chunk = options.max_round_triangles / 4;
        for (;;) {
            if (cells.empty()) {
                if (!reopen_pending()) break;
                continue;
            }
            if (4 * cells.size() > options.max_round_triangles) {
                pending.emplace_back(cells.begin() + std::ptrdiff_t(chunk), cells.end());
                cells.resize(chunk);
                ++r.chunks;
            }
            if (r.bound_evaluations + 4 * cells.size() > budget) {
                r.budget_exhausted = true;
                break;
            }
            ++r.rounds;
            split_round();
        }
    }

    // One round: every open cell into four, its edge midpoints bounded (and
    // queried where they can raise the lower bound), then the four parts
    // bounded against the raised lower bound, those still open kept in
    // `cells` (in order: cell i's parts 4 i .. 4 i + 3). The parts are made
    // and bounded a block at a time from the cells and their midpoints'
    // bounds: only the open ones are held, not four per cell.
    void split_round()
    {
        const detail::Triangles& tris = target.tris;
        const detail::Neighbours& nbr = target.nbr;
        // A midpoint's distance to the closer of its edge's two faces bounds
        // its distance to B from above; only where that bound exceeds the
        // lower bound can the midpoint raise it, and only there is it queried
        // exactly (its distance is then a lower-bound candidate).
        const std::size_t n = cells.size();
        const double lower_now = best.d;
        mids.resize(n);
        found.assign(n, Candidate{});
        std::vector<std::size_t> queried(n, 0);
#pragma omp parallel for schedule(dynamic, 256)
        for (std::int64_t ii = 0; ii < std::int64_t(n); ++ii) {
            const auto i = std::size_t(ii);
            if (!stage.tick()) continue;
            const Cell& c = cells[i];
            Midpoints& mp = mids[i];
            Candidate& cand = found[i];
            for (std::size_t k = 0; k < 3; ++k) {
                const std::size_t k1 = (k + 1) % 3;
                const Vec3 m = midpoint(c, k);
                double md = face_distance(m, tris, c.closest[k]);
                std::uint32_t mf = c.closest[k];
                if (c.closest[k1] != c.closest[k]) {
                    const double other = face_distance(m, tris, c.closest[k1]);
                    if (other < md) {
                        md = other;
                        mf = c.closest[k1];
                    }
                }
                if (md > lower_now) descend_point(m, tris, nbr, mf, md, lower_now);
                if (md > lower_now) {
                    const ClosestPoint q = b_index.closest_point(m, mf);
                    ++queried[i];
                    md = q.distance;
                    mf = q.face;
                    if (q.distance > cand.d) cand = {q.distance, m, c.face, q.point, q.face};
                }
                mp.d[k] = md;
                mp.face[k] = mf;
            }
        }
        stage.check();
        for (const std::size_t q : queried) r.point_evaluations += q;
        for (const Candidate& cand : found)  // in order: the lowest index wins ties
            if (cand.d > best.d) best = cand;

        // The parts, bounded against the lower bound the round reached, a
        // block at a time; their bounds (and the faces that gave them) kept,
        // then the open ones made again into a list of their exact size (so
        // that even when all stay open the round holds no more than four
        // parts per cell, as a list of all parts would).
        detail::release(found);
        detail::release(queried);
        const double threshold = best.d + tolerance(best.d);
        constexpr std::size_t kBlock = std::size_t(1) << 14;  // cells per block: 64K parts
        std::vector<double> upper(4 * n);
        std::vector<std::uint32_t> hint(4 * n);
        std::size_t n_open = 0;
        for (std::size_t first = 0; first < n; first += kBlock) {
            const std::size_t m = std::min(kBlock, n - first);
            block.resize(4 * m);
#pragma omp parallel for schedule(dynamic, 64)
            for (std::int64_t ii = 0; ii < std::int64_t(m); ++ii) {
                const auto i = std::size_t(ii);
                split(cells[first + i], mids[first + i], &block[4 * i]);
                for (std::size_t k = 0; k < 4; ++k) {
                    if (!stage.tick()) continue;
                    Cell& c = block[4 * i + k];
                    detail::bound_cell(c, threshold, target);
                    upper[4 * (first + i) + k] = c.upper;
                    hint[4 * (first + i) + k] = c.hint;
                }
            }
            stage.check();
            for (const Cell& c : block) {
                if (closed(c, threshold))
                    upper_done = std::max(upper_done, c.upper);
                else
                    ++n_open;
            }
        }
        r.bound_evaluations += 4 * n;
        std::vector<Cell> open;
        open.reserve(n_open);
        for (std::size_t i = 0; i < n; ++i) {
            std::array<Cell, 4> part;
            split(cells[i], mids[i], part.data());
            for (std::size_t k = 0; k < 4; ++k) {
                Cell& c = part[k];
                c.upper = upper[4 * i + k];
                c.hint = hint[4 * i + k];
                if (!closed(c, threshold)) open.push_back(c);
            }
        }
        cells.swap(open);
    }

    // The midpoint of edge k (corners k, k + 1) of cell c.
    static Vec3 midpoint(const Cell& c, std::size_t k)
    {
        return 0.5 * (c.corner[k] + c.corner[(k + 1) % 3]);
    }

    // The four parts of cell c, its midpoints bounded by mp, into out[0..3]:
    // the three corner triangles and the middle one.
    static void split(const Cell& c, const Midpoints& mp, Cell* out)
    {
        const std::array<Vec3, 3> m{midpoint(c, 0), midpoint(c, 1), midpoint(c, 2)};
        for (std::size_t k = 0; k < 3; ++k) {
            Cell& ch = out[k];
            const std::size_t prev = (k + 2) % 3;  // edge (k - 1, k)
            ch.corner = {c.corner[k], m[k], m[prev]};
            ch.d = {c.d[k], mp.d[k], mp.d[prev]};
            ch.closest = {c.closest[k], mp.face[k], mp.face[prev]};
        }
        Cell& mid = out[3];
        mid.corner = m;
        mid.d = mp.d;
        mid.closest = mp.face;
        for (std::size_t k = 0; k < 4; ++k) {
            out[k].face = c.face;
            out[k].hint = c.hint;
            out[k].depth = c.depth + 1;
            out[k].upper = detail::kInf;
        }
    }

    // The interval, its tolerance and the location of the lower bound.
    CertifiedHausdorff finish()
    {
        double upper = std::max(upper_done, best.d);
        for (const Cell& c : cells) upper = std::max(upper, c.upper);
        for (const std::vector<Cell>& list : pending)
            for (const Cell& c : list) upper = std::max(upper, c.upper);
        r.lower = best.d;
        r.upper = upper;
        r.tolerance = tolerance(best.d);
        r.certified = !r.budget_exhausted && r.upper - r.lower <= r.tolerance;
        stage.finish();
        r.location = {best.point, best.face, best.closest, best.closest_face};
        return r;
    }

    const Mesh& a;
    const Mesh& b;
    const MeshData& b_data;
    const ClosestPointIndex& b_index;
    const HausdorffOptions& options;
    const double floor;
    const std::size_t budget;
    // Progress counts the triangles bounded and split (the total is not known).
    detail::StageProgress stage{"certification", 0};
    CertifiedHausdorff r;
    Candidate best;
    detail::BoundsTarget target;  // B as the bounds use it
    std::vector<Cell> cells;      // the open cells
    double upper_done = 0.0;      // the largest bound of the closed triangles
    // Open cells set aside when a round would create more than
    // max_round_triangles: the search goes on with the first
    // max_round_triangles / 4 of them and takes the lists set aside later,
    // the last one first (depth first, so the memory stays bounded). Until
    // a round would be that large the search is the breadth-first one.
    std::vector<std::vector<Cell>> pending;
    std::vector<Midpoints> mids;   // a round's bounds of the cells' edge midpoints
    std::vector<Candidate> found;  // a round's candidates, one per cell
    std::vector<Cell> block;       // a block of a round's parts, four per cell
};

}  // namespace

std::vector<detail::VertexClosest> detail::vertex_closest(const std::vector<ClosestPoint>& c)
{
    std::vector<VertexClosest> out(c.size());
    const auto n = std::int64_t(c.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) out[std::size_t(i)] = {c[std::size_t(i)].distance, c[std::size_t(i)].face};
    return out;
}

CertifiedHausdorff detail::certified_hausdorff(const MeshData& a_data, const MeshData& b_data,
                                               const ClosestPointIndex& b_index, const HausdorffOptions& options,
                                               const std::optional<HausdorffSeed>& seed,
                                               const std::vector<VertexClosest>& vq,
                                               const std::vector<std::uint32_t>* b_opposite)
{
    validate_inputs(a_data, b_data, b_index, options);
    const Mesh& a = a_data.mesh();
    if (vq.size() != a.n_vertices())
        throw InvalidArgumentError(
            fmt::format("certified_hausdorff: {} vertex closest points for {} vertices", vq.size(), a.n_vertices()));
    Certification s(a, b_data, b_index, options);
    s.set_up_lower_bound(seed, vq);
    s.set_up_target(b_opposite);
    s.first_round(vq);
    s.search();
    return s.finish();
}

CertifiedHausdorff certified_hausdorff(const Mesh& a, const Mesh& b, const ClosestPointIndex& b_index,
                                       const HausdorffOptions& options, const std::optional<HausdorffSeed>& seed)
{
    const MeshData a_data(a), b_data(b);
    validate_inputs(a_data, b_data, b_index, options);  // before the vertex queries
    return detail::certified_hausdorff(a_data, b_data, b_index, options, seed,
                                       detail::vertex_closest(b_index.closest_points(a.points)));
}

CertifiedHausdorff certified_hausdorff(const Mesh& a, const Mesh& b, const HausdorffOptions& options)
{
    const MeshData b_data(b);
    b_data.validate("certified_hausdorff: mesh B");
    const ClosestPointIndex index(b_data);
    const MeshData a_data(a);
    validate_inputs(a_data, b_data, index, options);  // before the vertex queries
    return detail::certified_hausdorff(a_data, b_data, index, options, std::nullopt,
                                       detail::vertex_closest(index.closest_points(a.points)));
}

// The seed of a certified Hausdorff distance: the sampled maximum of \p s,
// on a face of \p from (for a vertex sample, the lowest-index face using it).
HausdorffSeed detail::seed_of(const Mesh& from, const DistanceStats& s)
{
    HausdorffSeed seed{s.max_point, s.max_element, s.max};
    if (s.max_kind == SampleKind::OnVertex) {
        for (std::size_t f = 0; f < from.n_faces(); ++f) {
            const Face& t = from.faces[f];
            if (std::find(t.begin(), t.end(), int(s.max_element)) != t.end()) {
                seed.face = std::uint32_t(f);
                break;
            }
        }
    }
    return seed;
}

}  // namespace meshdiff
