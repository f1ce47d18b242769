//! \file signed_distance.h
//! \brief The sign of a distance to a closed, consistently oriented triangle
//! mesh by the angle-weighted pseudo-normal of the closest feature (Baerentzen
//! and Aanaes, "Signed distance computation using the angle weighted
//! pseudonormal", IEEE TVCG 11(3), 2005; METHOD.md section 6b).
//!
//! Convention: positive outside the mesh, negative inside, 0 on it (as Open3D
//! and CloudCompare; trimesh has the opposite sign).
//!
//! The closest point c of a query p lies on a feature of its face: a corner, an
//! edge or the interior (closest_feature(), the region of Ericson's method that
//! closest_point_on_triangle() takes). Its pseudo-normal n is the face normal
//! for the interior, the sum of the two unit face normals for an edge, and for
//! a vertex the sum over its faces of the face's angle at the vertex x its unit
//! normal. The sign is sign((p - c) . n), which Baerentzen and Aanaes prove
//! correct for every p whose closest point is c: faces that tie at a shared
//! edge or vertex give the same feature and the same pseudo-normal, where a
//! face normal can give the wrong sign.
//!
//! Availability (sign_unavailable_reason()): the mesh must be closed (no
//! boundary edge), edge- and vertex-manifold, consistently oriented (no edge
//! used twice in one direction), without degenerate faces (topology.h: a zero
//! area has no normal) and enclose a volume (signed volume != 0). A mesh
//! oriented inwards (negative signed volume) is used flipped, outwards
//! (PseudoNormals::flipped). Self-intersections are not detected: where
//! surfaces cross, inside and outside are not defined and the sign follows
//! the nearest sheet.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/mesh_data.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/geometry/point_triangle.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace meshdiff {

//! The feature of a triangle (a, b, c) holding a closest point.
enum class FeatureKind : std::uint8_t
{
    Vertex,    //!< corner `index` (0: a, 1: b, 2: c)
    Edge,      //!< edge `index` from corner index to corner (index + 1) mod 3
    Interior,  //!< the interior of the face (index 0)
};

//! The closest point of a triangle to a query and the feature it lies on.
struct ClosestFeature
{
    Vec3 point = Vec3::Zero();
    FeatureKind kind = FeatureKind::Interior;
    std::uint8_t index = 0;
};

//! The closest point of triangle (a, b, c) to \p p, bit for bit that of
//! closest_point_on_triangle(), and the Voronoi region it comes from. A thin
//! triangle (point_triangle.h) is the union of its edges: the region is an
//! edge or a corner.
ClosestFeature closest_feature(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

//! The pseudo-normals of a closed, oriented mesh, outward (not normalised:
//! only their directions matter). The pseudo-normal of the edge from corner k
//! to corner k + 1 of face f is face[f] + face[opposite[3 f + k] / 3].
struct PseudoNormals
{
    //! Unit face normals, per face: unit_face_normal() of each face's corners.
    //! May be left empty (the surface distance drops them once the vertex
    //! normals are made): the signs then make them from the corners when
    //! needed, the same values.
    std::vector<Vec3> face;
    std::vector<std::uint32_t> opposite;  //!< per half-edge 3 f + k: the opposite half-edge 3 g + j
    std::vector<Vec3> vertex;             //!< per vertex: sum of angle x unit normal over its faces
    bool flipped = false;                 //!< the mesh was oriented inwards and is used flipped
    double volume = 0.0;                  //!< signed volume of the mesh as given
};

//! The unit normal of the triangle (a, b, c) as PseudoNormals::face holds it:
//! (b - a) x (c - a) normalised, negated when \p flipped.
inline Vec3 unit_face_normal(bool flipped, const Vec3& a, const Vec3& b, const Vec3& c)
{
    return (flipped ? -1.0 : 1.0) * (b - a).cross(c - a).normalized();
}

//! Why \p mesh cannot be signed against, naming the conditions and their
//! counts ("12 boundary edges"), or the empty string if it can (a zero volume
//! is pseudo_normals()'s to find). \p name (e.g. "the original mesh") starts
//! the sentence. The counts are topology_report()'s; non-manifold vertices
//! are counted only when the edges are closed, manifold and consistent.
std::string sign_unavailable_reason(const Mesh& mesh, const std::string& name);

//! The pseudo-normals of \p mesh, or std::nullopt with \p reason set
//! (sign_unavailable_reason(), or a zero volume) when it cannot be signed against.
std::optional<PseudoNormals> pseudo_normals(const Mesh& mesh, const std::string& name = "the mesh",
                                            std::string* reason = nullptr);
//! The same from \p data, the derived data of the mesh (mesh_data.h).
std::optional<PseudoNormals> pseudo_normals(const MeshData& data, const std::string& name = "the mesh",
                                            std::string* reason = nullptr);

//! Sign (-1, 0 or +1) of the distance of \p p to \p mesh whose closest point
//! lies on face \p face (the face of a ClosestPoint from the mesh's index):
//! 0 if p lies on the surface, +1 outside. \p normals are \p mesh's.
int distance_sign(const Mesh& mesh, const PseudoNormals& normals, const Vec3& p, std::uint32_t face);

//! Signed distances of \p queries: the distance to \p mesh (\p distances,
//! from its index) times distance_sign() with the closest faces \p faces;
//! in parallel, the same for any number of threads.
std::vector<double> signed_distances(const Mesh& mesh, const PseudoNormals& normals, const Vec3* queries,
                                     const double* distances, const std::uint32_t* faces, std::size_t n);

//! The distances of \p queries[0, n) to \p mesh (indexed by \p index) into
//! \p distances, bit for bit ClosestPointIndex::distances(), and their signs
//! (-1, 0, +1; distance_sign()) into \p signs, from the same queries.
void signed_query(const Mesh& mesh, const ClosestPointIndex& index, const PseudoNormals& normals, const Vec3* queries,
                  std::size_t n, double* distances, std::int8_t* signs);

//! Inside test by the generalised winding number (sum of the solid angles of
//! the faces, Van Oosterom and Strackee's formula, / 4 pi): about 1 inside a
//! closed outward mesh, 0 outside. O(#faces); for tests (the brute-force oracle).
double winding_number(const Mesh& mesh, const Vec3& p);

}  // namespace meshdiff
