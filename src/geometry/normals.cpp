#include "meshdiff/geometry/normals.h"

#include "meshdiff/core/tolerances.h"
#include "meshdiff/error.h"

#include "core/face_corner.h"

#include <cmath>

namespace meshdiff {

std::vector<Vec3> vertex_normals(const Mesh& mesh)
{
    return vertex_normals(MeshData(mesh));
}

std::vector<Vec3> vertex_normals(const MeshData& data)
{
    return vertex_normals(data, data.vertex_faces());
}

std::vector<Vec3> vertex_normals(const MeshData& data, const Adjacency& vertex_faces)
{
    const Mesh& mesh = data.mesh();
    const std::size_t n = mesh.n_vertices();
    if (vertex_faces.size() != n)
        throw InvalidArgumentError("vertex_normals: the vertex-face incidence is not this mesh's");
    std::vector<Vec3> normals(n);
    const std::vector<char>& degenerate = data.degenerate_faces();
    // One vertex at a time, its faces in ascending order (the incidence's
    // rows): the sums of a loop over the faces, in parallel. A face's normal
    // is made at each of its corners, the same bits each time.
#pragma omp parallel for schedule(static, 4096)
    for (std::ptrdiff_t iv = 0; iv < std::ptrdiff_t(n); ++iv) {
        const auto v = std::size_t(iv);
        Vec3 sum = Vec3::Zero();
        double weight = 0.0;
        for (const std::uint32_t* fi = vertex_faces.begin(v); fi != vertex_faces.end(v); ++fi) {
            const std::size_t f = *fi;
            if (degenerate[f]) continue;  // a face that repeats a corner is degenerate
            const Face& t = mesh.faces[f];
            const int k = detail::corner_of(t, v);
            const Vec3 nf = face_cross(mesh, f).normalized();
            const Vec3& p = mesh.points[v];
            const Vec3 e1 = mesh.points[std::size_t(t[(k + 1) % 3])] - p;
            const Vec3 e2 = mesh.points[std::size_t(t[(k + 2) % 3])] - p;
            // atan2 of |cross| and dot is accurate for tiny and near-straight angles.
            const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
            sum += angle * nf;
            weight += angle;
        }
        // A sum that nearly cancels (back-to-back faces, folds) has a direction
        // made of rounding errors: treat it as no normal rather than a random one.
        const double len = sum.norm();
        normals[v] = len > kMinNormalRatio * weight && len > 0.0 ? Vec3(sum / len) : Vec3(Vec3::Zero());
    }
    return normals;
}

}  // namespace meshdiff
