#include "meshdiff/geometry/sampling.h"

#include "meshdiff/error.h"

#include "core/stage_progress.h"
#include "geometry/sample_plan.h"

#include <Eigen/Geometry>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>

namespace meshdiff {

namespace {

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
        throw OptionError("sampling.vertices",
                          "vertex, edge and face samples are all off ({sampling.edges}, {sampling.faces} too); "
                          "enable at least one");
    if (options.samples && options.density)
        throw OptionError("sampling.samples", "excludes {sampling.density}; give at most one");
    if (options.samples && (*options.samples == 0 || *options.samples > kMaxSamples))
        throw OptionError("sampling.samples",
                          fmt::format("{} is outside 1..{} per surface", *options.samples, kMaxSamples));
    if (options.density && !(std::isfinite(*options.density) && *options.density > 0.0))
        throw OptionError("sampling.density", fmt::format("{} must be finite and > 0", *options.density));
}

namespace {

// sample_target() with the mesh's derived data.
std::size_t sample_target(const MeshData& data, const SamplingOptions& options, std::size_t default_target)
{
    const Mesh& mesh = data.mesh();
    if (options.samples) return *options.samples;
    if (options.density) {
        const auto& degenerate = data.degenerate_faces();
        double area = 0.0;
        for (std::size_t f = 0; f < mesh.n_faces(); ++f)
            if (!degenerate[f]) area += 0.5 * face_cross(mesh, f).norm();
        const double target = *options.density * area;
        if (!(target <= double(kMaxSamples)))
            throw InvalidArgumentError(
                fmt::format("SamplingOptions: density {} x area {:.6g} asks for {:.3g} samples, above the limit of {} "
                            "per surface",
                            *options.density, area, target, kMaxSamples));
        return std::size_t(std::llround(target));
    }
    if (default_target > kMaxSamples)
        throw InvalidArgumentError(
            fmt::format("SamplingOptions: the default budget of {} samples exceeds the limit of {} per surface; set "
                        "samples or density",
                        default_target, kMaxSamples));
    return default_target;
}

}  // namespace

std::size_t sample_target(const Mesh& mesh, const SamplingOptions& options, std::size_t default_target)
{
    return sample_target(MeshData(mesh), options, default_target);
}

namespace detail {

namespace {

// The plan's offsets are 32-bit (sample_plan.h): at most the vertices (below
// 2^31) and the budget (at most kMaxSamples) fit. Kept as a check, since a
// wrapped offset would make wrong samples silently.
void check_offsets(std::size_t samples)
{
    if (samples > std::numeric_limits<std::uint32_t>::max())
        throw InvalidArgumentError(
            fmt::format("sample_surface: {} samples do not fit the plan's 32-bit offsets", samples));
}

}  // namespace

SamplePlan plan_samples(const MeshData& data, const SamplingOptions& options)
{
    const Mesh& mesh = data.mesh();
    SamplePlan plan;
    SurfaceSamples& s = plan.counts;
    plan.scheme = options.face_scheme;
    plan.seed = options.seed;
    s.target = sample_target(data, options, 10 * mesh.n_faces());

    const auto& degenerate = data.degenerate_faces();
    // The faces' areas in parallel, summed in face order.
    std::vector<double> face_area(mesh.n_faces());
    const auto nf = std::int64_t(mesh.n_faces());
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < nf; ++i) {
        const auto f = std::size_t(i);
        face_area[f] = degenerate[f] ? 0.0 : 0.5 * face_cross(mesh, f).norm();
    }
    double area = 0.0;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        if (!degenerate[f]) area += face_area[f];
    // Coordinates near 1e80 make the squared norms overflow: the area is inf,
    // the face density 0, inf x 0 a NaN count, and the lattice order of a NaN
    // cast to an integer a loop without end. validate() refuses such meshes
    // (max_coordinate); this keeps the plan finite whatever the caller passes.
    if (!std::isfinite(area))
        throw InvalidMeshError(
            fmt::format("sample_surface: the surface area is not finite (coordinates beyond meshdiff's limit of +-{}?)",
                        max_coordinate));

    // Counts are decided sequentially (carry-over); SampleMaker then fills
    // positions in parallel into disjoint ranges: the result does not depend
    // on threads.

    // Vertices: every referenced one, in index order.
    if (options.vertices) {
        std::vector<char> referenced(mesh.n_vertices(), 0);
        for (const Face& t : mesh.faces)
            for (auto v : t) referenced[std::size_t(v)] = 1;
        for (std::size_t v = 0; v < mesh.n_vertices(); ++v)
            if (referenced[v]) plan.vertices.push_back(std::uint32_t(v));
        s.n_vertex = plan.vertices.size();
    }
    check_cancelled(current_progress());  // the serial steps are checked in between
    if (s.n_vertex >= s.target) return plan;
    double remaining = double(s.target - s.n_vertex);

