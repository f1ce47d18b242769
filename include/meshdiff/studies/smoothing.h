//! \file smoothing.h
//! \brief The five mesh smoothing methods compared in the paper (section
//! 6.2-6.3; METHOD.md section 7), each with post-updating (Jacobi) and
//! pre-updating (Gauss-Seidel).
//!
//! Notation: U(x_i) = (1/n_i) sum_{j in N1(i)} x_j - x_i is the umbrella vector
//! (uniform weights, n_i the valence). Boundary vertices (meshdiff::
//! boundary_vertex_mask: on a boundary or non-manifold edge) never move;
//! isolated vertices never move either. Results are deterministic: the same
//! mesh and options give bitwise the same positions.
//! - Laplacian: x_i += lambda U(x_i).
//! - Taubin (1995): one iteration is a lambda step followed by a mu step of the
//!   Laplacian (lambda > 0, mu < -lambda).
//! - Bilaplacian (Kobbelt, Campagna, Vorsatz, Seidel 1998): U2(x_i) = (1/n_i)
//!   sum_j U(x_j) - U(x_i); x_i -= damping U2(x_i) / nu_i with nu_i = 1 + (1/n_i)
//!   sum_j 1/n_j (damping = 1 is their exact local relaxation).
//! - Mean curvature flow (Desbrun, Meyer, Schroeder, Barr 1999), explicit:
//!   x_i += dt Hn_i with the mean-curvature normal Hn_i = 1/(4 A_i) sum_j (cot
//!   a_ij + cot b_ij) (x_j - x_i), A_i the mixed Voronoi area of Meyer et al.
//!   2002 (Voronoi area for non-obtuse triangles, half or a quarter of the
//!   triangle's area for obtuse ones). |Hn_i| approximates |H|, and Hn points
//!   to the inside of a convex surface, so a sphere of radius r shrinks by
//!   about dt / r per step.
//!   With `implicit` set, each MCF iteration is instead one backward-Euler step
//!   of Desbrun et al.: (D - dt L) X' = D X, D = diag(4 A_i), L the cotangent
//!   Laplacian (L_ij = cot a_ij + cot b_ij, L_ii = -sum_j L_ij), weights and
//!   areas taken from the current positions (semi-implicit), boundary vertices
//!   (and vertices without area) held, their columns moved to the right-hand
//!   side so that the system is symmetric positive definite; solved by
//!   conjugate gradients from the current positions to a relative residual of
//!   1e-13 (sparse LDL^T if that fails); no volume rescaling. It allows large
//!   steps.
//! - Modified mean curvature flow (Ohtake, Belyaev, Bogaevski 2000, eq. 13):
//!   move along the umbrella direction m = U/|U| at the normal speed of mean
//!   curvature flow. With cos t = m . Hn / |Hn|: F = |Hn| m / cos t if cos t >
//!   epsilon, F = 2 Hn - |Hn| m / cos t if cos t < -epsilon, F = 0 otherwise
//!   (and where |Hn| or |U| is zero); x_i += dt F. In both moving branches the
//!   component of F along Hn is |Hn|, the tangential part follows the umbrella,
//!   which evens out triangle shapes.
//!
//! The flows' time step dt = step * e^2, where e is the mean edge length of
//! the mesh before the first iteration: step is dimensionless, so a given step
//! acts alike at every scale (on a regular valence-6 grid, MCF with step s moves
//! like a Laplacian step with lambda about 2 s).
//!
//! Stability of the explicit flows. An explicit step is stable while
//! dt |lambda_max| <= 2 for the linearised operator Hn = M^-1 L X; row i of
//! M^-1 L has Gershgorin radius 2 sum_j |w_ij| / (4 A_i), so dt <= S =
//! min_i 4 A_i / sum_j |w_ij| is sufficient. S is 0.5 e^2 on an equilateral
//! mesh but a few hundredths of e^2 on a noisy scan with 1-degree angles, and
//! mean curvature flow keeps lowering it: it moves vertices along the normal
//! only, so they crowd where the surface recedes (ear tips, rims). Every
//! iteration therefore computes S from the current positions and reports
//! dt / S (SmoothingReport::stability_ratio; above 1 the step may amplify
//! the shortest-wavelength modes). StepControl::Fixed (the default; the
//! paper gives no step, and its reference [4] uses implicit fairing) always
//! takes dt = step e^2. StepControl::Adaptive takes
//! dt_k = min(step e^2, stability * S): every iteration is then a stable step
//! of the same flow, but on a poor mesh a step can be orders of magnitude
//! shorter than asked, so the flow time (SmoothingReport::time) can fall far
//! behind iterations * step. Limiting each vertex's own step instead was
//! tried and rejected: neighbours moving at different speeds fold the ear tips
//! of a noisy bunny even faster (sigma_1 42 after 50 steps against 15 with the
//! fixed step). Implicit MCF needs no limit, but like the explicit flow it
//! degenerates thin features once the flow time reaches a few e^2.
//! Cotangents of (near-)degenerate corners (|cross| <= 1e-12 |a| |b|) count as
//! 0, and a vertex whose mixed area vanishes does not move, so degenerate faces
//! never produce NaN.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/topology.h"
#include "meshdiff/enum_names.h"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace meshdiff {

