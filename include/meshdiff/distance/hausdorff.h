//! \file hausdorff.h
//! \brief The certified one-sided Hausdorff distance between two triangle
//! meshes: an interval [lower, upper] that contains the true value
//! max over p on A of d(p, B), with upper - lower within a tolerance, and the
//! point of A where the lower bound is attained (docs/accuracy.md).
//!
//! Method: branch and bound over the triangles of A (after Tang, Lee, Kim,
//! "Interactive Hausdorff distance computation for general polygonal models",
//! SIGGRAPH 2009, and CGAL's bounded_error_Hausdorff_distance).
//! - Lower bound: the largest exact distance to B of a point of A evaluated so
//!   far: every vertex of A that a face uses, the maximum of the Metro samples
//!   when given, and every corner the search creates.
//! - Upper bound of a triangle T of A: for any one triangle t of B, the
//!   distance to t is convex over T, so its maximum over T is at a corner of T;
//!   and d(p, B) <= d(p, t). So U(T) = min over t of max over corners c of
//!   d(c, t) bounds d(p, B) on all of T. It is found first among the closest
//!   triangles of T's corners and the triangle that bounded T's parent, then
//!   by a descent over B's edge-adjacent triangles (to a neighbour with a
//!   smaller largest corner distance, while there is one), and only where the
//!   descent ends without a local minimum (a boundary, a cap of 16 steps) or
//!   at the depth limit by a search of B's bounding-volume hierarchy
//!   (ClosestPointIndex::hull_distance_bound()). Where no one triangle is
//!   near enough to all of T (T lies over an edge or a vertex of B), T is cut
//!   along the plane through that edge bisecting the angle between its two
//!   triangles, each part bounded by its own triangle (the maximum over a
//!   convex part is at one of its corners), a part reaching over another edge
//!   cut again (at most 8 cuts deep, 48 parts): around a vertex of B a part is
//!   passed along its fan. Any cut gives a valid bound, since every point of T
//!   lies in a part. A second, cheaper
//!   bound comes first: d(., B) is 1-Lipschitz and every point of T lies
//!   within diam(T) / sqrt(3) of a corner, so U(T) <= max d(c, B) +
//!   diam(T) / sqrt(3). A T too wide for any triangle of B to be near all
//!   its corners (diam(T) > 2 x threshold + B's longest edge) is split
//!   without a search.
//! - Pruning: T is done when U(T) <= lower + tolerance; otherwise it is split
//!   into four at its edge midpoints, whose distances raise the lower bound.
//!   A midpoint is queried exactly only when its distance to a nearby
//!   triangle of B (its edge's corners' closest triangles, then a descent over
//!   their neighbours towards the midpoint) exceeds the lower bound: otherwise
//!   it cannot raise it, and that distance serves as its upper bound.
//!   The upper bound of the result is the largest U of the triangles that
//!   were done, so the interval always contains the true value.
//! - The search runs in rounds (all open triangles of a round in parallel,
//!   the lower bound updated between rounds), so the interval and the
//!   location do not depend on the number of threads.
//! - Memory: when a round would create more triangles than
//!   max_round_triangles, the open triangles beyond the first
//!   max_round_triangles / 4 are set aside and taken up, the last set aside
//!   first, once the others are done (and re-checked against the lower bound
//!   reached by then). Until then the search is breadth-first as above.
//! - It stops when no triangle is open (certified), or when the evaluations of
//!   upper bounds reach a budget: then the interval reached is returned with
//!   `certified` false (never an endless loop on adversarial input).
//!
//! Exactness. Distances are computed in double precision with the exact
//! point-to-triangle query of point_triangle.h; the interval is exact up to
//! that rounding (about 1e-15 of the coordinates) and, for the lower bound,
//! up to the thin-triangle guard of that query (kThinTriangleSine of a thin
//! triangle's longest edge). The tolerance never goes below 1e-13 of the
//! largest coordinate magnitude of the two meshes (the rounding level of the
//! distances), so that two copies of one mesh end at once.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/geometry/closest_point.h"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace meshdiff {

//! The default relative width of the certified interval: four certain digits.
constexpr double kDefaultHausdorffTolerance = 1e-4;