    // Edges: density sqrt(face density) per unit length, with carry-over.
    if (options.edges) {
        plan.edges = unique_edges(data);
        const auto& edges = plan.edges;
        check_cancelled(current_progress());
        // The edges' lengths in parallel, summed in edge order.
        std::vector<double> len(edges.size());
        const auto ne = std::int64_t(edges.size());
#pragma omp parallel for schedule(static)
        for (std::int64_t j = 0; j < ne; ++j) {
            const auto i = std::size_t(j);
            len[i] = (mesh.points[edges[i].b] - mesh.points[edges[i].a]).norm();
        }
        double length = 0.0;
        for (std::size_t i = 0; i < edges.size(); ++i) length += len[i];
        if (!std::isfinite(length))
            throw InvalidMeshError(fmt::format(
                "sample_surface: the edge length is not finite (coordinates beyond meshdiff's limit of +-{}?)",
                max_coordinate));
        // Never more than the remaining budget (Metro would overshoot here).
        const double cap = length > 0.0 ? remaining / length : 0.0;
        s.edge_density = options.faces && area > 0.0 ? std::min(std::sqrt(remaining / area), cap) : cap;
        std::vector<std::uint32_t>& offset = plan.edge_offset;
        offset.assign(edges.size() + 1, std::uint32_t(s.n_vertex));
        std::size_t at = s.n_vertex;
        double carry = 0.0;
        for (std::size_t i = 0; i < edges.size(); ++i) {
            carry += len[i] * s.edge_density;
            const auto n = std::size_t(carry);
            at += n;
            offset[i + 1] = std::uint32_t(at);
            carry -= double(n);
        }
        check_offsets(at);
        s.n_edge = at - s.n_vertex;
        remaining = std::max(0.0, remaining - double(s.n_edge));
    }

    check_cancelled(current_progress());
    // Faces.
    if (options.faces && area > 0.0 && remaining > 0.0) {
        s.face_density = remaining / area;
        const bool lattice = options.face_scheme == FaceSampling::SimilarTriangles;
        // Per face: the lattice order k (SimilarTriangles) or the count.
        if (lattice) plan.face_order.assign(mesh.n_faces(), 0);
        std::vector<std::uint32_t>& offset = plan.face_offset;
        offset.assign(mesh.n_faces() + 1, std::uint32_t(s.n_vertex + s.n_edge));
        std::size_t at = s.n_vertex + s.n_edge;
        double carry = 0.0;
        for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
            std::size_t n = 0;
            if (!degenerate[f]) {
                carry += face_area[f] * s.face_density;
                const auto due = std::size_t(carry);
                if (lattice) {
                    const std::size_t k = lattice_order(due);
                    plan.face_order[f] = std::uint32_t(k);
                    n = k * (k + 1) / 2;
                } else {
                    n = due;
                }
                carry -= double(n);
            }
            at += n;
            offset[f + 1] = std::uint32_t(at);
        }
        check_offsets(at);
        s.n_face = at - s.n_vertex - s.n_edge;
    }
    return plan;
}

SampleMaker::SampleMaker(const Mesh& mesh, const SamplePlan& plan)
    : mesh_(mesh), plan_(plan), rng_(plan.seed), drawn_(plan.counts.n_vertex + plan.counts.n_edge)
{}

