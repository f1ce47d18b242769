#include "meshdiff/studies/noise.h"

#include "meshdiff/error.h"
#include "meshdiff/geometry/normals.h"
#include "studies/random.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace meshdiff {

namespace {

void require(bool ok, const char* field, const std::string& what)
{
    if (!ok) throw OptionError(std::string("noise.") + field, what);
}

void validate_options(const NoiseOptions& o)
{
    require(std::isfinite(o.amplitude) && o.amplitude >= 0, "amplitude",
            fmt::format("must be finite and >= 0 (got {})", o.amplitude));
    require(is_known(o.unit), "unit", fmt::format("is not a NoiseUnit (got {})", int(o.unit)));
    require(is_known(o.direction), "direction", fmt::format("is not a NoiseDirection (got {})", int(o.direction)));
    require(is_known(o.distribution), "distribution",
            fmt::format("is not a NoiseDistribution (got {})", int(o.distribution)));
}

}  // namespace

NoiseReport add_noise(Mesh& mesh, const NoiseOptions& options)
{
    validate_options(options);
    validate(mesh, "noise");

    NoiseReport report;
    report.mean_edge = mean_edge_length(mesh, vertex_adjacency(mesh));
    report.diagonal = bounding_box(mesh).diagonal();
    switch (options.unit) {
        case NoiseUnit::MeanEdge:
            report.unit_length = report.mean_edge;
            break;
        case NoiseUnit::BBoxDiagonal:
            report.unit_length = report.diagonal;
            break;
        case NoiseUnit::Absolute:
            report.unit_length = 1.0;
            break;
    }
    report.amplitude = options.amplitude * report.unit_length;
    require(std::isfinite(report.amplitude), "amplitude",
            fmt::format("times the unit ({} x {}) is not finite", options.amplitude, report.unit_length));
    const double a = report.amplitude;

    std::vector<char> in_face(mesh.n_vertices(), 0);
    for (const Face& f : mesh.faces)
        for (auto v : f) in_face[std::size_t(v)] = 1;
    const std::vector<char> boundary = boundary_vertex_mask(mesh);
    const bool along_normal = options.direction == NoiseDirection::Normal;
    const std::vector<Vec3> normals = along_normal ? vertex_normals(mesh) : std::vector<Vec3>();

    // Serial and in vertex order: every vertex consumes the same raw outputs
    // (noise.h), whether it moves or not.
    std::mt19937_64 rng(options.seed);
    for (std::size_t i = 0; i < mesh.n_vertices(); ++i) {
        Vec3 d = Vec3::Zero();
        if (along_normal) {
            d = normals[i];
        } else {
            const auto [g0, g1] = detail::gaussian_pair(rng);
            const double g2 = detail::gaussian_pair(rng).first;
            const Vec3 g(g0, g1, g2);
            const double len = g.norm();
            if (len > 0) d = g / len;
        }
        double t = 0.0;
        if (options.distribution == NoiseDistribution::Uniform)
            t = a * detail::uniform_pm1(rng);
        else
            t = a * detail::gaussian_pair(rng).first;

        if (!in_face[i]) {
            ++report.skipped_isolated;
        } else if (boundary[i] && !options.move_boundary) {
            ++report.skipped_boundary;
        } else if (d == Vec3::Zero()) {
            ++report.skipped_no_direction;
        } else {
            ++report.moved;
            // t = 0 leaves the point bitwise unchanged (adding -0.0 or +0.0 could flip the sign of a zero).
            if (t != 0.0) mesh.points[i] += t * d;
            report.max_displacement = std::max(report.max_displacement, std::abs(t));
        }
    }
    // A result meshdiff would not read back (non-finite, or beyond the readers' limit) is refused.
    for (std::size_t i = 0; i < mesh.n_vertices(); ++i)
        require(mesh.points[i].allFinite() && mesh.points[i].cwiseAbs().maxCoeff() <= max_coordinate, "amplitude",
                fmt::format("moves vertex {} to ({}, {}, {}), beyond meshdiff's limit of +-{} (no output is written)",
                            i, mesh.points[i].x(), mesh.points[i].y(), mesh.points[i].z(), max_coordinate));
    return report;
}

}  // namespace meshdiff
