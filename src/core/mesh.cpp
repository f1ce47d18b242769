#include "meshdiff/core/mesh.h"

#include "meshdiff/error.h"

#include "core/derivations.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace meshdiff {

void validate(const Mesh& mesh, const std::string& what)
{
    detail::note_derivation(detail::Derived::Validation, mesh);
    if (mesh.points.empty()) throw InvalidMeshError(fmt::format("{}: mesh has no vertices", what));
    if (mesh.faces.empty()) throw InvalidMeshError(fmt::format("{}: mesh has no faces", what));
    const auto n = std::int64_t(mesh.n_vertices());
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        for (auto v : mesh.faces[f])
            if (v < 0 || v >= n)
                throw InvalidMeshError(
                    fmt::format("{}: face {} refers to vertex {}, but there are {} vertices", what, f, v, n));
    for (std::size_t i = 0; i < mesh.n_vertices(); ++i) {
        const Vec3& p = mesh.points[i];
        if (!p.allFinite())
            throw InvalidMeshError(
                fmt::format("{}: vertex {} has a non-finite coordinate ({}, {}, {})", what, i, p.x(), p.y(), p.z()));
        if (p.cwiseAbs().maxCoeff() > max_coordinate)
            throw InvalidMeshError(
                fmt::format("{}: vertex {} has a coordinate beyond meshdiff's limit of +-{} ({}, {}, {})", what, i,
                            max_coordinate, p.x(), p.y(), p.z()));
    }
}

BoundingBox bounding_box(const Mesh& mesh)
{
    detail::note_derivation(detail::Derived::Box, mesh);
    BoundingBox box;
    if (mesh.points.empty()) return box;
    box.min = box.max = mesh.points[0];
    for (const auto& p : mesh.points) {
        box.min = box.min.cwiseMin(p);
        box.max = box.max.cwiseMax(p);
    }
    return box;
}

Vec3 face_cross(const Mesh& mesh, std::size_t f)
{
    const Face& t = mesh.faces[f];
    const Vec3& a = mesh.points[std::size_t(t[0])];
    return (mesh.points[std::size_t(t[1])] - a).cross(mesh.points[std::size_t(t[2])] - a);
}

double surface_area(const Mesh& mesh)
{
    double area = 0.0;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) area += 0.5 * face_cross(mesh, f).norm();
    return area;
}

}  // namespace meshdiff