enum class SmoothingMethod
{
    Laplacian,
    Taubin,
    Bilaplacian,
    MeanCurvatureFlow,
    ModifiedMeanCurvatureFlow
};

//! Post-updating (Jacobi): every new position is computed from the positions
//! of the previous iteration, then all are applied. Pre-updating
//! (Gauss-Seidel): vertices are updated in place in index order, each using the
//! already updated positions of its neighbours.
enum class SmoothingUpdate
{
    Post,
    Pre
};

//! Step control of the explicit flows (mcf, modified-mcf); see above.
enum class StepControl
{
    Fixed,    //!< dt = step e^2 at every iteration (a fixed explicit step; may diverge)
    Adaptive  //!< dt_k = min(step e^2, stability * S of the current mesh)
};

//! Options of smooth(). Only the fields of the chosen method are validated.
//! The most iterations one smoothing takes.
constexpr int kMaxIterations = 1'000'000;

struct SmoothingOptions
{
    SmoothingMethod method = SmoothingMethod::Laplacian;
    SmoothingUpdate update = SmoothingUpdate::Post;
    int iterations = 10;    //!< >= 0; a Taubin iteration is one lambda and one mu step
    double lambda = 0.5;    //!< Laplacian and Taubin step, in (0, 1]
    double mu = -0.53;      //!< Taubin's negative step, mu < -lambda and mu >= -1
    double step = 0.1;      //!< MCF / modified MCF step, in units of the mean edge length squared; in (0, 10]
                            //!< (implicit MCF: in (0, 1000])
    bool implicit = false;  //!< MCF only: backward-Euler steps (post-updating only)
    double damping = 1.0;   //!< bilaplacian relaxation factor, in (0, 1]
    double epsilon = 0.1;   //!< modified MCF: |cos t| below this does not move the vertex; in [0, 1)
    StepControl step_control = StepControl::Fixed;  //!< explicit flows only
    double stability = 0.5;                         //!< adaptive control: fraction of the stability bound S, in (0, 1]
    //! Called once before the first iteration with 0 and after every iteration
    //! k = 1..iterations with the current mesh (for profiles during smoothing).
    std::function<void(int iteration, const Mesh& mesh)> callback;
};

//! What smooth() did; the fields are filled for the explicit flows
//! (mcf without `implicit`, modified-mcf) only.
struct SmoothingReport
{
    std::vector<double> steps;            //!< per iteration: the step taken, in units of mean_edge^2
    std::vector<double> stability_ratio;  //!< per iteration: dt / S (see above); above 1 may diverge
    double time = 0.0;                    //!< flow time: the sum of steps, in units of mean_edge^2
    int unstable_iterations = 0;          //!< iterations with stability_ratio > 1
    double mean_edge = 0.0;               //!< e, the mean edge length before the first iteration
    //! The largest stability_ratio (0 without explicit flow steps).
    double max_stability_ratio() const
    {
        double m = 0.0;
        for (double r : stability_ratio) m = std::max(m, r);
        return m;
    }
};

//! Smooths \p mesh in place (positions only; faces are untouched) with the
//! method, update scheme and parameters of \p options.
//! The rules of \p options for its method (the ranges in the field comments).
//! \throw OptionError naming the field ("smooth.<field>").
void validate(const SmoothingOptions& options);

//! \throw OptionError naming the field ("smooth.<field>") if an option of the chosen
//!        method is out of range.
//! \throw InvalidMeshError if the mesh fails meshdiff::validate().
//! \throw SolverError if an iteration produces a non-finite coordinate (an
//!        explicit flow step too large for the mesh) or the implicit system
//!        cannot be factorised; the mesh then holds the last finite state.
SmoothingReport smooth(Mesh& mesh, const SmoothingOptions& options);

template <>
struct EnumNames<SmoothingMethod>
{
    static constexpr const char* what = "smoothing method";
    static constexpr std::array<EnumName<SmoothingMethod>, 5> names{
        {{SmoothingMethod::Laplacian, "laplacian"},
         {SmoothingMethod::Taubin, "taubin"},
         {SmoothingMethod::Bilaplacian, "bilaplacian"},
         {SmoothingMethod::MeanCurvatureFlow, "mcf"},
         {SmoothingMethod::ModifiedMeanCurvatureFlow, "modified-mcf"}}};
};

template <>
struct EnumNames<SmoothingUpdate>
{
    static constexpr const char* what = "smoothing update";
    static constexpr std::array<EnumName<SmoothingUpdate>, 2> names{
        {{SmoothingUpdate::Post, "post"}, {SmoothingUpdate::Pre, "pre"}}};
};

template <>
struct EnumNames<StepControl>
{
    static constexpr const char* what = "step control";
    static constexpr std::array<EnumName<StepControl>, 2> names{
        {{StepControl::Fixed, "fixed"}, {StepControl::Adaptive, "adaptive"}}};
};

}  // namespace meshdiff
