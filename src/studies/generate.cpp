#include "meshdiff/studies/generate.h"

#include "meshdiff/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace meshdiff {

namespace {

// The fields that apply to each kind.
const std::set<std::string>& applicable(ShapeKind kind)
{
    static const std::set<std::string> sphere = {"subdivisions", "frequency", "radius"},
                                       noisy = {"subdivisions", "frequency", "radius", "noise", "seed"},
                                       ellipsoid = {"subdivisions", "frequency", "axes"},
                                       torus = {"major", "minor", "n"},
                                       torus_irregular = {"major", "minor", "vertices", "seed"},
                                       heightfield = {"n", "amplitude"},
                                       heightfield_irregular = {"vertices", "amplitude", "seed"},
                                       plane = {"n", "spacing"};
    switch (kind) {
        case ShapeKind::Sphere:
            return sphere;
        case ShapeKind::NoisySphere:
            return noisy;
        case ShapeKind::Ellipsoid:
            return ellipsoid;
        case ShapeKind::Torus:
            return torus;
        case ShapeKind::TorusIrregular:
            return torus_irregular;
        case ShapeKind::Heightfield:
            return heightfield;
        case ShapeKind::HeightfieldIrregular:
            return heightfield_irregular;
        case ShapeKind::Plane:
            return plane;
    }
    throw OptionError("generate.kind", "not a known shape");
}

void check(const GenerateOptions& o)
{
    if (!is_known(o.kind)) throw OptionError("generate.kind", "not a known shape");
    const std::vector<std::pair<const char*, bool>> given = {{"subdivisions", o.subdivisions.has_value()},
                                                             {"frequency", o.frequency.has_value()},
                                                             {"radius", o.radius.has_value()},
                                                             {"noise", o.noise.has_value()},
                                                             {"axes", o.axes.has_value()},
                                                             {"major", o.major.has_value()},
                                                             {"minor", o.minor.has_value()},
                                                             {"n", o.n.has_value()},
                                                             {"vertices", o.vertices.has_value()},
                                                             {"amplitude", o.amplitude.has_value()},
                                                             {"spacing", o.spacing.has_value()},
                                                             {"seed", o.seed.has_value()}};
    const auto& ok = applicable(o.kind);
    for (const auto& [field, is_given] : given)
        if (is_given && !ok.count(field))
            throw OptionError(std::string("generate.") + field, fmt::format("does not apply to {}", to_string(o.kind)));
    if (o.subdivisions && o.frequency)
        throw OptionError("generate.frequency",
                          "instead of {generate.subdivisions} (geodesic sphere or icosphere), not both");
    if (o.subdivisions && (*o.subdivisions < 0 || *o.subdivisions > kMaxSubdivisions))
        throw OptionError("generate.subdivisions",
                          fmt::format("{} is outside 0..{}", *o.subdivisions, kMaxSubdivisions));
    if (o.frequency && (*o.frequency < 1 || *o.frequency > kMaxFrequency))
        throw OptionError("generate.frequency", fmt::format("{} is outside 1..{}", *o.frequency, kMaxFrequency));
    if (o.n && (*o.n < kMinGridN || *o.n > kMaxGridN))
        throw OptionError("generate.n", fmt::format("{} is outside {}..{}", *o.n, kMinGridN, kMaxGridN));
    if (o.vertices && (*o.vertices < 1 || *o.vertices > kMaxIrregularVertices))
        throw OptionError("generate.vertices", fmt::format("{} is outside 1..{}", *o.vertices, kMaxIrregularVertices));
    if (o.radius && !(std::isfinite(*o.radius) && *o.radius > 0.0))
        throw OptionError("generate.radius", fmt::format("{} must be finite and > 0", *o.radius));
}

}  // namespace

