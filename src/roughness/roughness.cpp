#include "meshdiff/roughness/roughness.h"

#include "meshdiff/error.h"
#include "meshdiff/geometry/normals.h"
#include "meshdiff/geometry/vertex_areas.h"
#include "meshdiff/roughness/metric_levels.h"
#include "meshdiff/roughness/neighborhood.h"

#include "core/release.h"
#include "roughness/level_stream.h"
#include "roughness/profile_keeping_h.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

namespace meshdiff {

std::vector<int> default_levels()
{
    std::vector<int> l(20);
    std::iota(l.begin(), l.end(), 1);
    return l;
}

void validate(const ProfileOptions& options)
{
    if (options.levels.size() > kMaxLevels)
        throw OptionError("profile.levels", fmt::format("more than the limit of {} levels", kMaxLevels));
    for (int l : options.levels)
        if (l < 1 || l > kMaxLevel)
            throw OptionError("profile.levels", fmt::format("level {} is out of 1..{}", l, kMaxLevel));
    check_radii(options.radii);
    if (options.levels.empty() && options.radii.empty() && !options.global)
        throw OptionError("profile.levels",
                          "no level to compute: no ring level, no {profile.radii} and no {profile.global} level");
    if (!is_known(options.normalize)) throw OptionError("profile.normalize", "not a known normalisation");
    if (!is_known(options.curvature.method))
        throw OptionError("profile.curvature.method", "not a known curvature method");
    if (!is_known(options.curvature.weighting))
        throw OptionError("profile.curvature.weighting", "not a known row weighting");
    if (options.curvature.method == CurvatureMethod::Jet && options.curvature.weighting != RowWeighting::None)
        throw OptionError("profile.curvature.weighting",
                          "applies to the goldfeather and quadric fits; the jet fit weights its rows itself (1/|d|^4)");
    if (!(options.outlier_fraction > 0.0 && options.outlier_fraction <= 1.0))
        throw OptionError("profile.outlier_fraction", "must be in (0, 1]");
    if (!(options.trim >= 0.0 && options.trim <= kMaxTrim))
        throw OptionError("profile.trim", fmt::format("{} is not a share in [0, {}]", options.trim, kMaxTrim));
    if (options.bootstrap > kMaxBootstrap)
        throw OptionError("profile.bootstrap",
                          fmt::format("{} resamples is above the limit of {}", options.bootstrap, kMaxBootstrap));
    if (options.paper) {
        const ProfileOptions paper = paper_profile_options();
        auto refuse = [](const char* field, const std::string& value) {
            throw OptionError("profile.paper", fmt::format("is the paper's method (the goldfeather fit without row "
                                                           "weights, the paper's normalisation, untrimmed sigma); "
                                                           "{{{}}} {} contradicts it",
                                                           field, value));
        };
        if (options.curvature.method != paper.curvature.method)
            refuse("profile.curvature.method", to_string(options.curvature.method));
        if (options.curvature.weighting != paper.curvature.weighting)
            refuse("profile.curvature.weighting", to_string(options.curvature.weighting));
        if (options.normalize != paper.normalize) refuse("profile.normalize", to_string(options.normalize));
        if (options.trim != paper.trim) refuse("profile.trim", fmt::format("{:g}", options.trim));
    }
}

ProfileOptions paper_profile_options(ProfileOptions base)
{
    base.paper = true;
    base.curvature.method = CurvatureMethod::GoldfeatherCubic;
    base.curvature.weighting = RowWeighting::None;
    base.normalize = NormalizeMethod::Paper;
    base.trim = 0.0;
    return base;
}

LevelRoughness level_roughness(int level, const std::vector<double>& D, double outlier_fraction)
{
    LevelRoughness r;
    r.level = level;
    std::vector<double> sq;
    sq.reserve(D.size());
    for (double d : D)
        if (!std::isnan(d)) sq.push_back(d * d);
    r.vertices_used = sq.size();
    if (sq.empty()) return r;
    // Plain sum in vertex order: deterministic.
    double total = 0.0;
    for (double v : sq) total += v;
    r.sigma = std::sqrt(total / double(sq.size()));
    if (total > 0.0) {
        const auto k = std::max<std::size_t>(1, std::size_t(std::ceil(outlier_fraction * double(sq.size()))));
        // In place: sq is not needed any more (the top k summed in the order
        // nth_element leaves them, as ever).
        std::nth_element(sq.begin(), sq.begin() + std::ptrdiff_t(k - 1), sq.end(), std::greater<>());
        double top = 0.0;
        for (std::size_t i = 0; i < k; ++i) top += sq[i];
        r.top_share = top / total;
    }
    // The worst vertices by |D| (ties by id: a total order, so the list is
    // unique), kept sorted in one pass over the vertices.
    constexpr std::size_t kWorst = 10;
    auto worse = [&](std::uint32_t a, std::uint32_t b) {
        const double da = std::abs(D[a]), db = std::abs(D[b]);
        return da != db ? da > db : a < b;
    };
    std::array<std::uint32_t, kWorst> top{};
    std::size_t m = 0;
    for (std::size_t i = 0; i < D.size(); ++i) {
        if (std::isnan(D[i])) continue;
        const auto id = std::uint32_t(i);
        if (m == kWorst && !worse(id, top[m - 1])) continue;
        std::size_t at = m < kWorst ? m++ : m - 1;
        for (; at > 0 && worse(id, top[at - 1]); --at) top[at] = top[at - 1];
        top[at] = id;
    }
    r.worst_vertices.assign(top.begin(), top.begin() + std::ptrdiff_t(m));
    return r;
}

double trimmed_rms(const std::vector<double>& D, double trim, const std::vector<double>* weights, std::size_t* dropped)
{
    // The kept vertices: all but the k of largest |D| (ties by id).
    std::vector<std::uint32_t> ids;
    ids.reserve(D.size());
    for (std::size_t i = 0; i < D.size(); ++i)
        if (!std::isnan(D[i])) ids.push_back(std::uint32_t(i));
    const auto k = std::min(ids.size(), std::size_t(std::ceil(trim * double(ids.size()))));
    if (dropped) *dropped = k;
    auto worse = [&](std::uint32_t a, std::uint32_t b) {
        const double da = std::abs(D[a]), db = std::abs(D[b]);
        return da != db ? da > db : a < b;
    };
    if (k > 0) std::nth_element(ids.begin(), ids.begin() + std::ptrdiff_t(k - 1), ids.end(), worse);
    std::sort(ids.begin() + std::ptrdiff_t(k), ids.end());  // the sums in vertex order: deterministic
    double total = 0.0, wtotal = 0.0;
    for (std::size_t j = k; j < ids.size(); ++j) {
        const double w = weights ? (*weights)[ids[j]] : 1.0;
        total += w * D[ids[j]] * D[ids[j]];
        wtotal += w;
    }
    return wtotal > 0.0 ? std::sqrt(total / wtotal) : std::numeric_limits<double>::quiet_NaN();
}

namespace {

// splitmix64: the resamples' random numbers (fast, and the same on every platform).
std::uint64_t splitmix64(std::uint64_t& state)
{
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// A uniform index in [0, m) from 64 random bits (Lemire's multiply-shift; the
// bias, below m / 2^64, is far below anything a resample could show).
std::size_t uniform_index(std::uint64_t bits, std::size_t m)
{
    // The high 64 bits of bits x m, in 32-bit halves (portable C++).
    const std::uint64_t a_hi = bits >> 32, a_lo = bits & 0xFFFFFFFFull;
    const std::uint64_t b_hi = std::uint64_t(m) >> 32, b_lo = std::uint64_t(m) & 0xFFFFFFFFull;
    const std::uint64_t lo_lo = a_lo * b_lo, hi_lo = a_hi * b_lo, lo_hi = a_lo * b_hi, hi_hi = a_hi * b_hi;
    const std::uint64_t cross = (lo_lo >> 32) + (hi_lo & 0xFFFFFFFFull) + lo_hi;
    return std::size_t(hi_hi + (hi_lo >> 32) + (cross >> 32));
}

}  // namespace

std::optional<std::pair<double, double>> bootstrap_interval(const std::vector<double>& D, double trim,
                                                            std::size_t resamples, std::uint64_t seed,
                                                            const std::vector<double>* weights)
{
    std::vector<std::uint32_t> used;
    used.reserve(D.size());
    for (std::size_t i = 0; i < D.size(); ++i)
        if (!std::isnan(D[i])) used.push_back(std::uint32_t(i));
    const std::size_t m = used.size();
    if (resamples == 0 || m == 0) return std::nullopt;
    const std::size_t drop = std::min(m, std::size_t(std::ceil(trim * double(m))));
    std::vector<double> sigma(resamples);
    // Resample b draws its m vertices from its own stream (seed, b): the same
    // sigmas at any thread count. Summed in draw order (with a trim: in the
    // order nth_element leaves the kept ones, deterministic too).
#pragma omp parallel
    {
        std::vector<std::uint32_t> pick(drop > 0 ? m : 0);
#pragma omp for schedule(static)
        for (std::ptrdiff_t ib = 0; ib < std::ptrdiff_t(resamples); ++ib) {
            std::uint64_t state = seed ^ (0xD1B54A32D192ED03ull * (std::uint64_t(ib) + 1));
            double total = 0.0, wtotal = 0.0;
            if (drop == 0) {
                for (std::size_t j = 0; j < m; ++j) {
                    const std::uint32_t i = used[uniform_index(splitmix64(state), m)];
                    const double w = weights ? (*weights)[i] : 1.0;
                    total += w * D[i] * D[i];
                    wtotal += w;
                }
            } else {
                for (std::size_t j = 0; j < m; ++j) pick[j] = used[uniform_index(splitmix64(state), m)];
                // Leave out the drop largest |D| of the resample (ties by id), as trimmed_rms().
                auto worse = [&](std::uint32_t a, std::uint32_t b) {
                    const double da = std::abs(D[a]), db = std::abs(D[b]);
                    return da != db ? da > db : a < b;
                };
                std::nth_element(pick.begin(), pick.begin() + std::ptrdiff_t(drop - 1), pick.end(), worse);
                for (std::size_t j = drop; j < m; ++j) {
                    const double w = weights ? (*weights)[pick[j]] : 1.0;
                    total += w * D[pick[j]] * D[pick[j]];
                    wtotal += w;
                }
            }
            sigma[std::size_t(ib)] = wtotal > 0.0 ? std::sqrt(total / wtotal) : 0.0;
        }
    }
    std::sort(sigma.begin(), sigma.end());
    const double tail = (1.0 - kBootstrapConfidence) / 2.0;
    const auto at = [&](double q) { return sigma[std::size_t(std::llround(q * double(resamples - 1)))]; };
    return std::pair{at(tail), at(1.0 - tail)};
}

namespace {

// sigma of \p l trimmed as \p options ask (nothing changes without a trim).
void apply_trim(LevelRoughness& l, const std::vector<double>& D, const ProfileOptions& options,
                const std::vector<double>* weights = nullptr)
{
    if (!(options.trim > 0.0) || l.vertices_used == 0) return;
    const double s = trimmed_rms(D, options.trim, weights, &l.trimmed);
    l.sigma = std::isnan(s) ? 0.0 : s;
}

// The global level and the metric levels.
void global_and_radii(RoughnessProfile& p, const MeshData& unit, const Adjacency& adj, const std::vector<double>& H,
                      std::size_t undefined, const ProfileOptions& options)
{
    const std::size_t n = H.size();
    std::vector<double> D(n);
    if (options.global) {
        p.has_global = true;
        // Mean over all other vertices with defined H, in O(n).
        D = global_means(H);
        for (std::size_t i = 0; i < n; ++i) D[i] = H[i] - D[i];  // NaN propagates
        p.global = level_roughness(0, D, options.outlier_fraction);
        apply_trim(p.global, D, options);
        p.global.sigma_interval = bootstrap_interval(D, options.trim, options.bootstrap, options.bootstrap_seed);
        p.global.no_neighborhood = (n - undefined) - p.global.vertices_used;
        if (options.keep_vertex_data) p.D_global = D;
    }
    if (!options.radii.empty()) {
        // Metric levels (METHOD.md section 5a): area-weighted ball means.
        const std::vector<double> area = vertex_areas(unit.mesh());
        const BallMeans balls = ball_means(unit, adj, H, area, options.radii);
        p.radii.resize(options.radii.size());
        if (options.keep_vertex_data) p.D_radii.resize(options.radii.size());
        for (std::size_t k = 0; k < options.radii.size(); ++k) {
            for (std::size_t i = 0; i < n; ++i) D[i] = H[i] - balls.mean[k][i];  // NaN propagates
            LevelRoughness lr = weighted_level_roughness(options.radii[k], D, area, options.outlier_fraction);
            apply_trim(lr, D, options, &area);
            lr.sigma_interval = bootstrap_interval(D, options.trim, options.bootstrap, options.bootstrap_seed, &area);
            lr.no_neighborhood = (n - undefined) - lr.vertices_used;
            p.radii[k] = std::move(lr);
            if (options.keep_vertex_data) p.D_radii[k] = D;
        }
    }
}

// Levels and global level from H on the normalised mesh; fills p (and p.H
// with keep_H, as with keep_vertex_data).
void profile_from_H(RoughnessProfile& p, const MeshData& unit, const Adjacency& adj, std::vector<double> H,
                    std::size_t undefined, const ProfileOptions& options, bool keep_H = false,
                    const detail::SecondFold* second = nullptr)
{
    const std::size_t n = H.size();
    p.outlier_fraction = options.outlier_fraction;
    p.trim = options.trim;
    p.bootstrap = options.bootstrap;
    p.bootstrap_seed = options.bootstrap_seed;
    const std::size_t n_levels = options.levels.size();
    p.levels.resize(n_levels);
    // The ring levels' statistics are folded batch by batch (level_stream.h):
    // D itself is stored only when kept or resampled by the bootstrap; the
    // same sums, so the same bits, either way.
    if (options.keep_vertex_data) p.D.resize(n_levels);
    detail::fold_levels(
        unit, adj, H, nullptr, options.levels, {options.outlier_fraction, options.trim},
        options.keep_vertex_data || options.bootstrap > 0,
        [&](std::size_t li, const detail::LevelSums& sums, std::vector<double>& D) {
            LevelRoughness& lr = p.levels[li];
            lr = detail::streamed_level_roughness(options.levels[li], sums, options.outlier_fraction, options.trim);
            lr.no_neighborhood = (n - undefined) - lr.vertices_used;
            if (options.bootstrap > 0)
                lr.sigma_interval = bootstrap_interval(D, options.trim, options.bootstrap, options.bootstrap_seed);
            if (options.keep_vertex_data) p.D[li] = std::move(D);
        },
        second);
    global_and_radii(p, unit, adj, H, undefined, options);
    if (options.keep_vertex_data || keep_H) p.H = std::move(H);
}

}  // namespace

Normalization normalization_of(const Mesh& mesh, NormalizeMethod method)
{
    switch (method) {
        case NormalizeMethod::Paper:
            return unit_normalization(mesh);
        case NormalizeMethod::Area:
            return area_normalization(mesh);
        case NormalizeMethod::Original:
            break;
    }
    throw OptionError("profile.normalize", "original needs two meshes: it is the frame of a comparison's original");
}

RoughnessProfile roughness_profile(const Mesh& mesh, const ProfileOptions& options)
{
    validate(options);
    return roughness_profile(mesh, options, normalization_of(mesh, options.normalize));
}

RoughnessProfile roughness_profile(const Mesh& mesh, const ProfileOptions& options, const Normalization& frame)
{
    return detail::roughness_profile_keeping_H(mesh, options, frame, false);
}

RoughnessProfile detail::roughness_profile_keeping_H(const Mesh& mesh, const ProfileOptions& options,
                                                     const Normalization& frame, bool keep_H,
                                                     const SecondFoldHook& second)
{
    validate(options);
    const ProgressScope scope(options.progress ? options.progress : current_progress());
    check_cancelled(current_progress());
    RoughnessProfile p;
    p.vertices = mesh.n_vertices();
    p.normalization = frame;
    Mesh unit = apply_normalization(mesh, p.normalization);
    check_cancelled(current_progress());  // the serial steps are checked in between
    // The vertex-face incidence gives the adjacency and the normals, both in
    // parallel, and goes before the fits (28 MB a 1M mesh).
    auto incidence = std::make_unique<Adjacency>(vertex_faces(unit));
    const Adjacency adj = vertex_adjacency(unit, *incidence);
    check_ball_work(unit, adj, options.radii);  // before any long work
    check_cancelled(current_progress());
    const MeshData unit_data(unit);  // its box and degenerate faces, derived once
    p.curvature_options = options.curvature;
    // The normals only for the fits: freed before the rings (24 MB a 1M mesh).
    CurvatureField field = [&] {
        const std::vector<Vec3> normals = vertex_normals(unit_data, *incidence);
        incidence.reset();
        return mean_curvature(unit, adj, normals, options.curvature);
    }();
    // A second fold over the rings made from H and the normalised mesh,
    // before its faces go.
    const std::optional<detail::SecondFold> other = second ? second(unit, field.H) : std::nullopt;
    // The rings read the points, the adjacency and unit_data's box (derived
    // above, as its degenerate-face mask): the copy of the faces goes before
    // them (24 MB a 1M mesh), unless the metric levels' vertex areas need it.
    // unit_data derives nothing more from the mesh after this.
    if (options.radii.empty()) {
        (void)unit_data.box();  // derived already by the mask; made sure of
        detail::release(unit.faces);
    }
    p.curvature_undefined = field.undefined;
    p.curvature_widened = field.widened;
    p.curvature_normal_rows_dropped = field.normal_rows_dropped;
    p.curvature_fallback = field.quadric_fallback;
    p.curvature_steep = field.steep;
    p.curvature_capped = field.capped;
    p.curvature_capped_vertices = field.capped_vertices;
    profile_from_H(p, unit_data, adj, std::move(field.H), field.undefined, options, keep_H, other ? &*other : nullptr);
    return p;
}

RoughnessProfile roughness_profile_from_curvature(const Mesh& mesh, const std::vector<double>& H_in,
                                                  const ProfileOptions& options)
{
    validate(options);
    const ProgressScope scope(options.progress ? options.progress : current_progress());
    if (H_in.size() != mesh.n_vertices())
        throw InvalidArgumentError(
            fmt::format("profile: {} curvature values for {} vertices", H_in.size(), mesh.n_vertices()));
    RoughnessProfile p;
    p.vertices = mesh.n_vertices();
    p.normalization = normalization_of(mesh, options.normalize);
    const Mesh unit = apply_normalization(mesh, p.normalization);
    std::vector<double> H(H_in);
    std::size_t undefined = 0;
    for (double& h : H) {
        if (!std::isfinite(h)) {
            h = std::numeric_limits<double>::quiet_NaN();
            ++undefined;
        } else {
            h *= p.normalization.scale;
        }
    }
    p.curvature_undefined = undefined;
    const Adjacency adj = vertex_adjacency(unit);
    check_ball_work(unit, adj, options.radii);
    profile_from_H(p, MeshData(unit), adj, std::move(H), undefined, options);
    return p;
}

ExactProfile exact_profile(const Mesh& mesh, const std::vector<double>& exact_H, const ProfileOptions& options,
                           const RoughnessProfile& estimated)
{
    if (estimated.H.size() != mesh.n_vertices())
        throw InvalidArgumentError("exact_profile: the estimated profile has no per-vertex H (keep_vertex_data)");
    ProfileOptions o = options;
    o.keep_vertex_data = true;
    ExactProfile e;
    e.profile = roughness_profile_from_curvature(mesh, exact_H, o);
    e.h_error = curvature_error(estimated.H, e.profile.H);
    std::vector<char> boundary = boundary_vertex_mask(mesh);
    e.h_error_interior = curvature_error(estimated.H, e.profile.H, boundary);
    for (char& b : boundary) b = b ? 0 : 1;  // now: skip the interior
    e.h_error_boundary = curvature_error(estimated.H, e.profile.H, boundary);
    return e;
}

}  // namespace meshdiff
