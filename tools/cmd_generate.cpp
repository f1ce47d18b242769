#include "commands.h"
#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/report/text.h"
#include "meshdiff/shapes.h"
#include "options.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace meshdiff::cli {

namespace {

struct GenerateArgs
{
    std::string kind;
    std::string out;
    int subdivisions = 4;
    int frequency = 0;  // geodesic sphere frequency; 0: use the icosphere subdivisions
    double radius = 1.0;
    double noise = 0.02;
    std::vector<double> axes = {1.5, 1.0, 1.0};
    double major = 1.0;
    double minor = 0.25;
    int n = 0;                 // grid resolution; 0: the kind's default
    std::size_t vertices = 0;  // approximate vertex count of irregular kinds; 0: default
    double amplitude = 1.0;
    double spacing = 1.0;
    std::uint64_t seed = 1;
    std::map<std::string, const CLI::Option*> given;  // option name -> option, to find the ones set
};

const std::vector<std::string>& kinds()
{
    static const std::vector<std::string> k = {
        "sphere",      "noisy-sphere",          "ellipsoid", "torus", "torus-irregular",
        "heightfield", "heightfield-irregular", "plane"};
    return k;
}

// Which options each kind reads; any other option given is a usage error.
const std::set<std::string>& applicable(const std::string& kind)
{
    static const std::map<std::string, std::set<std::string>> table = {
        {"sphere", {"--subdivisions", "--frequency", "--radius"}},
        {"noisy-sphere", {"--subdivisions", "--frequency", "--radius", "--noise", "--seed"}},
        {"ellipsoid", {"--subdivisions", "--frequency", "--axes"}},
        {"torus", {"--major", "--minor", "--n"}},
        {"torus-irregular", {"--major", "--minor", "--vertices", "--seed"}},
        {"heightfield", {"--n", "--amplitude"}},
        {"heightfield-irregular", {"--vertices", "--amplitude", "--seed"}},
        {"plane", {"--n", "--spacing"}},
    };
    return table.at(kind);
}

Shape make_shape(const GenerateArgs& a, std::string& description)
{
    const std::string& k = a.kind;
    // The sphere tessellation: the icosphere, or with --frequency the geodesic sphere.
    const bool geodesic = a.frequency > 0;
    const std::string base = geodesic ? fmt::format("geodesic sphere frequency={}", a.frequency)
                                      : fmt::format("icosphere subdivisions={}", a.subdivisions);
    if (k == "sphere") {
        description = fmt::format("{} radius={}", base, a.radius);
        return geodesic ? geodesic_sphere(a.frequency, a.radius) : icosphere(a.subdivisions, a.radius);
    }
    if (k == "noisy-sphere") {
        description = fmt::format(
            "{} radius={} with uniform radial noise +-{} of the radius, seed={}; exact_H is the noise-free sphere's "
            "1/radius",
            base, a.radius, a.noise, a.seed);
        return geodesic ? noisy_sphere(geodesic_sphere(a.frequency, a.radius), a.noise, a.seed)
                        : noisy_sphere(a.subdivisions, a.noise, a.seed, a.radius);
    }
    if (k == "ellipsoid") {
        if (a.axes.size() != 3) throw InvalidArgumentError("generate: --axes takes three semi-axes A B C");
        description = fmt::format("ellipsoid: {} scaled by a={} b={} c={}", base, a.axes[0], a.axes[1], a.axes[2]);
        return geodesic ? ellipsoid(geodesic_sphere(a.frequency).mesh, a.axes[0], a.axes[1], a.axes[2])
                        : ellipsoid(a.subdivisions, a.axes[0], a.axes[1], a.axes[2]);
    }
    if (k == "torus") {
        const int n_major = a.n > 0 ? a.n : 64;
        const double ratio = a.major > 0 && a.minor > 0 ? a.minor / a.major : 0.25;
        const int n_minor = std::max(3, int(std::lround(n_major * ratio)));
        description =
            fmt::format("torus R={} r={} regular grid n_major={} n_minor={}", a.major, a.minor, n_major, n_minor);
        return torus(n_major, n_minor, a.major, a.minor);
    }
    if (k == "torus-irregular") {
        const std::size_t v = a.vertices > 0 ? a.vertices : 1024;
        description = fmt::format("torus R={} r={} irregular, about {} vertices, seed={}", a.major, a.minor, v, a.seed);
        return torus_irregular(v, a.major, a.minor, a.seed);
    }
    if (k == "heightfield") {
        const int n = a.n > 0 ? a.n : 33;
        description =
            fmt::format("height field (see shapes.h) amplitude={} on a regular {}x{} grid", a.amplitude, n, n);
        return heightfield(n, a.amplitude);
    }
    if (k == "heightfield-irregular") {
        const std::size_t v = a.vertices > 0 ? a.vertices : 1089;
        description = fmt::format("height field (see shapes.h) amplitude={} irregular, about {} vertices, seed={}",
                                  a.amplitude, v, a.seed);
        return heightfield_irregular(v, a.seed, a.amplitude);
    }
    // plane
    const int n = a.n > 0 ? a.n : 17;
    description = fmt::format("plane grid {}x{} spacing={}", n, n, a.spacing);
    return plane_grid(n, n, a.spacing);
}

int run_generate(const GenerateArgs& a)
{
    if (std::find(kinds().begin(), kinds().end(), a.kind) == kinds().end())
        throw InvalidArgumentError(fmt::format(
            "generate: unknown shape '{}' (expected sphere, noisy-sphere, ellipsoid, torus, torus-irregular, "
            "heightfield, heightfield-irregular or plane)",
            a.kind));
    const auto& ok = applicable(a.kind);
    for (const auto& [name, opt] : a.given)
        if (opt->count() > 0 && ok.count(name) == 0)
            throw InvalidArgumentError(fmt::format("generate: {} does not apply to {}", name, a.kind));
    if (a.given.at("--frequency")->count() > 0 && a.given.at("--subdivisions")->count() > 0)
        throw InvalidArgumentError(
            "generate: give --subdivisions (icosphere) or --frequency (geodesic sphere), not both");
    if (a.given.at("--frequency")->count() > 0 && (a.frequency < 1 || a.frequency > 1024))
        throw InvalidArgumentError(fmt::format("generate: --frequency must be in 1..1024 (got {})", a.frequency));
    if (a.given.at("--n")->count() > 0 && a.n < 2)
        throw InvalidArgumentError(fmt::format("generate: --n must be >= 2 (got {})", a.n));

    std::string description;
    const Shape shape = make_shape(a, description);
    write_mesh(a.out, shape.mesh, {{"exact_H", shape.exact_H}},
               {"meshdiff generate: " + description, "exact_H: exact mean curvature, +1/r on a sphere"});
    if (!writes_vertex_properties(a.out)) std::cerr << "meshdiff: note: exact_H is only stored in .ply files\n";
    std::cout << shape_text(a.out, shape, description);
    return 0;
}

}  // namespace

