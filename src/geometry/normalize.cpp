#include "meshdiff/geometry/normalize.h"

#include "meshdiff/core/tolerances.h"
#include "meshdiff/error.h"

#include <cmath>

namespace meshdiff {

Normalization unit_normalization(const Mesh& mesh)
{
    if (mesh.points.empty()) throw InvalidMeshError("normalisation: mesh has no vertices");
    Normalization n;
    // Sums in a fixed order (deterministic); long double limits cancellation on
    // meshes far from the origin.
    long double sx = 0, sy = 0, sz = 0;
    for (const auto& p : mesh.points) {
        sx += p.x();
        sy += p.y();
        sz += p.z();
    }
    const auto count = static_cast<long double>(mesh.points.size());
    n.center = Vec3(double(sx / count), double(sy / count), double(sz / count));
    long double s = 0;
    for (const auto& p : mesh.points) s += (p - n.center).norm();
    n.scale = double(s / count);
    if (!(n.scale > 0.0) || !std::isfinite(n.scale))
        throw InvalidMeshError("normalisation: all vertices coincide, the mesh has no extent");
    return n;
}

Normalization area_normalization(const Mesh& mesh)
{
    if (mesh.points.empty()) throw InvalidMeshError("normalisation: mesh has no vertices");
    long double sx = 0, sy = 0, sz = 0, total = 0;  // face order: deterministic
    for (const Face& f : mesh.faces) {
        const Vec3& a = mesh.points[std::size_t(f[0])];
        const Vec3& b = mesh.points[std::size_t(f[1])];
        const Vec3& c = mesh.points[std::size_t(f[2])];
        const double area = 0.5 * (b - a).cross(c - a).norm();
        if (!(area > 0.0) || !std::isfinite(area)) continue;
        const Vec3 g = (a + b + c) / 3.0;
        sx += area * g.x();
        sy += area * g.y();
        sz += area * g.z();
        total += area;
    }
    if (!(total > 0.0L)) throw InvalidMeshError("normalisation (area): the mesh has no face of positive area");
    Normalization n;
    n.method = NormalizeMethod::Area;
    n.center = Vec3(double(sx / total), double(sy / total), double(sz / total));
    n.scale = std::sqrt(double(total) / (4.0 * kPi));
    if (!(n.scale > 0.0) || !std::isfinite(n.scale))
        throw InvalidMeshError("normalisation (area): the mesh has no extent");
    return n;
}

Mesh apply_normalization(const Mesh& mesh, const Normalization& n)
{
    Mesh out;
    out.faces = mesh.faces;
    out.points.reserve(mesh.points.size());
    const double inv = 1.0 / n.scale;
    for (const auto& p : mesh.points) out.points.push_back((p - n.center) * inv);
    return out;
}

}  // namespace meshdiff
