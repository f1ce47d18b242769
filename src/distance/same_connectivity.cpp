#include "meshdiff/distance/same_connectivity.h"

#include "meshdiff/core/tolerances.h"
#include "meshdiff/core/topology.h"

#include "core/compensated_sum.h"

#include <fmt/format.h>

#include <cmath>
#include <vector>

namespace meshdiff {

namespace {

using Sum = detail::CompensatedSum;  // sequential, in index order

}  // namespace

std::optional<SameConnectivity> same_connectivity(const Mesh& a, const Mesh& b, std::string* reason)
{
    return same_connectivity(MeshData(a), MeshData(b), reason);
}

std::optional<SameConnectivity> same_connectivity(const MeshData& a_data, const MeshData& b_data, std::string* reason)
{
    const Mesh& a = a_data.mesh();
    const Mesh& b = b_data.mesh();
    auto refuse = [reason](std::string why) -> std::optional<SameConnectivity> {
        if (reason) *reason = std::move(why);
        return std::nullopt;
    };
    if (a.n_vertices() != b.n_vertices())
        return refuse(fmt::format("vertex counts differ ({} vs {})", a.n_vertices(), b.n_vertices()));
    if (a.n_faces() != b.n_faces())
        return refuse(fmt::format("face counts differ ({} vs {})", a.n_faces(), b.n_faces()));
    for (std::size_t f = 0; f < a.n_faces(); ++f)
        if (a.faces[f] != b.faces[f])
            return refuse(fmt::format("face {} differs: ({}, {}, {}) vs ({}, {}, {})", f, a.faces[f][0], a.faces[f][1],
                                      a.faces[f][2], b.faces[f][0], b.faces[f][1], b.faces[f][2]));
    SameConnectivity r;
    r.vertices = a.n_vertices();
    Sum d2;
    for (std::size_t v = 0; v < a.n_vertices(); ++v) {
        const double d = (b.points[v] - a.points[v]).norm();
        d2.add(d * d);
        if (d > r.displacement_max) {
            r.displacement_max = d;
            r.max_vertex = v;
        }
    }
    if (r.vertices > 0) r.displacement_rms = std::sqrt(d2.value() / double(r.vertices));
    const std::vector<char>& da = a_data.degenerate_faces();
    const std::vector<char>& db = b_data.degenerate_faces();
    Sum a2;
    for (std::size_t f = 0; f < a.n_faces(); ++f) {
        if (da[f] || db[f]) {
            ++r.degenerate_faces;
            continue;
        }
        const Vec3 na = face_cross(a, f).normalized();
        const Vec3 nb = face_cross(b, f).normalized();
        const double angle = std::atan2(na.cross(nb).norm(), na.dot(nb)) * 180.0 / kPi;
        ++r.faces;
        a2.add(angle * angle);
        if (angle > r.normal_max_deg) {
            r.normal_max_deg = angle;
            r.max_face = f;
        }
    }
    if (r.faces > 0) r.normal_rms_deg = std::sqrt(a2.value() / double(r.faces));
    return r;
}

}  // namespace meshdiff
