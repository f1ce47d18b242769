#include "meshdiff/roughness/curvature.h"

#include "meshdiff/core/tolerances.h"
#include "meshdiff/error.h"
#include "meshdiff/geometry/cotangent.h"
#include "meshdiff/geometry/normals.h"

#include "core/stage_progress.h"
#include "roughness/hub_tree.h"
#include "roughness/normal_equations.h"

#include <fmt/format.h>
#include <Eigen/QR>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

namespace meshdiff {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Relative rank threshold of the Goldfeather-Interrante fits' QRs.
constexpr double kCubicRankThreshold = 1e-10;

enum class FitResult
{
    Cubic,
    Quadric,
    Failed
};

using detail::dist2;
using detail::HubTree;
using detail::HubTrees;
using detail::kHubDegree;
using detail::Ranked;

// A fit's matrices, with \p Rows7 and \p Rows3 rows at most (Eigen::Dynamic:
// any number, on the heap).
template <int Rows7, int Rows3>
struct FitBuffers
{
    using Matrix7 = Eigen::Matrix<double, Eigen::Dynamic, 7, Eigen::ColMajor, Rows7, 7>;
    using Vector7 = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, Rows7, 1>;
    using Matrix3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::ColMajor, Rows3, 3>;
    using Vector3 = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, Rows3, 1>;
    Matrix7 M;
    Vector7 rhs;
    Matrix3 Q;
    Vector3 qrhs;
    // Kept between vertices: on the heap, Eigen reallocates only when the row count changes.
    Eigen::ColPivHouseholderQR<Matrix7> qr7;
    Eigen::ColPivHouseholderQR<Matrix3> qr3;
};

// The jet fit: 9 columns (x, y, x^2, xy, y^2, x^3, x^2 y, x y^2, y^3; no
// constant, the jet interpolates the vertex), rank threshold of the QR, and
// the squared distance (in units of h) below which a neighbour coincides with
// the vertex.
constexpr int kJetColumns = 9;

// The jet fit's matrices (kJetColumns columns, at most \p Rows rows).
template <int Rows>
struct JetBuffers
{
    using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, Rows, kJetColumns>;
    using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, Rows, 1>;
    Matrix M;
    Vector rhs;
    Eigen::ColPivHouseholderQR<Matrix> qr;
};

// Scratch space per thread: neighbourhood and least-squares system.
struct FitScratch
{
    std::vector<std::uint32_t> nbrs;
    std::vector<std::uint32_t> stamp;  // visited marks for the 2-ring
    std::uint32_t mark = 0;
    std::vector<Ranked> rest, near;  // candidates of a capped 2-ring
    // The least-squares systems: sized at compile time for every fit but a
    // hub's (up to kMaxFitNeighbors neighbours, three rows each), so that no
    // fit allocates; on the heap for a hub's 1-ring. The arithmetic is the
    // same on both (report corpus identical).
    std::unique_ptr<FitBuffers<3 * int(kMaxFitNeighbors), int(kMaxFitNeighbors)>> fixed =
        std::make_unique<FitBuffers<3 * int(kMaxFitNeighbors), int(kMaxFitNeighbors)>>();
    FitBuffers<Eigen::Dynamic, Eigen::Dynamic> heap;
    // The jet fit's (up to kMaxFitNeighbors neighbours; a hub's 1-ring on the heap).
    std::unique_ptr<JetBuffers<int(kMaxFitNeighbors)>> jet_fixed =
        std::make_unique<JetBuffers<int(kMaxFitNeighbors)>>();
    JetBuffers<Eigen::Dynamic> jet_heap;
};

// The fitting neighbourhood of v into s.nbrs: the 1-ring, or, below
// min_neighbors, the 2-ring (1-ring first, then in the order found), cut to
// the 1-ring and the nearest others, kMaxFitNeighbors in all, when larger.
void gather_neighbourhood(std::size_t v, const Mesh& mesh, const Adjacency& adj, const HubTrees& hubs,
                          int min_neighbors, FitScratch& s, bool& widened, bool& capped)
{
    s.nbrs.assign(adj.begin(v), adj.end(v));
    widened = false;
    capped = false;
    if (int(s.nbrs.size()) >= min_neighbors) return;
    widened = true;
    if (++s.mark == 0) {
        std::fill(s.stamp.begin(), s.stamp.end(), 0u);
        s.mark = 1;
    }
    s.stamp[v] = s.mark;
    for (auto w : s.nbrs) s.stamp[w] = s.mark;
    const std::size_t ring1 = s.nbrs.size();
    bool through_hub = false;
    for (std::size_t k = 0; k < ring1; ++k) {
        if (!hubs.slot.empty() && hubs.slot[s.nbrs[k]] >= 0) {
            through_hub = true;
            continue;
        }
        for (auto it = adj.begin(s.nbrs[k]); it != adj.end(s.nbrs[k]); ++it)
            if (s.stamp[*it] != s.mark) {
                s.stamp[*it] = s.mark;
                s.nbrs.push_back(*it);
            }
    }
    if (!through_hub && s.nbrs.size() <= kMaxFitNeighbors) return;

    // Capped: the 1-ring and the `keep` nearest of the rest of the 2-ring. The
    // nearest `keep` of a hub's neighbours outside the 1-ring and v are among
    // its keep + ring1 + 1 nearest (v and the 1-ring can take ring1 places).
    capped = true;
    const Vec3& p = mesh.points[v];
    const std::size_t keep = kMaxFitNeighbors - ring1;
    s.rest.clear();
    for (std::size_t k = ring1; k < s.nbrs.size(); ++k) s.rest.push_back({dist2(mesh.points[s.nbrs[k]], p), s.nbrs[k]});
    for (std::size_t k = 0; k < ring1; ++k) {
        const std::int32_t slot = hubs.slot.empty() ? -1 : hubs.slot[s.nbrs[k]];
        if (slot < 0) continue;
        hubs.trees[std::size_t(slot)].nearest(p, keep + ring1 + 1, s.near);
        for (const Ranked& r : s.near)
            if (s.stamp[r.second] != s.mark) {
                s.stamp[r.second] = s.mark;
                s.rest.push_back(r);
            }
    }
    const std::size_t take = std::min(keep, s.rest.size());
    if (take < s.rest.size()) std::nth_element(s.rest.begin(), s.rest.begin() + std::ptrdiff_t(take), s.rest.end());
    std::sort(s.rest.begin(), s.rest.begin() + std::ptrdiff_t(take));
    s.nbrs.resize(ring1);
    for (std::size_t k = 0; k < take; ++k) s.nbrs.push_back(s.rest[k].second);
}

// The fitting estimators (cubic with quadric fallback, or quadric only).
// `dropped`: set when the cubic system left out a neighbour's normal rows (the
// max_normal_angle_deg rule).
// Any tangent frame (u, w) with u x w = N: the frame of both fits.
std::pair<Vec3, Vec3> tangent_frame(const Vec3& N)
{
    const Vec3 helper = std::abs(N.x()) < 0.6 ? Vec3::UnitX() : (std::abs(N.y()) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ());
    const Vec3 u = N.cross(helper).normalized();
    return {u, N.cross(u)};
}

// h of both fits: the mean distance from p to its fitting neighbours.
double mean_distance(const Mesh& mesh, const Vec3& p, const std::vector<std::uint32_t>& nbrs)
{
    double h = 0.0;
    for (auto q : nbrs) h += (mesh.points[q] - p).norm();
    return h / double(nbrs.size());
}

template <class Buffers>
FitResult fit_with(std::size_t v, const Mesh& mesh, const std::vector<Vec3>& normals, const CurvatureOptions& opt,
                   bool cubic, const std::vector<std::uint32_t>& nbrs, Buffers& s, double& H, bool& dropped)
{
    dropped = false;
    const Vec3& N = normals[v];
    const Vec3& p = mesh.points[v];
    const std::pair<Vec3, Vec3> frame = tangent_frame(N);
    const Vec3 &u = frame.first, &w = frame.second;  // named: lambdas capture them (C++17)

    const std::size_t m = nbrs.size();
    const double h = mean_distance(mesh, p, nbrs);
    if (!(h > 0.0)) return FitResult::Failed;
    const double inv_h = 1.0 / h;
    const double cos_max = std::cos(opt.max_normal_angle_deg * kPi / 180.0);
    // Neighbour q in the scaled tangent frame, and its row weight.
    auto local = [&](std::uint32_t q) {
        const Vec3 d = (mesh.points[q] - p) * inv_h;
        const double x = d.dot(u), y = d.dot(w);
        const double wt =
            opt.weighting == RowWeighting::InverseSquare && (x * x + y * y) > 0.0 ? 2.0 / (x * x + y * y) : 1.0;
        return std::array<double, 4>{x, y, d.dot(N), wt};
    };

    if (cubic) {
        if (s.M.rows() < Eigen::Index(3 * m)) {
            s.M.resize(Eigen::Index(3 * m), 7);
            s.rhs.resize(Eigen::Index(3 * m));
        }
        Eigen::Index r = 0;
        for (auto q : nbrs) {
            const auto [x, y, z, wt] = local(q);
            s.M.row(r) << x * x / 2, x * y, y * y / 2, x * x * x, x * x * y, x * y * y, y * y * y;
            s.M.row(r) *= wt;
            s.rhs(r++) = wt * z;
            const Vec3& n = normals[q];
            const double a = n.dot(u), b = n.dot(w), c = n.dot(N);
            if (c >= cos_max && c > 0.0) {
                s.M.row(r) << x, y, 0, 3 * x * x, 2 * x * y, y * y, 0;
                s.M.row(r) *= wt;
                s.rhs(r++) = -wt * a / c;
                s.M.row(r) << 0, x, y, 0, x * x, 2 * x * y, 3 * y * y;
                s.M.row(r) *= wt;
                s.rhs(r++) = -wt * b / c;
            } else {
                dropped = true;
            }
        }
        if (r >= 7) {
            // Well conditioned (nearly every fit): normal equations; else, or
            // if H is not finite, the QR decides as before.
            std::array<double, 7> Xn;
            if (detail::solve_by_normal_equations<7>(s.M.topRows(r), s.rhs.head(r), kCubicRankThreshold, Xn)) {
                const double Hs = -(Xn[0] + Xn[2]) / 2.0;
                if (std::isfinite(Hs)) {
                    H = Hs * inv_h;
                    return FitResult::Cubic;
                }
            }
            auto& qr = s.qr7;
            qr.setThreshold(kCubicRankThreshold);
            qr.compute(s.M.topRows(r));
            if (qr.rank() == 7) {
                const Eigen::Matrix<double, 7, 1> X = qr.solve(s.rhs.head(r));
                const double Hs = -(X(0) + X(2)) / 2.0;
                if (std::isfinite(Hs)) {
                    H = Hs * inv_h;
                    return FitResult::Cubic;
                }
            }
        }
    }
    // Position-only quadric.
    s.Q.resize(Eigen::Index(m), 3);
    s.qrhs.resize(Eigen::Index(m));
    Eigen::Index r = 0;
    for (auto q : nbrs) {
        const auto [x, y, z, wt] = local(q);
        s.Q.row(r) << wt * x * x / 2, wt * x * y, wt * y * y / 2;
        s.qrhs(r++) = wt * z;
    }
    if (r < 3) return FitResult::Failed;
    auto& qr = s.qr3;
    qr.setThreshold(kCubicRankThreshold);
    qr.compute(s.Q);
    if (qr.rank() < 3) return FitResult::Failed;
    const Eigen::Vector3d X = qr.solve(s.qrhs);
    const double Hs = -(X(0) + X(2)) / 2.0;
    if (!std::isfinite(Hs)) return FitResult::Failed;
    H = Hs * inv_h;
    return FitResult::Quadric;
}

// The jet's neighbourhood: the 2-ring as gather_neighbourhood() makes it
// (capped the same way), widened by the next ring, in the order found, while
// it has fewer than kJetMinNeighbors vertices (never beyond kMaxFitNeighbors).
// `widened`: the 3-ring was used.
void gather_jet_neighbourhood(std::size_t v, const Mesh& mesh, const Adjacency& adj, const HubTrees& hubs,
                              FitScratch& s, bool& widened, bool& capped)
{
    bool two_ring = false;
    // A vertex of kMaxFitNeighbors neighbours or more fits its 1-ring alone (as the other fits do).
    const int widen_below = adj.degree(v) >= kMaxFitNeighbors ? 0 : std::numeric_limits<int>::max();
    gather_neighbourhood(v, mesh, adj, hubs, widen_below, s, two_ring, capped);
    widened = false;
    if (!two_ring || capped || s.nbrs.size() >= kJetMinNeighbors) return;
    // gather_neighbourhood() marked v and the 2-ring with s.mark (it widened: the
    // 1-ring is below INT_MAX); the 2-ring's new shell starts after the 1-ring.
    const std::size_t ring1 = adj.degree(v);
    const std::size_t ring2 = s.nbrs.size();
    for (std::size_t k = ring1; k < ring2 && s.nbrs.size() < kMaxFitNeighbors; ++k) {
        if (!hubs.slot.empty() && hubs.slot[s.nbrs[k]] >= 0) continue;
        for (auto it = adj.begin(s.nbrs[k]); it != adj.end(s.nbrs[k]) && s.nbrs.size() < kMaxFitNeighbors; ++it)
            if (s.stamp[*it] != s.mark) {
                s.stamp[*it] = s.mark;
                s.nbrs.push_back(*it);
                widened = true;
            }
    }
}

// The jet fit's system of v (curvature.h) into s.M and s.rhs: its row count
// and 1 / h, or false where h is not > 0 (the fit fails).
template <class Buffers>
bool jet_system(std::size_t v, const Mesh& mesh, const Vec3& N, const std::vector<std::uint32_t>& nbrs, Buffers& s,
                Eigen::Index& rows, double& inv_h)
{
    const Vec3& p = mesh.points[v];
    const std::pair<Vec3, Vec3> frame = tangent_frame(N);
    const Vec3 &u = frame.first, &w = frame.second;
    const double h = mean_distance(mesh, p, nbrs);
    if (!(h > 0.0)) return false;
    inv_h = 1.0 / h;
    s.M.resize(Eigen::Index(nbrs.size()), kJetColumns);
    s.rhs.resize(Eigen::Index(nbrs.size()));
    // One row per neighbour, scaled by 1 / |d|^4 (d in units of h); the jet
    // passes through the vertex (no constant term). A neighbour on the vertex
    // itself (a duplicated point) says nothing and is left out.
    rows = 0;
    for (auto q : nbrs) {
        const Vec3 d = (mesh.points[q] - p) * inv_h;
        const double d2 = d.squaredNorm();
        if (!(d2 > kJetCoincident)) continue;
        const double x = d.dot(u), y = d.dot(w), wt = 1.0 / (d2 * d2);
        const double mono[kJetColumns] = {x, y, x * x, x * y, y * y, x * x * x, x * x * y, x * y * y, y * y * y};
        for (int c = 0; c < kJetColumns; ++c) s.M(rows, c) = mono[c] * wt;
        s.rhs(rows++) = wt * d.dot(N);
    }
    return true;
}

// The jet fit's result from its system (jet_system()): the cubic jet of the
// normal equations' solution J where it was solved and gives a finite H,
// else the QR's (the cubic jet, then the degree-2 jet on its first 5
// columns). Returns Cubic, or Quadric when the cubic jet was rank-deficient
// and the degree-2 jet gave H.
template <class Buffers>
FitResult jet_result(Buffers& s, Eigen::Index rows, double inv_h, const std::array<double, kJetColumns>* J, double& H,
                     bool& steep)
{
    // H and the steep flag from the jet's first 5 coefficients; false if H is not finite.
    auto mean_curvature_of = [&](double fx, double fy, double fxx_2, double fxy, double fyy_2) {
        const double fxx = 2.0 * fxx_2, fyy = 2.0 * fyy_2;
        const double g = 1.0 + fx * fx + fy * fy;
        const double Hs =
            -((1.0 + fy * fy) * fxx - 2.0 * fx * fy * fxy + (1.0 + fx * fx) * fyy) / (2.0 * g * std::sqrt(g));
        if (!std::isfinite(Hs)) return false;
        H = Hs * inv_h;
        steep = fx * fx + fy * fy > kJetSteepSlope * kJetSteepSlope;
        return true;
    };
    if (J && mean_curvature_of((*J)[0], (*J)[1], (*J)[2], (*J)[3], (*J)[4])) return FitResult::Cubic;
    for (const Eigen::Index cols : {Eigen::Index(kJetColumns), Eigen::Index(5)}) {
        if (rows < cols) continue;
        auto& qr = s.qr;
        qr.setThreshold(kJetRankThreshold);
        qr.compute(s.M.topLeftCorner(rows, cols));
        if (qr.rank() < cols) continue;
        const Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kJetColumns, 1> X = qr.solve(s.rhs.head(rows));
        if (!mean_curvature_of(X(0), X(1), X(2), X(3), X(4))) continue;
        return cols == kJetColumns ? FitResult::Cubic : FitResult::Quadric;
    }
    return FitResult::Failed;
}

// The jet fit (curvature.h): its system, solved by normal equations where
// well conditioned (nearly every fit), else (or if H is not finite) by the QR.
template <class Buffers>
FitResult jet_with(std::size_t v, const Mesh& mesh, const Vec3& N, const std::vector<std::uint32_t>& nbrs, Buffers& s,
                   double& H, bool& steep)
{
    Eigen::Index rows = 0;
    double inv_h = 0.0;
    if (!jet_system(v, mesh, N, nbrs, s, rows, inv_h)) return FitResult::Failed;
    std::array<double, kJetColumns> J;
    const bool solved = rows >= kJetColumns && detail::solve_by_normal_equations<kJetColumns>(
                                                   s.M.topRows(rows), s.rhs.head(rows), kJetRankThreshold, J);
    return jet_result(s, rows, inv_h, solved ? &J : nullptr, H, steep);
}

FitResult fit_vertex(std::size_t v, const Mesh& mesh, const std::vector<Vec3>& normals, const CurvatureOptions& opt,
                     bool cubic, FitScratch& s, double& H, bool& dropped, bool& steep)
{
    steep = false;
    if (opt.method == CurvatureMethod::Jet) {
        if (s.nbrs.size() <= kMaxFitNeighbors) return jet_with(v, mesh, normals[v], s.nbrs, *s.jet_fixed, H, steep);
        return jet_with(v, mesh, normals[v], s.nbrs, s.jet_heap, H, steep);
    }
    if (s.nbrs.size() <= kMaxFitNeighbors) return fit_with(v, mesh, normals, opt, cubic, s.nbrs, *s.fixed, H, dropped);
    return fit_with(v, mesh, normals, opt, cubic, s.nbrs, s.heap, H, dropped);
}

CurvatureField fitted_curvature(const Mesh& mesh, const Adjacency& adj, const std::vector<Vec3>& normals,
                                const CurvatureOptions& opt)
{
    const std::size_t n = mesh.n_vertices();
    const bool cubic = opt.method == CurvatureMethod::GoldfeatherCubic || opt.method == CurvatureMethod::Jet;
    const bool jet = opt.method == CurvatureMethod::Jet;
    CurvatureField field;
    field.H.assign(n, kNaN);
    // bit 0 widened, bit 1 fallback, bit 2 no normal, bit 3 capped, bit 4 normal rows dropped, bit 5 steep jet
    std::vector<unsigned char> how(n, 0);
    HubTrees hubs;
    for (std::size_t v = 0; v < n; ++v)
        if (adj.degree(v) > kHubDegree) {
            if (hubs.slot.empty()) hubs.slot.assign(n, -1);
            hubs.slot[v] = std::int32_t(hubs.trees.size());
            hubs.trees.emplace_back(mesh.points, adj.begin(v), adj.end(v));
        }
    detail::StageProgress stage("curvature", n);
    // A fit's outcome into the field.
    auto record = [&](std::size_t v, FitResult r, double H, bool widened, bool capped, bool dropped, bool steep) {
        if (r == FitResult::Failed) return;
        field.H[v] = H;
        how[v] = static_cast<unsigned char>((widened ? 1 : 0) | (cubic && r == FitResult::Quadric ? 2 : 0) |
                                            (capped ? 8 : 0) | (dropped ? 16 : 0) | (steep ? 32 : 0));
    };
    // With AVX2, the jet fits' normal equations four vertices at a time (the
    // lanes of solve_by_normal_equations_x4(): the factorisation and the
    // triangular solves are chains of dependent steps, which four fits run
    // side by side); every H the same to the last bit as one at a time.
#if defined(__x86_64__)
    const bool x4 = jet && detail::use_avx2();
#else
    const bool x4 = false;
#endif
#pragma omp parallel
    {
        FitScratch s;
        s.stamp.assign(n, 0u);
        // The pending fits of a group: their systems (one buffer each), rows and 1 / h.
        struct Pending
        {
            std::size_t v;
            Eigen::Index rows;
            double inv_h;
            bool widened, capped;
        };
        std::array<Pending, 4> pending{};
        std::array<std::unique_ptr<JetBuffers<int(kMaxFitNeighbors)>>, 4> lanes;
        if (x4)
            for (auto& b : lanes) b = std::make_unique<JetBuffers<int(kMaxFitNeighbors)>>();
        constexpr std::ptrdiff_t kGroup = 4;
        const std::ptrdiff_t groups = (std::ptrdiff_t(n) + kGroup - 1) / kGroup;
#pragma omp for schedule(dynamic, 256)
        for (std::ptrdiff_t ig = 0; ig < groups; ++ig) {
            int waiting = 0;
            for (std::ptrdiff_t iv = ig * kGroup; iv < std::min(std::ptrdiff_t(n), (ig + 1) * kGroup); ++iv) {
                const auto v = std::size_t(iv);
                if (!stage.tick()) continue;
                if (normals[v].squaredNorm() == 0.0) {
                    how[v] = 4;
                    continue;
                }
                bool widened = false, capped = false;
                if (jet)
                    gather_jet_neighbourhood(v, mesh, adj, hubs, s, widened, capped);
                else
                    gather_neighbourhood(v, mesh, adj, hubs, opt.min_neighbors, s, widened, capped);
                if (capped) how[v] = 8;
                if (s.nbrs.size() < 3) continue;
                double H = kNaN;
                bool dropped = false, steep = false;
                if (x4 && s.nbrs.size() <= kMaxFitNeighbors) {
                    Pending& f = pending[std::size_t(waiting)];
                    auto& b = *lanes[std::size_t(waiting)];
                    f = {v, 0, 0.0, widened, capped};
                    if (!jet_system(v, mesh, normals[v], s.nbrs, b, f.rows, f.inv_h)) continue;
                    if (f.rows >= kJetColumns) {
                        ++waiting;
                        continue;
                    }
                    record(v, jet_result(b, f.rows, f.inv_h, nullptr, H, steep), H, widened, capped, false, steep);
                    continue;
                }
                const FitResult r = fit_vertex(v, mesh, normals, opt, cubic, s, H, dropped, steep);
                record(v, r, H, widened, capped, dropped, steep);
            }
#if defined(__x86_64__)
            if (waiting == 0) continue;
            using Rows = decltype(lanes[0]->M.topRows(1));
            using Rhs = decltype(lanes[0]->rhs.head(1));
            // The systems waiting; an idle lane (not read) repeats the first.
            const auto at = [&](int l) { return std::size_t(l < waiting ? l : 0); };
            auto rows_of = [&](int l) { return lanes[at(l)]->M.topRows(pending[at(l)].rows); };
            auto rhs_of = [&](int l) { return lanes[at(l)]->rhs.head(pending[at(l)].rows); };
            std::array<Rows, 4> M{rows_of(0), rows_of(1), rows_of(2), rows_of(3)};
            std::array<Rhs, 4> b{rhs_of(0), rhs_of(1), rhs_of(2), rhs_of(3)};
            const Rows* Mp[4] = {&M[0], &M[1], &M[2], &M[3]};
            const Rhs* bp[4] = {&b[0], &b[1], &b[2], &b[3]};
            std::array<std::array<double, kJetColumns>, 4> J;
            const unsigned solved =
                detail::solve_by_normal_equations_x4<kJetColumns>(Mp, bp, waiting, kJetRankThreshold, J.data());
            for (int l = 0; l < waiting; ++l) {
                const Pending& f = pending[std::size_t(l)];
                double H = kNaN;
                bool steep = false;
                const FitResult r = jet_result(*lanes[std::size_t(l)], f.rows, f.inv_h,
                                               solved >> l & 1u ? &J[std::size_t(l)] : nullptr, H, steep);
                record(f.v, r, H, f.widened, f.capped, false, steep);
            }
#endif
        }
    }
    stage.finish();
    for (std::size_t v = 0; v < n; ++v) {
        if (std::isnan(field.H[v])) ++field.undefined;
        if (how[v] & 1) ++field.widened;
        if (how[v] & 2) ++field.quadric_fallback;
        if (how[v] & 4) ++field.no_normal;
        if (how[v] & 16) ++field.normal_rows_dropped;
        if (how[v] & 32) ++field.steep;
        if (how[v] & 8) {
            ++field.capped;
            if (field.capped_vertices.size() < kCappedVerticesListed) field.capped_vertices.push_back(std::uint32_t(v));
        }
    }
    return field;
}

CurvatureField meyer_curvature(const Mesh& mesh, const std::vector<Vec3>& normals)
{
    // H = -Hn . n with the mean-curvature normal of cotangent.h.
    const std::size_t n = mesh.n_vertices();
    const std::vector<CotangentSums> sums = cotangent_sums_by_face(mesh, degenerate_face_mask(mesh));
    const auto boundary = boundary_vertex_mask(mesh);
    CurvatureField field;
    field.H.assign(n, kNaN);
    for (std::size_t v = 0; v < n; ++v) {
        if (normals[v].squaredNorm() == 0.0) ++field.no_normal;
        if (boundary[v] || normals[v].squaredNorm() == 0.0) continue;
        if (!(sums[v].area4 > 0.0)) continue;
        field.H[v] = -sums[v].curvature_normal().dot(normals[v]);
    }
    for (double h : field.H)
        if (std::isnan(h)) ++field.undefined;
    return field;
}

}  // namespace

