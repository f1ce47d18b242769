#include "meshdiff/studies/smoothing.h"

#include "meshdiff/error.h"
#include "meshdiff/geometry/cotangent.h"

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace meshdiff {

namespace {

void require(bool ok, const char* field, const std::string& what)
{
    if (!ok) throw OptionError(std::string("smooth.") + field, what);
}

}  // namespace

void validate(const SmoothingOptions& o)
{
    require(is_known(o.method), "method", fmt::format("is not a SmoothingMethod (got {})", int(o.method)));
    require(is_known(o.update), "update", fmt::format("is not a SmoothingUpdate (got {})", int(o.update)));
    require(is_known(o.step_control), "step_control",
            fmt::format("is not a StepControl (got {})", int(o.step_control)));
    require(o.iterations >= 0 && o.iterations <= kMaxIterations, "iterations",
            fmt::format("{} is outside 0..{}", o.iterations, kMaxIterations));
    const bool flow =
        o.method == SmoothingMethod::MeanCurvatureFlow || o.method == SmoothingMethod::ModifiedMeanCurvatureFlow;
    require(!o.implicit || o.method == SmoothingMethod::MeanCurvatureFlow, "implicit",
            "applies to mean curvature flow (mcf) only");
    require(!o.implicit || o.update == SmoothingUpdate::Post, "implicit", "is a simultaneous solve: use post-updating");
    if (o.method == SmoothingMethod::Laplacian || o.method == SmoothingMethod::Taubin)
        require(std::isfinite(o.lambda) && o.lambda > 0 && o.lambda <= 1, "lambda",
                fmt::format("must be in (0, 1] (got {})", o.lambda));
    if (o.method == SmoothingMethod::Taubin)
        require(std::isfinite(o.mu) && o.mu < -o.lambda && o.mu >= -1, "mu",
                fmt::format("must be < -lambda = {} and >= -1 (got {})", -o.lambda, o.mu));
    if (o.method == SmoothingMethod::Bilaplacian)
        require(std::isfinite(o.damping) && o.damping > 0 && o.damping <= 1, "damping",
                fmt::format("must be in (0, 1] (got {})", o.damping));
    if (o.method == SmoothingMethod::ModifiedMeanCurvatureFlow)
        require(std::isfinite(o.epsilon) && o.epsilon >= 0 && o.epsilon < 1, "epsilon",
                fmt::format("must be in [0, 1) (got {})", o.epsilon));
    if (flow && !o.implicit)
        require(std::isfinite(o.stability) && o.stability > 0 && o.stability <= 1, "stability",
                fmt::format("must be in (0, 1] (got {})", o.stability));
    if (flow) {
        const double max_step = o.implicit ? 1000.0 : 10.0;
        require(std::isfinite(o.step) && o.step > 0 && o.step <= max_step, "step",
                fmt::format("must be in (0, {}] (got {})", max_step, o.step));
    }
}

namespace {

// Umbrella vector of vertex i from the positions p.
Vec3 umbrella(const Adjacency& adj, const std::vector<Vec3>& p, std::size_t i)
{
    const std::size_t n = adj.degree(i);
    if (n == 0) return Vec3::Zero();
    Vec3 sum = Vec3::Zero();
    for (auto j = adj.begin(i); j != adj.end(i); ++j) sum += p[*j];
    return sum / double(n) - p[i];
}

// One backward-Euler MCF step (Desbrun et al. 1999): (D - dt L) X' = D X with
// D = diag(4 A_mixed), L the cotangent Laplacian; fixed vertices keep their
// positions, as do vertices without area. Their columns move to the right-hand
// side, so the matrix of the free vertices is symmetric positive definite
// (L is symmetric negative semidefinite).
void implicit_mcf_step(const Mesh& mesh, const Adjacency& vf, const std::vector<char>& fixed, double dt,
                       std::vector<Vec3>& p)
{
    const CotangentSystem system = backward_euler_system(mesh, vf, fixed, dt, p);
    const Eigen::Index free = system.free();
    if (free == 0) return;
    const Eigen::SparseMatrix<double>& a = system.matrix;
    const Eigen::MatrixXd& rhs = system.rhs;
    // Conjugate gradients (Jacobi preconditioner) from the current positions:
    // for the usual steps the system is dominated by D and converges in tens
    // of iterations, far faster than a factorisation of a large mesh; single
    // threaded, so the result does not depend on the thread count. Sparse
    // Cholesky is the fallback.
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
    cg.setTolerance(1e-13);
    cg.setMaxIterations(std::max<Eigen::Index>(1000, free / 10));
    cg.compute(a);
    Eigen::MatrixXd x = cg.solveWithGuess(rhs, system.positions);
    if (cg.info() != Eigen::Success || !x.allFinite()) {
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
        ldlt.compute(a);
        if (ldlt.info() != Eigen::Success)
            throw SolverError("smooth: implicit mcf: the system could not be factorised");
        x = ldlt.solve(rhs);
        if (ldlt.info() != Eigen::Success || !x.allFinite())
            throw SolverError("smooth: implicit mcf: the solve failed");
    }
    for (std::size_t i = 0; i < p.size(); ++i)
        if (system.index[i] >= 0) p[i] = x.row(system.index[i]).transpose();
}

// Ohtake et al. (2000) eq. 13: move along the umbrella at MCF normal speed.
Vec3 modified_flow(const Vec3& hn, const Vec3& u, double epsilon)
{
    const double h = hn.norm(), ul = u.norm();
    if (!(h > 0) || !(ul > 0)) return Vec3::Zero();
    const Vec3 m = u / ul;
    const double c = m.dot(hn) / h;
    if (c > epsilon) return (h / c) * m;
    if (c < -epsilon) return 2 * hn - (h / c) * m;
    return Vec3::Zero();
}

class Smoother
{
public:
    Smoother(Mesh& mesh, const SmoothingOptions& o)
        : mesh_(mesh),
          o_(o),
          adj_(vertex_adjacency(mesh)),
          fixed_(boundary_vertex_mask(mesh)),
          pre_(o.update == SmoothingUpdate::Pre)
    {
        if (o.method == SmoothingMethod::MeanCurvatureFlow || o.method == SmoothingMethod::ModifiedMeanCurvatureFlow) {
            vf_ = vertex_faces(mesh);
            const double e = mean_edge_length(mesh, adj_);
            e2_ = e * e;
            dt_ = o.step * e2_;
        }
        if (o.method == SmoothingMethod::Bilaplacian) {
            inv_nu_.assign(mesh.n_vertices(), 0.0);
            for (std::size_t i = 0; i < adj_.size(); ++i) {
                const std::size_t n = adj_.degree(i);
                if (n == 0) continue;
                double s = 0;
                for (auto j = adj_.begin(i); j != adj_.end(i); ++j)
                    if (adj_.degree(*j) > 0) s += 1.0 / double(adj_.degree(*j));
                inv_nu_[i] = 1.0 / (1.0 + s / double(n));
            }
        }
        for (std::size_t i = 0; i < fixed_.size(); ++i)
            if (adj_.degree(i) == 0) fixed_[i] = 1;
    }

    //! Runs one iteration; returns the step taken (units of e^2) and its
    //! ratio to the stability bound for the explicit flows, zeros otherwise.
    std::pair<double, double> iterate()
    {
        switch (o_.method) {
            case SmoothingMethod::Laplacian:
                sweep([&](const std::vector<Vec3>& p, std::size_t i) -> Vec3 {
                    return o_.lambda * umbrella(adj_, p, i);
                });
                break;
            case SmoothingMethod::Taubin:
                sweep([&](const std::vector<Vec3>& p, std::size_t i) -> Vec3 {
                    return o_.lambda * umbrella(adj_, p, i);
                });
                sweep([&](const std::vector<Vec3>& p, std::size_t i) -> Vec3 { return o_.mu * umbrella(adj_, p, i); });
                break;
            case SmoothingMethod::Bilaplacian:
                if (pre_) {
                    sweep([&](const std::vector<Vec3>& p, std::size_t i) -> Vec3 { return bilaplacian_step(p, i); });
                } else {
                    // Umbrellas of all vertices once, then U2 from them.
                    const std::vector<Vec3>& p = mesh_.points;
                    u_.resize(p.size());
                    const auto n = std::ptrdiff_t(p.size());
#pragma omp parallel for schedule(static)
                    for (std::ptrdiff_t k = 0; k < n; ++k) u_[std::size_t(k)] = umbrella(adj_, p, std::size_t(k));
                    sweep([&](const std::vector<Vec3>&, std::size_t i) -> Vec3 {
                        return Vec3(-o_.damping * inv_nu_[i] *
                                    umbrella2(i, [&](std::size_t j) -> Vec3 { return u_[j]; }));
                    });
                }
                break;
            case SmoothingMethod::MeanCurvatureFlow: {
                if (o_.implicit) {
                    implicit_mcf_step(mesh_, vf_, fixed_, dt_, mesh_.points);
                    return {o_.step, 0.0};
                }
                const FlowStep s = flow_step();
                sweep([&](const std::vector<Vec3>& p, std::size_t i) -> Vec3 { return Vec3(s.dt * hn(p, i)); });
                return {s.dt == dt_ ? o_.step : s.dt / e2_, s.dt / s.stable};
            }
            case SmoothingMethod::ModifiedMeanCurvatureFlow: {
                const FlowStep s = flow_step();
                sweep([&](const std::vector<Vec3>& p, std::size_t i) -> Vec3 {
                    return Vec3(s.dt * modified_flow(hn(p, i), umbrella(adj_, p, i), o_.epsilon));
                });
                return {s.dt == dt_ ? o_.step : s.dt / e2_, s.dt / s.stable};
            }
        }
        return {0.0, 0.0};
    }

    double mean_edge() const
    {
        return std::sqrt(e2_);
    }

private:
    struct FlowStep
    {
        double dt;      // the step to take
        double stable;  // the sufficient stability bound min_i 4 A_i / sum_j |w_ij|
    };

    // The time step of an explicit flow iteration from the current positions:
    // the nominal dt, or with adaptive control at most `stability` times the
    // stability bound (see smoothing.h).
    FlowStep flow_step()
    {
        const std::vector<Vec3>& p = mesh_.points;
        if (!pre_) hn_.assign(p.size(), Vec3::Zero());
        const auto n = std::ptrdiff_t(p.size());
        double bound = std::numeric_limits<double>::infinity();
        // min is exact and order-independent: the result does not depend on the thread count.
#pragma omp parallel for schedule(static) reduction(min : bound)
        for (std::ptrdiff_t k = 0; k < n; ++k) {
            const auto i = std::size_t(k);
            if (fixed_[i]) continue;
            const CotangentSums c = cotangent_sums(mesh_, vf_, p, i);
            if (c.area4 > 0 && c.abs_weights > 0) bound = std::min(bound, c.area4 / c.abs_weights);
            if (!pre_) hn_[i] = c.curvature_normal();  // the post-updating sweep reads these positions' Hn
        }
        if (o_.step_control == StepControl::Fixed) return {dt_, bound};
        return {std::min(dt_, o_.stability * bound), bound};
    }

    // Hn of vertex i at positions p: kept by flow_step() when post-updating
    // (p are then the positions it saw), computed in place when pre-updating.
    Vec3 hn(const std::vector<Vec3>& p, std::size_t i) const
    {
        return pre_ ? curvature_normal(mesh_, vf_, p, i) : hn_[i];
    }

    template <class UmbrellaOf>
    Vec3 umbrella2(std::size_t i, UmbrellaOf&& u) const
    {
        const std::size_t n = adj_.degree(i);
        Vec3 sum = Vec3::Zero();
        for (auto j = adj_.begin(i); j != adj_.end(i); ++j) sum += u(*j);
        return sum / double(n) - u(i);
    }

    Vec3 bilaplacian_step(const std::vector<Vec3>& p, std::size_t i) const
    {
        const Vec3 u2 = umbrella2(i, [&](std::size_t j) -> Vec3 { return umbrella(adj_, p, j); });
        return -o_.damping * inv_nu_[i] * u2;
    }

    // One pass over all movable vertices with displacement d(p, i): Jacobi
    // (all displacements from the same positions) or Gauss-Seidel (in place).
    template <class Displacement>
    void sweep(Displacement&& d)
    {
        std::vector<Vec3>& p = mesh_.points;
        if (pre_) {
            for (std::size_t i = 0; i < p.size(); ++i)
                if (!fixed_[i]) p[i] += d(p, i);
        } else {
            delta_.assign(p.size(), Vec3::Zero());
            const auto n = std::ptrdiff_t(p.size());
            // Independent per vertex, so the result does not depend on the thread count.
#pragma omp parallel for schedule(static)
            for (std::ptrdiff_t k = 0; k < n; ++k) {
                const auto i = std::size_t(k);
                if (!fixed_[i]) delta_[i] = d(p, i);
            }
            for (std::size_t i = 0; i < p.size(); ++i) p[i] += delta_[i];
        }
    }

    Mesh& mesh_;
    const SmoothingOptions& o_;
    Adjacency adj_;
    Adjacency vf_;
    std::vector<char> fixed_;
    std::vector<double> inv_nu_;
    std::vector<Vec3> u_, delta_, hn_;
    double dt_ = 0.0;
    double e2_ = 1.0;
    bool pre_;
};

bool all_finite(const std::vector<Vec3>& p)
{
    for (const auto& x : p)
        if (!x.allFinite()) return false;
    return true;
}

}  // namespace

SmoothingReport smooth(Mesh& mesh, const SmoothingOptions& options)
{
    validate(options);
    validate(mesh, "smooth");
    SmoothingReport report;
    if (options.callback) options.callback(0, mesh);
    if (options.iterations == 0) return report;
    Smoother smoother(mesh, options);
    const bool flow = (options.method == SmoothingMethod::MeanCurvatureFlow && !options.implicit) ||
                      options.method == SmoothingMethod::ModifiedMeanCurvatureFlow;
    if (options.method == SmoothingMethod::MeanCurvatureFlow ||
        options.method == SmoothingMethod::ModifiedMeanCurvatureFlow)
        report.mean_edge = smoother.mean_edge();
    std::vector<Vec3> previous;
    for (int k = 1; k <= options.iterations; ++k) {
        previous = mesh.points;
        const auto [step, ratio] = smoother.iterate();
        if (flow) {
            report.steps.push_back(step);
            report.stability_ratio.push_back(ratio);
            report.time += step;
            if (ratio > 1) ++report.unstable_iterations;
        }
        if (!all_finite(mesh.points)) {
            mesh.points = std::move(previous);
            throw SolverError(fmt::format(
                "smooth: {} iteration {} produced a non-finite coordinate (step {} too large for this mesh?)",
                to_string(options.method), k, options.step));
        }
        if (options.callback) options.callback(k, mesh);
    }
    return report;
}

}  // namespace meshdiff