GeneratedShape generate_shape(const GenerateOptions& o)
{
    check(o);
    using D = GenerateDefaults;
    GeneratedShape g;
    const bool geodesic = o.frequency.has_value();
    const int subdivisions = o.subdivisions.value_or(D::subdivisions);
    const std::string base = geodesic ? fmt::format("geodesic sphere frequency={}", *o.frequency)
                                      : fmt::format("icosphere subdivisions={}", subdivisions);
    const double radius = o.radius.value_or(D::radius), major = o.major.value_or(D::major),
                 minor = o.minor.value_or(D::minor), amplitude = o.amplitude.value_or(D::amplitude);
    const std::uint64_t seed = o.seed.value_or(D::seed);
    switch (o.kind) {
        case ShapeKind::Sphere:
            g.description = fmt::format("{} radius={}", base, radius);
            g.shape = geodesic ? geodesic_sphere(*o.frequency, radius) : icosphere(subdivisions, radius);
            break;
        case ShapeKind::NoisySphere: {
            const double noise = o.noise.value_or(D::noise);
            g.description = fmt::format(
                "{} radius={} with uniform radial noise +-{} of the radius, seed={}; exact_H is the noise-free "
                "sphere's 1/radius",
                base, radius, noise, seed);
            g.shape = geodesic ? noisy_sphere(geodesic_sphere(*o.frequency, radius), noise, seed)
                               : noisy_sphere(subdivisions, noise, seed, radius);
            break;
        }
        case ShapeKind::Ellipsoid: {
            const auto a = o.axes.value_or(D::axes);
            g.description = fmt::format("ellipsoid: {} scaled by a={} b={} c={}", base, a[0], a[1], a[2]);
            g.shape = geodesic ? ellipsoid(geodesic_sphere(*o.frequency).mesh, a[0], a[1], a[2])
                               : ellipsoid(subdivisions, a[0], a[1], a[2]);
            break;
        }
        case ShapeKind::Torus: {
            const int n_major = o.n.value_or(D::torus_n);
            const double ratio = major > 0 && minor > 0 ? minor / major : D::minor / D::major;
            const int n_minor = std::max(3, int(std::lround(n_major * ratio)));
            g.description =
                fmt::format("torus R={} r={} regular grid n_major={} n_minor={}", major, minor, n_major, n_minor);
            g.shape = torus(n_major, n_minor, major, minor);
            break;
        }
        case ShapeKind::TorusIrregular: {
            const std::size_t v = o.vertices.value_or(D::torus_vertices);
            g.description = fmt::format("torus R={} r={} irregular, about {} vertices, seed={}", major, minor, v, seed);
            g.shape = torus_irregular(v, major, minor, seed);
            break;
        }
        case ShapeKind::Heightfield: {
            const int n = o.n.value_or(D::heightfield_n);
            g.description =
                fmt::format("height field (see shapes.h) amplitude={} on a regular {}x{} grid", amplitude, n, n);
            g.shape = heightfield(n, amplitude);
            break;
        }
        case ShapeKind::HeightfieldIrregular: {
            const std::size_t v = o.vertices.value_or(D::heightfield_vertices);
            g.description = fmt::format(
                "height field (see shapes.h) amplitude={} irregular, about {} vertices, seed={}", amplitude, v, seed);
            g.shape = heightfield_irregular(v, seed, amplitude);
            break;
        }
        case ShapeKind::Plane: {
            const int n = o.n.value_or(D::plane_n);
            const double spacing = o.spacing.value_or(D::spacing);
            g.description = fmt::format("plane grid {}x{} spacing={}", n, n, spacing);
            g.shape = plane_grid(n, n, spacing);
            break;
        }
    }
    // A surface meshdiff would not read back (non-finite or beyond the readers'
    // limit), or an exact H that is not a number, is refused: name the option
    // that sizes the kind.
    const char* size_field = "generate.radius";
    switch (o.kind) {
        case ShapeKind::Ellipsoid:
            size_field = "generate.axes";
            break;
        case ShapeKind::Torus:
        case ShapeKind::TorusIrregular:
            size_field = "generate.major";
            break;
        case ShapeKind::Heightfield:
        case ShapeKind::HeightfieldIrregular:
            size_field = "generate.amplitude";
            break;
        case ShapeKind::Plane:
            size_field = "generate.spacing";
            break;
        default:
            break;
    }
    for (std::size_t i = 0; i < g.shape.mesh.n_vertices(); ++i) {
        const Vec3& p = g.shape.mesh.points[i];
        if (!p.allFinite() || p.cwiseAbs().maxCoeff() > max_coordinate || !std::isfinite(g.shape.exact_H[i]))
            throw OptionError(size_field,
                              fmt::format("makes vertex {} ({}, {}, {}; exact H {}) non-finite or beyond meshdiff's "
                                          "limit of +-{}: meshdiff could not read the surface back",
                                          i, p.x(), p.y(), p.z(), g.shape.exact_H[i], max_coordinate));
    }
    return g;
}

}  // namespace meshdiff
