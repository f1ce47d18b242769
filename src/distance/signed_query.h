// Private: signed_query() (meshdiff/distance/signed_distance.h) with a side
// job for the query team, for the surface distance's chunks, and the
// pseudo-normals without their face normals.
#pragma once

#include "meshdiff/distance/signed_distance.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace meshdiff::detail {

//! signed_query() with \p beside run once by one thread of the team while the
//! others query (detail::distances_with_regions()); its exception is rethrown
//! once the queries are done. \p order, if given, is the order of the queries
//! (a permutation of 0 .. n - 1, as distances_with_regions() takes it): the
//! same distances and signs.
void signed_query(const Mesh& mesh, const ClosestPointIndex& index, const PseudoNormals& normals, const Vec3* queries,
                  std::size_t n, double* distances, std::int8_t* signs, const std::function<void()>& beside,
                  const std::uint32_t* order = nullptr);

//! -1, 0 or 1: the sign of \p s (0 for NaN).
inline int sign_of(double s)
{
    return s > 0.0 ? 1 : (s < 0.0 ? -1 : 0);
}

//! The sign of d . unit_face_normal(flipped, a, b, c) as that product rounds
//! (the sign of a point whose closest point lies inside the face, d being
//! the point less its closest point), without the normal's square root and
//! division where the product with the unnormalised normal n = (b - a) x
//! (c - a) is certain of it: |d . n| above 1e-13 of the sum of |d_i n_i|,
//! about 450 units in the last place, where the normalisation and both dot
//! products err by under 8 of them; n and that sum within 1e-150 .. 1e150, so
//! that neither product overflows or loses its last bits to underflow. Else
//! (near the face's plane, or at extreme scales) the normalised product, as
//! before: the same sign in every case.
inline int interior_sign(bool flipped, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 n = (b - a).cross(c - a);
    const double x = d.x() * n.x(), y = d.y() * n.y(), z = d.z() * n.z();
    const double t = x + y + z;
    const double scale = std::abs(x) + std::abs(y) + std::abs(z);
    const double n2 = n.squaredNorm();
    if (n2 >= 1e-150 && n2 <= 1e150 && scale >= 1e-150 && scale <= 1e150 && std::abs(t) > 1e-13 * scale)
        return (t > 0.0) != flipped ? 1 : -1;
    return sign_of(d.dot(unit_face_normal(flipped, a, b, c)));
}

//! pseudo_normals(data, name, reason) with PseudoNormals::face left empty:
//! the vertex normals summed from face normals made as they are read (the
//! same values), never 24 bytes a face held at once (48 MB for 2M faces,
//! beside the index being built).
std::optional<PseudoNormals> pseudo_normals_without_faces(const MeshData& data, const std::string& name,
                                                          std::string* reason);

}  // namespace meshdiff::detail