struct HausdorffOptions
{
    //! Width of the interval asked for, relative to the lower bound: 1e-4
    //! gives four certain digits. The larger of this (times the lower bound)
    //! and absolute_tolerance is used.
    double relative_tolerance = kDefaultHausdorffTolerance;
    //! Width asked for in the meshes' length unit (0: relative only).
    double absolute_tolerance = 0.0;
    //! Budget of upper-bound evaluations (triangles of A bounded); 0 means
    //! the default, 2,000,000 + 20 x (#faces of A + #faces of B).
    std::size_t max_evaluations = 0;
    //! The most triangles one round may create (4 per open triangle); each
    //! holds about 130 bytes, so the default bounds a round's memory near
    //! 1 GB. Beyond it the open triangles are taken in parts (see the file
    //! comment); at least 4.
    std::size_t max_round_triangles = std::size_t(1) << 23;
};

//! The limits of HausdorffOptions: relative_tolerance 0 (none) or in
//! [kMinHausdorffTolerance, kMaxHausdorffTolerance] (below 1e-12 the rounding
//! of the distances decides; above 0.5 not one digit is certain), and
//! max_evaluations at most kMaxHausdorffBudget (each open triangle holds about
//! 130 bytes).
constexpr double kMinHausdorffTolerance = 1e-12;
constexpr double kMaxHausdorffTolerance = 0.5;
constexpr std::size_t kMaxHausdorffBudget = 1'000'000'000;

//! \throw OptionError naming the field unless relative_tolerance is 0 or
//! within its limits, absolute_tolerance is finite and >= 0, at least one
//! of them is > 0, max_evaluations <= kMaxHausdorffBudget and
//! max_round_triangles >= 4.
void validate(const HausdorffOptions& options);

//! Where a one-sided Hausdorff distance is attained: a point of the sampled
//! mesh and its closest point on the other.
struct HausdorffLocation
{
    Vec3 point = Vec3::Zero();          //!< on the sampled mesh A
    std::uint32_t face = 0;             //!< a face of A holding it (lowest index among its sources)
    Vec3 closest_point = Vec3::Zero();  //!< the closest point of B
    std::uint32_t closest_face = 0;     //!< the face of B holding it (lowest index on ties)
};

//! A certified one-sided Hausdorff distance, in the meshes' length unit.
struct CertifiedHausdorff
{
    double lower = 0.0;      //!< the distance of `location.point` to B: a point value, so h >= lower
    double upper = 0.0;      //!< h <= upper
    double tolerance = 0.0;  //!< the width asked for, in the length unit, at the final lower bound
    bool certified = false;  //!< upper - lower <= tolerance (false only when the budget ran out)
    HausdorffLocation location;
    std::size_t bound_evaluations = 0;  //!< upper bounds of triangles evaluated
    std::size_t point_evaluations = 0;  //!< exact point distances evaluated (vertices and new corners)
    int rounds = 0;                     //!< subdivision rounds run
    //! Times open triangles were set aside because a round would have created
    //! more than max_round_triangles (0: the search was breadth-first throughout).
    int chunks = 0;
    bool budget_exhausted = false;  //!< the search stopped at max_evaluations
};

//! A seed of the lower bound: a point of A with its exact distance to B (the
//! largest Metro sample, for example).
struct HausdorffSeed
{
    Vec3 point = Vec3::Zero();
    std::uint32_t face = 0;  //!< a face of A holding the point
    double distance = 0.0;   //!< its exact distance to B
};

//! The one-sided Hausdorff distance from \p a to \p b (indexed by \p b_index,
//! built from \p b), certified as described in the file comment. \p seed, when
//! given, joins the lower bound (so lower >= seed->distance).
//! \throw InvalidArgumentError for invalid options or an index that does not
//!        hold B's faces.
//! \throw InvalidMeshError if a mesh is invalid (meshdiff::validate(): no
//!        face, an index out of range, a non-finite coordinate).
CertifiedHausdorff certified_hausdorff(const Mesh& a, const Mesh& b, const ClosestPointIndex& b_index,
                                       const HausdorffOptions& options = {},
                                       const std::optional<HausdorffSeed>& seed = std::nullopt);

//! As above, building the index of \p b.
CertifiedHausdorff certified_hausdorff(const Mesh& a, const Mesh& b, const HausdorffOptions& options = {});

}  // namespace meshdiff
