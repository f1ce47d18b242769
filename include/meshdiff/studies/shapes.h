//! \file shapes.h
//! \brief Analytic test and experiment surfaces with their exact mean curvature
//! per vertex (METHOD.md sections 4 and 8; the paper's sections 6.1-6.3).
//!
//! Conventions shared by every generator:
//! - Faces are counter-clockwise seen from outside (closed shapes) or from +z
//!   (plane and height field), so normals point outward / upward.
//! - exact_H is the mean curvature (k1 + k2) / 2 at each vertex, signed so that
//!   a surface bending away from its normal is positive: a sphere of radius r
//!   has H = +1/r, a bump of a height field has H > 0, a pit H < 0.
//! - Vertices lie on the analytic surface up to rounding (|error| of a few ulp).
//! - Random generators use std::mt19937_64 and map its raw 64-bit outputs to
//!   [0, 1) as (x >> 11) * 2^-53 themselves, so a seed gives the same mesh on
//!   every platform and standard library.
//! - Every generator validates its arguments first and throws
//!   meshdiff::InvalidArgumentError naming the offending parameter.
#pragma once

#include "meshdiff/core/mesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace meshdiff {

//! A mesh together with the exact mean curvature of the underlying analytic
//! surface at each of its vertices.
struct Shape
{
    Mesh mesh;
    std::vector<double> exact_H;  //!< one per vertex, H = +1/r on a sphere of radius r
};

//! Icosphere: a regular icosahedron whose faces are split into four, \p
//! subdivisions times, new vertices projected onto the sphere. 10 * 4^k + 2
//! vertices (12, 42, 162, 642, 2562, 10242, ...); twelve vertices of valence 5,
//! the rest valence 6. exact_H = 1 / radius.
//! \param subdivisions 0..8
//! \param radius > 0
//! \throw InvalidArgumentError if an argument is out of range.
Shape icosphere(int subdivisions, double radius = 1.0);

//! Geodesic sphere of class I: every face of the icosahedron of icosphere(0)
//! is cut by a regular barycentric grid of \p frequency f into f^2 triangles,
//! whose points are projected onto the sphere: 20 f^2 faces and 10 f^2 + 2
//! vertices (f = 20: 8000 faces, the size of the paper's spheres); twelve
//! vertices of valence 5, the rest valence 6. Frequencies 1 and 2 give the
//! same meshes as icosphere(0) and icosphere(1). exact_H = 1 / radius.
//! \param frequency 1..1024
//! \param radius > 0
//! \throw InvalidArgumentError if an argument is out of range.
Shape geodesic_sphere(int frequency, double radius = 1.0);

//! Latitude-longitude sphere with single-vertex poles: \p n_longitude vertices
//! per ring, \p n_latitude bands between the poles (n_latitude - 1 rings), so
//! n_longitude * (n_latitude - 1) + 2 vertices. Ring k sits at polar angle
//! pi k / n_latitude. exact_H = 1 / radius.
//! \param n_longitude >= 3
//! \param n_latitude >= 2
//! \param radius > 0
//! \throw InvalidArgumentError if an argument is out of range.
Shape uv_sphere(int n_longitude, int n_latitude, double radius = 1.0);

//! Torus around the z axis, point(u, v) = ((R + r cos v) cos u, (R + r cos v)
//! sin u, r sin v), sampled on the regular grid u = 2 pi i / n_major, v = 2 pi j
//! / n_minor; every quad is split along the same diagonal, so every vertex has
//! valence 6. Vertex index i * n_minor + j.
//! exact_H = (R + 2 r cos v) / (2 r (R + r cos v)): (R + 2r) / (2r (R + r)) on
//! the outer equator, (R - 2r) / (2r (R - r)) on the inner one (negative when
//! R < 2r).
//! \param n_major, n_minor >= 3
//! \param R > r > 0
//! \throw InvalidArgumentError if an argument is out of range.
Shape torus(int n_major, int n_minor, double R = 1.0, double r = 0.25);

//! Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 made by scaling icosphere(\p
//! subdivisions) by (a, b, c) (the paper's stretched sphere: e.g. a = 1.5, b = c
//! = 1). exact_H = |x^2 + y^2 + z^2 - a^2 - b^2 - c^2| / (2 a^2 b^2 c^2 (x^2/a^4 +
//! y^2/b^4 + z^2/c^4)^(3/2)) at each vertex (METHOD.md section 4).
//! \param subdivisions 0..8
//! \param a, b, c > 0 (semi-axes along x, y, z)
//! \throw InvalidArgumentError if an argument is out of range.
Shape ellipsoid(int subdivisions, double a, double b, double c);
//! The same, stretching any mesh of the unit sphere (e.g. geodesic_sphere(20).mesh).
Shape ellipsoid(const Mesh& unit_sphere, double a, double b, double c);