void SampleMaker::make(std::size_t begin, std::size_t end, Vec3* points, SampleKind* kind, std::uint32_t* element)
{
    const Mesh& mesh = mesh_;
    const SamplePlan& plan = plan_;
    auto put = [&](std::size_t at, const Vec3& p, SampleKind k, std::size_t e) {
        points[at - begin] = p;
        kind[at - begin] = k;
        element[at - begin] = std::uint32_t(e);
    };
    // The elements i of a range [offset[i], offset[i + 1]) meeting [begin, end).
    std::int64_t first = 0, last = 0;
    auto elements = [begin, end, &first, &last](const std::vector<std::uint32_t>& offset) {
        first =
            std::max<std::int64_t>(std::upper_bound(offset.begin(), offset.end() - 1, begin) - offset.begin() - 1, 0);
        last = std::lower_bound(offset.begin(), offset.end() - 1, end) - offset.begin();
    };

    // Vertices.
    const std::size_t nv = plan.counts.n_vertex;
    const auto vertex_end = std::int64_t(std::min(end, nv));
#pragma omp parallel for schedule(static)
    for (std::int64_t a = std::int64_t(begin); a < vertex_end; ++a) {
        const auto at = std::size_t(a);
        const std::uint32_t v = plan.vertices[at];
        put(at, mesh.points[v], SampleKind::OnVertex, v);
    }

    // Edges: the n points that cut an edge into n + 1 equal parts.
    if (plan.counts.n_edge > 0 && end > nv && begin < nv + plan.counts.n_edge) {
        const auto& offset = plan.edge_offset;
        const auto& edges = plan.edges;
        elements(offset);
#pragma omp parallel for schedule(static)
        for (std::int64_t ii = first; ii < last; ++ii) {
            const auto i = std::size_t(ii);
            const std::size_t n = offset[i + 1] - offset[i];
            const Vec3& p0 = mesh.points[edges[i].a];
            const Vec3& p1 = mesh.points[edges[i].b];
            const Vec3 step = (p1 - p0) / double(n + 1);
            const std::size_t k0 = std::max<std::size_t>(offset[i], begin) - offset[i] + 1;
            const std::size_t k1 = std::min<std::size_t>(offset[i + 1], end) - offset[i];
            for (std::size_t k = k0; k <= k1; ++k)
                put(offset[i] + k - 1, p0 + step * double(k), SampleKind::OnEdge, edges[i].face);
        }
    }

    // Faces.
    if (plan.counts.n_face == 0 || end <= plan.face_offset.front()) return;
    const auto& offset = plan.face_offset;
    elements(offset);
    auto corners = [&mesh](std::size_t f) {
        const Face& t = mesh.faces[f];
        return std::array<const Vec3*, 3>{&mesh.points[std::size_t(t[0])], &mesh.points[std::size_t(t[1])],
                                          &mesh.points[std::size_t(t[2])]};
    };
    if (plan.scheme == FaceSampling::SimilarTriangles) {
#pragma omp parallel for schedule(static)
        for (std::int64_t ff = first; ff < last; ++ff) {
            const auto f = std::size_t(ff);
            const std::size_t k = plan.face_order[f];
            if (k == 0) continue;
            // Interior points of the lattice of step 1/(k+2) along both edges,
            // row by row (row i has k + 1 - i points).
            const auto [v0, v1, v2] = corners(f);
            const Vec3 e1 = (*v1 - *v0) / double(k + 2);
            const Vec3 e2 = (*v2 - *v0) / double(k + 2);
            std::size_t at = offset[f];
            for (std::size_t i = 1; i <= k && at < end; ++i) {
                if (at + (k + 1 - i) <= begin) {
                    at += k + 1 - i;
                    continue;
                }
                for (std::size_t j = 1; i + j <= k + 1; ++j, ++at)
                    if (at >= begin && at < end) put(at, *v0 + e1 * double(i) + e2 * double(j), SampleKind::OnFace, f);
            }
        }
    } else {
        // One random stream over the face samples in order, two draws each.
        const std::size_t start = std::max<std::size_t>(begin, offset.front());
        if (start < drawn_) {
            rng_.seed(plan.seed);
            drawn_ = offset.front();
        }
        rng_.discard(2 * (start - drawn_));
        for (auto ff = first; ff < last; ++ff) {
            const auto f = std::size_t(ff);
            const auto [v0, v1, v2] = corners(f);
            const Vec3 e1 = *v1 - *v0;
            const Vec3 e2 = *v2 - *v0;
            for (std::size_t at = std::max<std::size_t>(offset[f], start);
                 at < std::min<std::size_t>(offset[f + 1], end); ++at) {
                double r1 = unit_double(rng_);
                double r2 = unit_double(rng_);
                if (r1 + r2 > 1.0) {
                    r1 = 1.0 - r1;
                    r2 = 1.0 - r2;
                }
                put(at, *v0 + e1 * r1 + e2 * r2, SampleKind::OnFace, f);
            }
        }
        drawn_ = std::min<std::size_t>(end, offset.back());
    }
}

}  // namespace detail

namespace {

SurfaceSamples sample_surface_unreported(const MeshData& data, const SamplingOptions& options)
{
    const Mesh& mesh = data.mesh();
    const detail::SamplePlan plan = detail::plan_samples(data, options);
    SurfaceSamples s = plan.counts;
    const std::size_t n = plan.size();
    s.points.resize(n);
    s.kind.resize(n);
    s.element.resize(n);
    detail::SampleMaker(mesh, plan).make(0, n, s.points.data(), s.kind.data(), s.element.data());
    return s;
}

}  // namespace

SurfaceSamples sample_surface(const Mesh& mesh, const SamplingOptions& options)
{
    return sample_surface(MeshData(mesh), options);
}

SurfaceSamples sample_surface(const MeshData& data, const SamplingOptions& options)
{
    validate(options);
    data.validate("sample_surface");
    detail::StageProgress stage("sampling", 1);
    SurfaceSamples s = sample_surface_unreported(data, options);
    stage.finish();
    return s;
}

}  // namespace meshdiff
