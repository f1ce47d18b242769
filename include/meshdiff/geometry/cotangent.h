//! \file cotangent.h
//! \brief The cotangent operator of a triangle mesh, in one place: the
//! cotangent of a corner, the mixed Voronoi area, the mean-curvature normal and
//! the backward-Euler system of mean curvature flow. The Meyer curvature
//! estimator (curvature.h) and the curvature flows (smoothing.h) both use it.
//!
//! Meyer, Desbrun, Schroeder, Barr, "Discrete Differential-Geometry Operators
//! for Triangulated 2-Manifolds", VisMath 2002: around vertex i,
//!   Hn_i = 1 / (4 A_i) sum_j (cot a_ij + cot b_ij) (x_j - x_i),
//! a_ij and b_ij the angles opposite edge (i, j), A_i the mixed area (the
//! Voronoi area of i in a non-obtuse triangle; half the triangle's area if the
//! angle at i is obtuse, a quarter if another angle is). |Hn| approximates |H|
//! and Hn points to the inside of a convex surface: with outward normals n,
//! H = -Hn . n (a sphere of radius r gives +1/r).
//!
//! Flat corners. The cotangent of a corner whose sine is at most
//! kFlatCornerSine (|a x b| <= kFlatCornerSine |a| |b|) counts as 0, and a
//! vertex without mixed area has no curvature normal (zero), so degenerate
//! faces never produce NaN. Faces are "degenerate" in the sense of topology.h;
//! this is the numerical guard of the cotangent, documented there beside it.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/tolerances.h"
#include "meshdiff/core/topology.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cmath>
#include <cstddef>
#include <vector>

namespace meshdiff {

// kFlatCornerSine, the sine below which a corner's cotangent counts as 0 (see
// the file comment), is in core/tolerances.h.

//! cot of the angle between \p a and \p b; 0 for a flat corner.
inline double cot(const Vec3& a, const Vec3& b)
{
    const double cross = a.cross(b).norm();
    const double scale = a.norm() * b.norm();
    if (!(cross > kFlatCornerSine * scale)) return 0.0;
    return a.dot(b) / cross;
}

//! The part of vertex i's mixed area in triangle (i, j, k), from its edges
//! eij = x_j - x_i, eik = x_k - x_i, ejk = x_k - x_j and the cotangents at j and
//! k: the Voronoi part (|eij|^2 cot_k + |eik|^2 cot_j) / 8 for a non-obtuse
//! triangle, half the triangle's area if the angle at i is obtuse, a quarter
//! if another angle is; 0 for a triangle without area. \p tri is the
//! triangle's area.
inline double mixed_area_part(const Vec3& eij, const Vec3& eik, const Vec3& ejk, double cot_j, double cot_k, double tri)
{
    if (!(tri > 0)) return 0.0;
    if (eij.dot(eik) < 0) return tri / 2;
    if ((-eij).dot(ejk) < 0 || eik.dot(ejk) < 0) return tri / 4;
    return (eij.squaredNorm() * cot_k + eik.squaredNorm() * cot_j) / 8;
}

//! The same with the triangle's area computed from corner i, |eij x eik| / 2.
inline double mixed_area_part(const Vec3& eij, const Vec3& eik, const Vec3& ejk, double cot_j, double cot_k)
{
    return mixed_area_part(eij, eik, ejk, cot_j, cot_k, 0.5 * eij.cross(eik).norm());
}

//! The cotangent sums around one vertex i.
struct CotangentSums
{
    Vec3 sum = Vec3::Zero();   //!< sum_j (cot a_ij + cot b_ij) (x_j - x_i)
    double area4 = 0.0;        //!< 4 A_i, the mixed area times 4 (0 without area)
    double abs_weights = 0.0;  //!< sum_j |cot a_ij| + |cot b_ij| (the Gershgorin radius of the flow)

    //! The mean-curvature normal Hn_i = sum / (4 A_i); zero without area.
    Vec3 curvature_normal() const { return area4 > 0 ? Vec3(sum / area4) : Vec3::Zero(); }
};

//! The cotangent sums of vertex \p i at positions \p p (one per vertex of
//! \p mesh; the faces are the mesh's), over its faces \p vf (vertex_faces()).
CotangentSums cotangent_sums(const Mesh& mesh, const Adjacency& vf, const std::vector<Vec3>& p, std::size_t i);

//! The cotangent sums of every vertex of \p mesh at its own positions,
//! assembled face by face (faces with \p skip_face set, if given, left out):
//! each term is that of cotangent_sums(), but a triangle's area is computed once,
//! from its corner 0, so the areas of obtuse triangles (and so the sums) can
//! differ from cotangent_sums() in the last bits. Used by the Meyer estimator.
std::vector<CotangentSums> cotangent_sums_by_face(const Mesh& mesh, const std::vector<char>& skip_face = {});

//! Hn_i of cotangent_sums(); zero where the mixed area vanishes.
Vec3 curvature_normal(const Mesh& mesh, const Adjacency& vf, const std::vector<Vec3>& p, std::size_t i);

//! One backward-Euler step of mean curvature flow as a linear system over the
//! free vertices (Desbrun et al. 1999): (D - dt L) X' = D X, D = diag(4 A_i), L
//! the cotangent Laplacian (L_ij = cot a_ij + cot b_ij, L_ii = -sum_j L_ij),
//! weights and areas from the positions \p p. Vertices in \p fixed, and those
//! without mixed area, are held: their columns move to the right-hand side, so
//! the matrix is symmetric positive definite.
struct CotangentSystem
{
    std::vector<Eigen::Index> index;     //!< per vertex: its row, or -1 if held
    Eigen::SparseMatrix<double> matrix;  //!< D - dt L over the free vertices
    Eigen::MatrixXd rhs;                 //!< D X plus the held neighbours' terms, one row per free vertex
    Eigen::MatrixXd positions;           //!< the free vertices' positions X (a starting guess)
    Eigen::Index free() const { return rhs.rows(); }
};
CotangentSystem backward_euler_system(const Mesh& mesh, const Adjacency& vf, const std::vector<char>& fixed, double dt,
                                      const std::vector<Vec3>& p);

}  // namespace meshdiff