void add_generate_command(CLI::App& app, Action& action)
{
    auto args = std::make_shared<GenerateArgs>();
    auto* sub = app.add_subcommand(
        "generate", "write an analytic test surface with its exact mean curvature (PLY vertex property exact_H)");
    sub->add_option("SHAPE", args->kind,
                    "sphere | noisy-sphere | ellipsoid | torus | torus-irregular | heightfield | "
                    "heightfield-irregular | plane")
        ->required();
    sub->add_option("OUT", args->out, "output mesh (.ply keeps exact_H; .obj .off .stl do not)")->required();
    auto& g = args->given;
    g["--subdivisions"] =
        sub->add_option("--subdivisions", args->subdivisions, "icosphere subdivisions, 0..8 (sphere, ellipsoid)")
            ->check(in_range(0, 8, true))
            ->capture_default_str();
    g["--frequency"] = sub->add_option("--frequency", args->frequency,
                                       "instead of --subdivisions: geodesic sphere of frequency F, 20 F^2 faces (F = "
                                       "20: 8000 faces, the paper's size) (sphere, noisy-sphere, ellipsoid)")
                           ->check(in_range(1, 1024, true));
    g["--radius"] =
        sub->add_option("--radius", args->radius, "sphere radius")->check(positive())->capture_default_str();
    g["--noise"] =
        sub->add_option("--noise", args->noise, "noisy-sphere: radial noise, uniform in [-F, F) times the radius")
            ->capture_default_str();
    g["--axes"] = sub->add_option("--axes", args->axes, "ellipsoid semi-axes A B C along x, y, z")
                      ->expected(3)
                      ->capture_default_str();
    g["--major"] = sub->add_option("--major", args->major, "torus centre-circle radius R")->capture_default_str();
    g["--minor"] = sub->add_option("--minor", args->minor, "torus tube radius r")->capture_default_str();
    g["--n"] = sub->add_option("--n", args->n,
                               "grid resolution: torus vertices around the major circle (default 64; the tube gets "
                               "n r/R), heightfield and plane vertices per side (default 33, 17); at most 8192")
                   ->check(in_range(2, 8192, true));
    g["--vertices"] = sub->add_option("--vertices", args->vertices,
                                      "approximate vertex count of the irregular shapes (default 1024, 1089); at "
                                      "most 2^26")
                          ->check(in_range(1, double(std::size_t(1) << 26), true));
    g["--amplitude"] = sub->add_option("--amplitude", args->amplitude, "height field amplitude")->capture_default_str();
    g["--spacing"] = sub->add_option("--spacing", args->spacing, "plane grid spacing")->capture_default_str();
    g["--seed"] = sub->add_option("--seed", args->seed, "random seed of the noisy and irregular shapes")
                      ->check(in_range(0, 1.8e19, true))
                      ->capture_default_str();
    sub->callback([args, &action] { action = [args] { return run_generate(*args); }; });
}

}  // namespace meshdiff::cli
