#include "meshdiff/roughness/local_roughness.h"

#include "meshdiff/error.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace meshdiff {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The closest point of the other surface to each vertex: its face and
// barycentric coordinates.
struct Anchor
{
    std::uint32_t face = 0;
    Vec3 w = Vec3::Zero();
};

std::vector<Anchor> anchors(const Mesh& other, const Mesh& mesh, const ClosestPointIndex& index)
{
    const std::vector<ClosestPoint> cp = index.closest_points(mesh.points);
    std::vector<Anchor> out(cp.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t ij = 0; ij < std::ptrdiff_t(cp.size()); ++ij) {
        const auto j = std::size_t(ij);
        const Face& f = other.faces[cp[j].face];
        out[j].face = cp[j].face;
        out[j].w = barycentric(cp[j].point, other.points[std::size_t(f[0])], other.points[std::size_t(f[1])],
                               other.points[std::size_t(f[2])]);
    }
    return out;
}

// D at an anchor: the weighted mean over the corners with a defined D (NaN if none).
double interpolate(const std::vector<double>& D, const Face& f, const Vec3& w)
{
    double sum = 0.0, weight = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double d = D[std::size_t(f[std::size_t(c)])];
        if (std::isnan(d) || !(w[c] > 0.0)) continue;
        sum += w[c] * d;
        weight += w[c];
    }
    return weight > 0.0 ? sum / weight : kNaN;
}

struct Pooled
{
    double rms = kNaN;
    std::size_t used = 0;
};

// The RMS over the vertices j of D(j) - D'(cp(j)), without the share \p trim
// of largest magnitude (trimmed_rms()); the per-vertex differences into \p out
// when it is not null.
Pooled pool(const Mesh& other, const std::vector<Anchor>& at, const std::vector<double>& D,
            const std::vector<double>& D_other, double trim, std::vector<double>* out)
{
    std::vector<double> diff(D.size(), kNaN);
    std::size_t used = 0;
    for (std::size_t j = 0; j < D.size(); ++j) {
        if (std::isnan(D[j])) continue;
        const double d_other = interpolate(D_other, other.faces[at[j].face], at[j].w);
        if (std::isnan(d_other)) continue;
        diff[j] = D[j] - d_other;
        ++used;
    }
    Pooled p;
    p.used = used;
    if (used) p.rms = trimmed_rms(diff, trim);
    if (out) *out = std::move(diff);
    return p;
}

}  // namespace

Vec3 barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 e0 = b - a, e1 = c - a, q = p - a;
    const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
    const double d20 = q.dot(e0), d21 = q.dot(e1);
    const double den = d00 * d11 - d01 * d01;
    if (den > 1e-14 * d00 * d11 && std::isfinite(den)) {
        const double v = (d11 * d20 - d01 * d21) / den;
        const double w = (d00 * d21 - d01 * d20) / den;
        // The closest point lies in the triangle: clamp the rounding.
        Vec3 r(std::max(0.0, 1.0 - v - w), std::max(0.0, v), std::max(0.0, w));
        const double s = r.sum();
        if (s > 0.0) return r / s;
    }
    const double da = (p - a).squaredNorm(), db = (p - b).squaredNorm(), dc = (p - c).squaredNorm();
    if (da <= db && da <= dc) return {1.0, 0.0, 0.0};
    return db <= dc ? Vec3(0.0, 1.0, 0.0) : Vec3(0.0, 0.0, 1.0);
}

LocalRoughnessDistance local_roughness_distance(const Mesh& mesh, const RoughnessProfile& pa, const Mesh& other,
                                                const RoughnessProfile& pb, const ClosestPointIndex& index, double trim,
                                                bool keep_vertex_data)
{
    if (pa.D.size() != pa.levels.size() || pb.D.size() != pb.levels.size() || pa.D_radii.size() != pa.radii.size() ||
        pb.D_radii.size() != pb.radii.size() || (pa.has_global && pa.D_global.size() != mesh.n_vertices()) ||
        (pb.has_global && pb.D_global.size() != other.n_vertices()))
        throw InvalidArgumentError("local roughness: a profile has no per-vertex D (keep_vertex_data)");
    if (pa.vertices != mesh.n_vertices() || pb.vertices != other.n_vertices())
        throw InvalidArgumentError(
            fmt::format("local roughness: profiles of {} and {} vertices for meshes of {} and {}", pa.vertices,
                        pb.vertices, mesh.n_vertices(), other.n_vertices()));
    if (!(trim >= 0.0 && trim <= kMaxTrim))
        throw OptionError("local_trim", fmt::format("{} is not a share in [0, {}]", trim, kMaxTrim));
    LocalRoughnessDistance r;
    r.vertices = mesh.n_vertices();
    r.trim = trim;
    const std::vector<Anchor> at = anchors(other, mesh, index);
    for (std::size_t ia = 0; ia < pa.levels.size(); ++ia)
        for (std::size_t ib = 0; ib < pb.levels.size(); ++ib) {
            if (pa.levels[ia].level != pb.levels[ib].level) continue;
            std::vector<double> map;
            const Pooled p = pool(other, at, pa.D[ia], pb.D[ib], trim, keep_vertex_data ? &map : nullptr);
            r.levels.push_back(pa.levels[ia].level);
            r.rms.push_back(p.rms);
            r.used.push_back(p.used);
            if (keep_vertex_data) r.vertex.push_back(std::move(map));
            break;
        }
    if (pa.has_global && pb.has_global) {
        r.has_global = true;
        r.global = pool(other, at, pa.D_global, pb.D_global, trim, nullptr).rms;
    }
    for (std::size_t ia = 0; ia < pa.radii.size(); ++ia)
        for (std::size_t ib = 0; ib < pb.radii.size(); ++ib) {
            if (pa.radii[ia].radius != pb.radii[ib].radius) continue;
            r.radii.push_back(pa.radii[ia].radius);
            r.rms_radii.push_back(pool(other, at, pa.D_radii[ia], pb.D_radii[ib], trim, nullptr).rms);
            break;
        }
    return r;
}

}  // namespace meshdiff