CurvatureField mean_curvature(const Mesh& mesh, const Adjacency& adjacency, const std::vector<Vec3>& normals,
                              const CurvatureOptions& options)
{
    if (options.min_neighbors < 3 || options.min_neighbors > 64)
        throw InvalidArgumentError(
            fmt::format("curvature: min_neighbors = {} is outside [3, 64]", options.min_neighbors));
    if (!(options.max_normal_angle_deg > 0.0 && options.max_normal_angle_deg <= 90.0))
        throw InvalidArgumentError(
            fmt::format("curvature: max_normal_angle_deg = {} is outside (0, 90]", options.max_normal_angle_deg));
    if (options.method == CurvatureMethod::Jet && options.weighting != RowWeighting::None)
        throw InvalidArgumentError(
            "curvature: a row weighting applies to the goldfeather and quadric fits; the jet "
            "fit weights its rows itself (1/|d|^4)");
    if (adjacency.size() != mesh.n_vertices() || normals.size() != mesh.n_vertices())
        throw InvalidArgumentError("curvature: adjacency or normals do not match the mesh");
    if (options.method == CurvatureMethod::MeyerCotangent) {
        detail::StageProgress stage("curvature", 1);
        CurvatureField field = meyer_curvature(mesh, normals);
        stage.finish();
        return field;
    }
    return fitted_curvature(mesh, adjacency, normals, options);
}

CurvatureError curvature_error(const std::vector<double>& estimated, const std::vector<double>& reference,
                               const std::vector<char>& skip)
{
    if (estimated.size() != reference.size() || (!skip.empty() && skip.size() != estimated.size()))
        throw InvalidArgumentError(fmt::format("curvature_error: {} estimates, {} reference values, {} skip flags",
                                               estimated.size(), reference.size(), skip.size()));
    CurvatureError e;
    double sum = 0.0;
    for (std::size_t i = 0; i < estimated.size(); ++i) {
        if (!skip.empty() && skip[i]) continue;
        if (std::isnan(estimated[i])) {
            ++e.undefined;
            continue;
        }
        const double d = estimated[i] - reference[i];
        if (std::isnan(d)) continue;
        sum += d * d;
        e.max = std::max(e.max, std::abs(d));
        ++e.compared;
    }
    e.rms = e.compared ? std::sqrt(sum / double(e.compared)) : 0.0;
    return e;
}

CurvatureField mean_curvature(const Mesh& mesh, const CurvatureOptions& options)
{
    return mean_curvature(mesh, vertex_adjacency(mesh), vertex_normals(mesh), options);
}

}  // namespace meshdiff
