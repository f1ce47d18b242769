//! \file curvature.h
//! \brief Per-vertex mean curvature H (METHOD.md section 4).
//!
//! Convention: H = (k1 + k2) / 2 with the sign chosen so that convex regions
//! with outward normals are positive; a sphere of radius r gives H = +1/r. The
//! unit is 1 / (the mesh's length unit): roughness_profile() calls this on the
//! normalised mesh, so there H is dimensionless.
//!
//! Estimators:
//! - GoldfeatherCubic (the paper's): Goldfeather & Interrante, "A Novel
//!   Cubic-Order Algorithm for Approximating Principal Direction Vectors",
//!   ACM TOG 23(1), 2004. Least-squares fit of
//!   z = A/2 x^2 + B xy + C/2 y^2 + D x^3 + E x^2 y + F x y^2 + G y^3
//!   in the tangent frame of the vertex normal to the neighbours' positions
//!   and normals; H = -(A + C) / 2. Solved by column-pivoting Householder QR in
//!   local coordinates divided by h, the mean distance from the vertex to its
//!   fitting neighbours (then H = H' / h). This is not only conditioning: a
//!   position row's residual is a length and a normal row's a slope, so the
//!   division makes their relative weight independent of the local edge
//!   length. It changes the estimate, for the better (METHOD.md section 4:
//!   H error RMS on the irregular unit sphere of 3,072 vertices 0.117 without,
//!   0.079 with; ellipsoid 1.5:1:1 0.0054 vs 0.0046).
//!   Robustness rules of METHOD.md: fit on the 1-ring, widened to the 2-ring
//!   when the 1-ring has fewer than `min_neighbors` vertices; a neighbour's two
//!   normal rows are used only if its normal is within `max_normal_angle_deg`
//!   of the vertex normal; if the system is rank-deficient, fall back to the
//!   position-only quadric; if that fails too, H is undefined (NaN).
//!   Cap of the widened neighbourhood (not in METHOD.md; docs/accuracy.md):
//!   a 2-ring of more than kMaxFitNeighbors vertices, which only a vertex
//!   beside a hub of very high valence has (a fan of 100,000 triangles around
//!   one vertex: every rim vertex's 2-ring holds the whole rim), is cut to its
//!   1-ring plus the nearest other 2-ring vertices, kMaxFitNeighbors in all
//!   ("nearest": by squared distance, ties by the lower vertex id; these
//!   follow the 1-ring nearest first). Without the cap such a mesh costs
//!   valence^2 (20,000 fits of 20,000 neighbours at valence 20,000). The largest
//!   2-ring of any vertex of the meshes in ../shared/data/meshes is 88
//!   (teapot.obj), so no real mesh is affected (a latitude-longitude sphere
//!   is, beside its poles, from 250 longitudes on); capped fits are counted
//!   (CurvatureField::capped) and reported as a warning.
//! - Quadric: the position-only quadric z = A/2 x^2 + B xy + C/2 y^2 on the
//!   same neighbourhood (Goldfeather & Interrante's "method 2").
//! - MeyerCotangent: Meyer, Desbrun, Schroeder, Barr, "Discrete
//!   Differential-Geometry Operators for Triangulated 2-Manifolds", VisMath
//!   2002: cotangent formula with mixed Voronoi areas (cotangent.h), H = -Hn . n
//!   = K(x).n / 2. Undefined on boundary and non-manifold-edge vertices.
//! - Jet (the default since issue 28: it converges on irregular meshes,
//!   docs/accuracy.md): an osculating jet (Cazals & Pouget, "Estimating differential
//!   quantities using polynomial fitting of osculating jets", CAGD 22(2),
//!   2005), in its interpolating form: the least-squares fit of the cubic
//!   z = J1 x + J2 y + J3 x^2 + J4 xy + J5 y^2 + J6 x^3 + J7 x^2 y + J8 xy^2 + J9 y^3
//!   through the vertex to its 2-ring (widened to the 3-ring below
//!   kJetMinNeighbors neighbours; capped as above), positions only, in the
//!   frame of the vertex normal and in coordinates divided by h; each row is
//!   scaled by 1 / |d|^4 (d the neighbour's offset in units of h), so the
//!   1-ring leads and the outer ring fixes the cubic terms; a neighbour on the
//!   vertex itself (a duplicated point) is left out. H is the mean curvature
//!   of that graph at (0, 0), with its slope:
//!   H = -((1 + fy^2) fxx - 2 fx fy fxy + (1 + fx^2) fyy) / (2 (1 + fx^2 + fy^2)^(3/2)).
//!   Unlike the Goldfeather-Interrante fit it has linear terms and uses no
//!   vertex normals, so an O(h) error of the vertex normal only tilts the
//!   frame instead of entering H as O(1): it converges as h^2 on irregular
//!   triangulations where the cubic fit stalls (docs/accuracy.md). The
//!   weighting, min_neighbors and max_normal_angle_deg options do not apply
//!   (a weighting other than None is refused). Rank-deficient: the degree-2
//!   jet (5 columns) on the same points; failing that, H is undefined.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/topology.h"
#include "meshdiff/enum_names.h"

#include <cstdint>
#include <string>
#include <vector>

