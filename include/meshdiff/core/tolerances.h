//! \file core/tolerances.h
//! \brief pi and every degeneracy threshold of the library, in one place, with
//! why they differ (as pmp's tolerances.h and libigl's PI.h / EPS.h).
//!
//! Each threshold guards a different quantity and is set where that quantity
//! stops carrying information in double precision (unit roundoff u = 1.1e-16):
//! - kDegenerateArea is meshdiff's one notion of a degenerate face, shared by
//!   every subsystem (topology.h): twice the area against the squared box
//!   diagonal, so it is scale-free and at 1e-14 (a few hundred u) removes only
//!   faces whose area is rounding of the coordinates.
//! - kThinTriangleSine is a numerical guard of the exact point-triangle query
//!   only (point_triangle.h): below a sine of 1e-8 at a corner, the barycentric
//!   solve loses all of its digits (the error grows as u / sin^2), so the
//!   triangle is queried as the union of its edges, which is exact. It is a
//!   sine, not an area, and it does not make a face degenerate.
//! - kFlatCornerSine guards the cotangent (cotangent.h): cot = cos / sin is
//!   taken as 0 below a sine of 1e-12, where it would be larger than 1e12 and
//!   decided by rounding; the cotangent weights stay finite on any mesh.
//! - kHausdorffRoundingFloor is the smallest tolerance the certified Hausdorff
//!   distance accepts relative to the largest coordinate magnitude (hausdorff.h):
//!   below about 1e-13 the bounds themselves are rounding, so certifying to a
//!   tighter interval would be claiming digits that are not there.
//! - kMinNormalRatio (normals.h): a vertex normal whose area-weighted sum is
//!   shorter than 1e-6 of the summed face areas is undefined (faces that cancel).
//! - kJetRankThreshold and kJetCoincident are the jet fit's (curvature.h): the
//!   relative rank threshold of its column-pivoting QR, and the squared distance
//!   (in units of the local edge length h) below which a neighbour coincides
//!   with the vertex and is left out.
//! - kNormalEquationsMaxCondition and kNormalEquationsRankMargin guard the
//!   curvature fits' fast solve (roughness/normal_equations.h): equilibrated
//!   normal equations square the condition number kappa, so they are used only
//!   where kappa is certainly below 1e4 (kappa^2 u <= 1e-8, which one
//!   refinement step brings to the QR's own rounding) and where the fit's QR
//!   would certainly find full rank, by a factor 1e3 beyond its rank threshold
//!   (kJetRankThreshold); every other fit is solved by the QR as before, so
//!   every rank decision is the QR's.
#pragma once

namespace meshdiff {

//! pi to double precision; the library's one spelling.
constexpr double kPi = 3.14159265358979323846;

//! A face is degenerate (zero area) when |cross| <= kDegenerateArea x diag^2,
//! diag the bounding-box diagonal of its mesh (topology.h).
constexpr double kDegenerateArea = 1e-14;

//! Sine of the angle at corner 0 below which a triangle is queried as the union
//! of its edges (point_triangle.h).
constexpr double kThinTriangleSine = 1e-8;

//! The sine below which a corner's cotangent counts as 0 (cotangent.h).
constexpr double kFlatCornerSine = 1e-12;

//! Floor of the certified Hausdorff tolerance, relative to the largest
//! coordinate magnitude of the two meshes (hausdorff.h).
constexpr double kHausdorffRoundingFloor = 1e-13;

//! A vertex normal is undefined when its area-weighted sum is shorter than this
//! share of the summed areas (normals.h).
constexpr double kMinNormalRatio = 1e-6;

//! Relative rank threshold of the jet fit's QR (curvature.h).
constexpr double kJetRankThreshold = 1e-10;

//! Largest condition number (bounded above) of a curvature fit's column-scaled
//! matrix that is solved by normal equations rather than by the QR
//! (roughness/normal_equations.h).
constexpr double kNormalEquationsMaxCondition = 1e4;

//! A curvature fit is solved by normal equations only when its QR would find
//! full rank with pivots at least 1 / kNormalEquationsRankMargin times its
//! rank threshold (roughness/normal_equations.h).
constexpr double kNormalEquationsRankMargin = 1e-3;

//! Squared distance, in units of h, below which a neighbour coincides with the
//! vertex in the jet fit (curvature.h).
constexpr double kJetCoincident = 1e-20;

}  // namespace meshdiff