//! Flat regular grid in z = 0 with \p nx by \p ny vertices, \p spacing apart,
//! centred on the origin; every quad is split along the same diagonal, so
//! interior vertices have valence 6. Vertex index j * nx + i. exact_H = 0.
//! \param nx, ny >= 2
//! \param spacing > 0
//! \throw InvalidArgumentError if an argument is out of range.
Shape plane_grid(int nx, int ny, double spacing = 1.0);

//! icosphere(\p subdivisions, \p radius) with radial noise: each vertex p is
//! moved to p (1 + e), e drawn independently and uniformly from
//! [-noise_fraction, +noise_fraction) (in vertex order, one draw per vertex).
//! exact_H is that of the underlying sphere, 1 / radius, for every vertex: the
//! noise is what a smoother or a roughness measure should see as deviation.
//! \param noise_fraction in [0, 1)
//! \throw InvalidArgumentError if an argument is out of range.
Shape noisy_sphere(int subdivisions, double noise_fraction, std::uint64_t seed, double radius = 1.0);
//! The same radial noise on any \p sphere centred at the origin (e.g.
//! geodesic_sphere(20)); exact_H is kept.
Shape noisy_sphere(Shape sphere, double noise_fraction, std::uint64_t seed);

//! The torus of torus() sampled irregularly: a periodic grid in (u, v) of about
//! \p approx_vertices points (n_minor = round(sqrt(N r / R)), n_major =
//! round(N / n_minor), so cells are roughly square on the tube's centre
//! circle), each parameter point jittered uniformly by up to +-0.2 cells in u
//! and in v, and each quad split along a randomly chosen diagonal (valences
//! then range from 4 to 8). The jitter bound keeps every parameter quad convex,
//! so the triangulation is valid and consistently oriented. Points are computed
//! from (u, v), i.e. they lie on the same torus. Same exact_H formula.
//! \param approx_vertices >= 9
//! \param R > r > 0
//! \throw InvalidArgumentError if an argument is out of range.
Shape torus_irregular(std::size_t approx_vertices, double R, double r, std::uint64_t seed);

//! The height function of heightfield(): z = amplitude * f(x, y) on [-1, 1]^2,
//! f(x, y) = 0.3 g(x - 0.3, y - 0.2; 0.35) - 0.2 g(x + 0.4, y + 0.35; 0.25)
//!           + 0.05 sin(2 x) cos(3 y),   g(x, y; s) = exp(-(x^2 + y^2) / (2 s^2)):
//! a bump, a pit and a gentle wave, all smooth.
double heightfield_z(double x, double y, double amplitude = 1.0);

//! Exact mean curvature of the graph z = heightfield_z(x, y, amplitude) with
//! upward normal: H = -((1 + f_y^2) f_xx - 2 f_x f_y f_xy + (1 + f_x^2) f_yy) /
//! (2 (1 + f_x^2 + f_y^2)^(3/2)), so a bump is positive (as a sphere seen from
//! outside).
double heightfield_H(double x, double y, double amplitude = 1.0);

//! Regular n by n grid over [-1, 1]^2 lifted to z = heightfield_z(x, y,
//! amplitude); triangulated like plane_grid() (interior valence 6), faces
//! counter-clockwise seen from +z. Vertex index j * n + i. exact_H from
//! heightfield_H().
//! \param n >= 2
//! \param amplitude finite (0 gives a flat grid)
//! \throw InvalidArgumentError if an argument is out of range.
Shape heightfield(int n, double amplitude = 1.0);

//! The same height field sampled irregularly: a grid of about \p
//! approx_vertices points over [-1, 1]^2 whose interior points are jittered
//! uniformly by up to +-0.2 cells in x and y (boundary points only along their
//! side; corners fixed), each quad split along a random diagonal.
//! \param approx_vertices >= 4
//! \throw InvalidArgumentError if an argument is out of range.
Shape heightfield_irregular(std::size_t approx_vertices, std::uint64_t seed, double amplitude = 1.0);

}  // namespace meshdiff