namespace meshdiff {

enum class CurvatureMethod
{
    GoldfeatherCubic,
    Quadric,
    MeyerCotangent,
    Jet
};

//! Per-neighbour weighting of the least-squares rows of the fitting methods.
enum class RowWeighting
{
    None,          //!< all rows weight 1
    InverseSquare  //!< each neighbour's rows times 2 / (x^2 + y^2) (mymesh, curvpack)
};

template <>
struct EnumNames<CurvatureMethod>
{
    static constexpr const char* what = "curvature method";
    static constexpr std::array<EnumName<CurvatureMethod>, 4> names{{{CurvatureMethod::GoldfeatherCubic, "goldfeather"},
                                                                     {CurvatureMethod::Quadric, "quadric"},
                                                                     {CurvatureMethod::MeyerCotangent, "meyer"},
                                                                     {CurvatureMethod::Jet, "jet"}}};
};

template <>
struct EnumNames<RowWeighting>
{
    static constexpr const char* what = "row weighting";
    static constexpr std::array<EnumName<RowWeighting>, 2> names{
        {{RowWeighting::None, "none"}, {RowWeighting::InverseSquare, "inverse-square"}}};
};

//! Largest fitting neighbourhood of a widened (2-ring) fit: see the file
//! comment. Fits on the 1-ring are never capped.
constexpr std::size_t kMaxFitNeighbors = 256;

//! The jet fit widens its 2-ring to the 3-ring when the 2-ring has fewer
//! neighbours than this (a cubic jet has 10 coefficients).
constexpr std::size_t kJetMinNeighbors = 15;

//! A jet fit is steep when the slope of its graph at the vertex, |grad f|,
//! exceeds this (tan 30 degrees): the fitted tangent plane is tilted by more
//! than 30 degrees from the vertex normal. Many steep fits mean a surface
//! rough at the scale of its edges (noise of the order of an edge length),
//! where the jet's H stops growing with the roughness (docs/accuracy.md).
constexpr double kJetSteepSlope = 0.57735026918962573;

//! Share of steep jet fits above which a profile warns (WarningKind::SteepFits).
constexpr double kJetSteepShare = 0.1;

//! How many capped vertex ids CurvatureField::capped_vertices keeps.
constexpr std::size_t kCappedVerticesListed = 10;

struct CurvatureOptions
{
    CurvatureMethod method = CurvatureMethod::Jet;  //!< estimator (the default since issue 28: docs/accuracy.md)
    RowWeighting weighting = RowWeighting::None;    //!< row weighting of the fits (measured: see README)
    int min_neighbors = 6;                          //!< widen to the 2-ring below this 1-ring size
    double max_normal_angle_deg = 60.0;             //!< use a neighbour's normal rows only within this angle
};

//! H per vertex (NaN where undefined) and how each vertex was estimated.
struct CurvatureField
{
    std::vector<double> H;
    std::size_t undefined = 0;  //!< vertices with NaN H
    std::size_t widened = 0;    //!< fits that used the 2-ring (Jet: the 3-ring)
    //! Cubic fits (GoldfeatherCubic) with a defined H that left out the two
    //! normal rows of at least one neighbour (max_normal_angle_deg rule), the
    //! fits that fell back to the quadric included; 0 for the other methods.
    std::size_t normal_rows_dropped = 0;
    std::size_t quadric_fallback = 0;  //!< cubic fits that fell back to the quadric (Jet: to the degree-2 jet)
    std::size_t steep = 0;             //!< jet fits steeper than kJetSteepSlope (Jet only)
    std::size_t no_normal = 0;         //!< vertices without a vertex normal (all faces degenerate)
    std::size_t capped = 0;            //!< 2-ring neighbourhoods cut to kMaxFitNeighbors (fit defined or not)
    std::vector<std::uint32_t> capped_vertices;  //!< the lowest ids of those (at most kCappedVerticesListed)
};

//! The error of an estimated H against a reference H (an exact one).
struct CurvatureError
{
    double rms = 0.0;           //!< sqrt(mean of (H - H_ref)^2) over the compared vertices (0 if none)
    double max = 0.0;           //!< max |H - H_ref|
    std::size_t compared = 0;   //!< vertices compared
    std::size_t undefined = 0;  //!< vertices skipped because the estimate is NaN
};

//! The error of \p estimated against \p reference, vertex by vertex in index
//! order, leaving out vertices whose \p skip flag is set (if \p skip is
//! given), whose estimate is NaN (counted as undefined) or whose reference is
//! NaN.
//! \throw InvalidArgumentError if the sizes differ.
CurvatureError curvature_error(const std::vector<double>& estimated, const std::vector<double>& reference,
                               const std::vector<char>& skip = {});

//! Mean curvature of every vertex of \p mesh (in the mesh's own units).
//! \throw InvalidArgumentError for out-of-range options.
CurvatureField mean_curvature(const Mesh& mesh, const CurvatureOptions& options = {});

//! The same with the adjacency and vertex normals already computed
//! (vertex_adjacency(mesh), vertex_normals(mesh)).
CurvatureField mean_curvature(const Mesh& mesh, const Adjacency& adjacency, const std::vector<Vec3>& normals,
                              const CurvatureOptions& options = {});

}  // namespace meshdiff
