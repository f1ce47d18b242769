#include "meshdiff/roughness/local_roughness.h"

#include "meshdiff/error.h"
#include "meshdiff/geometry/normalize.h"
#include "meshdiff/roughness/metric_levels.h"
#include "meshdiff/roughness/neighborhood.h"

#include "roughness/level_stream.h"
#include "roughness/local_roughness_closest.h"

#include <fmt/format.h>

#include <algorithm>
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

// The anchors of mesh's vertices on other; their closest points moved to
// \p closest when given.
std::vector<Anchor> anchors(const Mesh& other, const Mesh& mesh, const ClosestPointIndex& index,
                            std::vector<ClosestPoint>* closest)
{
    std::vector<ClosestPoint> cp = index.closest_points(mesh.points);
    std::vector<Anchor> out(cp.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t ij = 0; ij < std::ptrdiff_t(cp.size()); ++ij) {
        const auto j = std::size_t(ij);
        const Face& f = other.faces[cp[j].face];
        out[j].face = cp[j].face;
        out[j].w = barycentric(cp[j].point, other.points[std::size_t(f[0])], other.points[std::size_t(f[1])],
                               other.points[std::size_t(f[2])]);
    }
    if (closest) *closest = std::move(cp);
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

// D(i) = F(i) - mean(i) (NaN where either is), pooled as the area-weighted
// RMS without the share \p trim of largest |D| (trimmed_rms()); D into \p out
// when it is not null.
Pooled pool(const std::vector<double>& F, const std::vector<double>& mean, const std::vector<double>& area, double trim,
            std::vector<double>* out)
{
    std::vector<double> D(F.size(), kNaN);
    std::size_t used = 0;
    for (std::size_t i = 0; i < F.size(); ++i) {
        D[i] = F[i] - mean[i];  // NaN propagates
        if (!std::isnan(D[i])) ++used;
    }
    Pooled p;
    p.used = used;
    if (used) p.rms = trimmed_rms(D, trim, &area);
    if (out) *out = std::move(D);
    return p;
}

// F(i) = H(i) - H'(cp(i)): the change of H, carried to the vertices of mesh
// (NaN where either is undefined).
std::vector<double> change_of_H(const Mesh& mesh, const std::vector<double>& H, const Mesh& other,
                                const std::vector<double>& other_H, const ClosestPointIndex& index,
                                std::vector<ClosestPoint>* closest)
{
    const std::size_t n = mesh.n_vertices();
    const std::vector<Anchor> at = anchors(other, mesh, index, closest);
    std::vector<double> F(n, kNaN);
    for (std::size_t i = 0; i < n; ++i) {
        if (std::isnan(H[i])) continue;
        const double h = interpolate(other_H, other.faces[at[i].face], at[i].w);
        if (!std::isnan(h)) F[i] = H[i] - h;
    }
    return F;
}

// The ring levels present in both profiles, in mesh's profile's order.
std::vector<int> common_levels(const std::vector<LevelRoughness>& a, const std::vector<LevelRoughness>& b)
{
    std::vector<int> levels;
    for (const LevelRoughness& la : a)
        for (const LevelRoughness& lb : b)
            if (la.level == lb.level) {
                levels.push_back(la.level);
                break;
            }
    return levels;
}

// What a level's folded sums give the result: its RMS, its count, its D.
std::function<void(std::size_t, const detail::LevelSums&, std::vector<double>&)> level_sink(LocalRoughnessDistance& r,
                                                                                            double trim,
                                                                                            bool keep_vertex_data)
{
    return [&r, trim, keep_vertex_data](std::size_t, const detail::LevelSums& sums, std::vector<double>& D) {
        r.rms.push_back(sums.used ? detail::streamed_trimmed_rms(sums, trim) : kNaN);
        r.used.push_back(sums.used);
        if (keep_vertex_data) r.vertex.push_back(std::move(D));
    };
}

void check_trim(double trim)
{
    if (!(trim >= 0.0 && trim <= kMaxTrim))
        throw OptionError("local_trim", fmt::format("{} is not a share in [0, {}]", trim, kMaxTrim));
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
                                                bool keep_vertex_data, LocalRoughnessParts parts)
{
    return detail::local_roughness_distance(mesh, pa, other, pb, index, trim, keep_vertex_data, parts, nullptr);
}

LocalRoughnessDistance detail::local_roughness_distance(const Mesh& mesh, const RoughnessProfile& pa, const Mesh& other,
                                                        const RoughnessProfile& pb, const ClosestPointIndex& index,
                                                        double trim, bool keep_vertex_data, LocalRoughnessParts parts,
                                                        std::vector<ClosestPoint>* closest)
{
    if (pa.H.size() != mesh.n_vertices() || pb.H.size() != other.n_vertices())
        throw InvalidArgumentError("local roughness: a profile has no per-vertex H (keep_vertex_data)");
    if (pa.vertices != mesh.n_vertices() || pb.vertices != other.n_vertices())
        throw InvalidArgumentError(
            fmt::format("local roughness: profiles of {} and {} vertices for meshes of {} and {}", pa.vertices,
                        pb.vertices, mesh.n_vertices(), other.n_vertices()));
    check_trim(trim);
    LocalRoughnessDistance r;
    r.vertices = mesh.n_vertices();
    r.vertices_radii = parts.radii ? mesh.n_vertices() : 0;
    r.trim = trim;
    const std::vector<double> F = change_of_H(mesh, pa.H, other, pb.H, index, closest);
    // The operator of mesh's own profile: its rings, its global level, its
    // balls on its normalised mesh; its vertex areas weight the RMS.
    const Mesh unit_mesh = apply_normalization(mesh, pa.normalization);
    const MeshData unit(unit_mesh);  // its box, derived once for the rings and the balls
    const Adjacency adj = vertex_adjacency(unit_mesh);
    const std::vector<double> area = vertex_areas(unit_mesh);
    if (parts.levels) r.levels = common_levels(pa.levels, pb.levels);
    // Folded batch by batch (level_stream.h): D stored only for the maps.
    if (!r.levels.empty())
        detail::fold_levels(unit, adj, F, &area, r.levels, {trim}, keep_vertex_data,
                            level_sink(r, trim, keep_vertex_data));
    if (parts.global && pa.has_global && pb.has_global) {
        r.has_global = true;
        r.global = pool(F, global_means(F), area, trim, nullptr).rms;
    }
    if (parts.radii)
        for (const LevelRoughness& la : pa.radii)
            for (const LevelRoughness& lb : pb.radii)
                if (la.radius == lb.radius) {
                    r.radii.push_back(la.radius);
                    break;
                }
    if (!r.radii.empty()) {
        const BallMeans balls = ball_means(unit, adj, F, area, r.radii);
        for (std::size_t k = 0; k < r.radii.size(); ++k)
            r.rms_radii.push_back(pool(F, balls.mean[k], area, trim, nullptr).rms);
    }
    return r;
}

detail::LocalRingsInProfile::LocalRingsInProfile(const Mesh& mesh, const Mesh& other,
                                                 const RoughnessProfile& other_profile,
                                                 const ClosestPointIndex& other_index, double trim,
                                                 bool keep_vertex_data, bool global, std::vector<ClosestPoint>* closest)
    : mesh_(mesh),
      other_(other),
      other_profile_(other_profile),
      index_(other_index),
      trim_(trim),
      keep_(keep_vertex_data),
      global_(global),
      closest_(closest)
{
    if (other_profile.H.size() != other.n_vertices() || other_profile.vertices != other.n_vertices())
        throw InvalidArgumentError("local roughness: the original's profile has no per-vertex H for its mesh");
    check_trim(trim);
}

std::optional<detail::SecondFold> detail::LocalRingsInProfile::start(const Mesh& unit, const std::vector<double>& H,
                                                                     const std::vector<int>& levels)
{
    if (H.size() != mesh_.n_vertices() || unit.n_vertices() != mesh_.n_vertices())
        throw InvalidArgumentError("local roughness: H is not of the processed mesh's vertices");
    started_ = true;
    F_ = change_of_H(mesh_, H, other_, other_profile_.H, index_, closest_);
    area_ = vertex_areas(unit);
    for (const int l : levels)
        if (std::none_of(other_profile_.levels.begin(), other_profile_.levels.end(),
                         [l](const LevelRoughness& lb) { return lb.level == l; }))
            throw InvalidArgumentError(
                "local roughness: the two profiles' ring levels differ (one search needs the same)");
    r_.levels = levels;
    if (r_.levels.empty()) return std::nullopt;
    return SecondFold{F_, &area_, {trim_}, keep_, level_sink(r_, trim_, keep_)};
}

LocalRoughnessDistance detail::LocalRingsInProfile::finish(const RoughnessProfile& profile)
{
    if (!started_ || profile.vertices != mesh_.n_vertices())
        throw InvalidArgumentError("local roughness: the processed mesh's profile was not made with its hook");
    r_.vertices = mesh_.n_vertices();
    r_.vertices_radii = 0;
    r_.trim = trim_;
    if (global_ && profile.has_global && other_profile_.has_global) {
        r_.has_global = true;
        r_.global = pool(F_, global_means(F_), area_, trim_, nullptr).rms;
    }
    return std::move(r_);
}

}  // namespace meshdiff
