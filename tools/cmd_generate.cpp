#include "commands.h"
#include "meshdiff/error.h"
#include "meshdiff/frontend/options.h"
#include "meshdiff/io/io.h"
#include "meshdiff/report/text.h"
#include "meshdiff/studies/generate.h"
#include "options.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace meshdiff::cli {

namespace {

struct GenerateArgs
{
    std::string kind;
    std::string out;
    Given subdivisions, frequency, radius, noise, major, minor, n, vertices, amplitude, spacing, seed;
    std::vector<std::string> axes;
    CLI::Option* axes_option = nullptr;
};

std::optional<std::uint64_t> whole(const Given& g, const char* field)
{
    if (!g.given()) return std::nullopt;
    return parse_whole_number(field, g.text);
}

std::optional<int> small(const Given& g, const char* field)
{
    const auto v = whole(g, field);
    if (!v) return std::nullopt;
    return int(std::min<std::uint64_t>(*v, std::uint64_t(INT_MAX)));
}

std::optional<double> number(const Given& g, const char* field)
{
    if (!g.given()) return std::nullopt;
    return parse_number(field, g.text);
}

int run_generate(const GenerateArgs& a)
{
    GenerateOptions o;
    o.kind = parse_enum_option<ShapeKind>("generate.kind", a.kind);
    o.subdivisions = small(a.subdivisions, "generate.subdivisions");
    o.frequency = small(a.frequency, "generate.frequency");
    o.n = small(a.n, "generate.n");
    if (const auto v = whole(a.vertices, "generate.vertices")) o.vertices = std::size_t(*v);
    o.seed = whole(a.seed, "generate.seed");
    o.radius = number(a.radius, "generate.radius");
    o.noise = number(a.noise, "generate.noise");
    o.major = number(a.major, "generate.major");
    o.minor = number(a.minor, "generate.minor");
    o.amplitude = number(a.amplitude, "generate.amplitude");
    o.spacing = number(a.spacing, "generate.spacing");
    if (a.axes_option->count() > 0)
        o.axes = std::array<double, 3>{parse_number("generate.axes", a.axes.at(0)),
                                       parse_number("generate.axes", a.axes.at(1)),
                                       parse_number("generate.axes", a.axes.at(2))};
    const GeneratedShape g = generate_shape(o);
    const Shape& shape = g.shape;
    const std::string& description = g.description;
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
    std::string shapes;
    for (const auto& name : enum_names<ShapeKind>()) shapes += (shapes.empty() ? "" : " | ") + name;
    sub->add_option("SHAPE", args->kind, shapes)->required();
    sub->add_option("OUT", args->out, "output mesh (.ply keeps exact_H; .obj .off .stl do not)")->required();
    using D = GenerateDefaults;
    auto add = [sub](const char* name, Given& g, const std::string& help, const std::string& default_text,
                     const char* type) {
        g.option = sub->add_option(name, g.text, help)->type_name(type);
        if (!default_text.empty()) g.option->default_str(default_text);
    };
    add("--subdivisions", args->subdivisions,
        fmt::format("icosphere subdivisions, 0..{} (sphere, ellipsoid)", kMaxSubdivisions),
        fmt::format("{}", D::subdivisions), "INT");
    add("--frequency", args->frequency,
        fmt::format("instead of --subdivisions: geodesic sphere of frequency F in 1..{}, 20 F^2 faces (F = 20: 8000 "
                    "faces, the paper's size) (sphere, noisy-sphere, ellipsoid)",
                    kMaxFrequency),
        "", "INT");
    add("--radius", args->radius, "sphere radius", fmt::format("{}", D::radius), "FLOAT");
    add("--noise", args->noise, "noisy-sphere: radial noise, uniform in [-F, F) times the radius",
        fmt::format("{}", D::noise), "FLOAT");
    args->axes_option = sub->add_option("--axes", args->axes, "ellipsoid semi-axes A B C along x, y, z")
                            ->expected(3)
                            ->type_name("FLOAT")
                            ->default_str(fmt::format("{} {} {}", D::axes[0], D::axes[1], D::axes[2]));
    add("--major", args->major, "torus centre-circle radius R", fmt::format("{}", D::major), "FLOAT");
    add("--minor", args->minor, "torus tube radius r", fmt::format("{}", D::minor), "FLOAT");
    add("--n", args->n,
        fmt::format("grid resolution: torus vertices around the major circle (default {}; the tube gets n r/R), "
                    "heightfield and plane vertices per side (default {}, {}); {}..{}",
                    D::torus_n, D::heightfield_n, D::plane_n, kMinGridN, kMaxGridN),
        "", "INT");
    add("--vertices", args->vertices,
        fmt::format("approximate vertex count of the irregular shapes (default {}, {}); at most {}", D::torus_vertices,
                    D::heightfield_vertices, kMaxIrregularVertices),
        "", "UINT");
    add("--amplitude", args->amplitude, "height field amplitude", fmt::format("{}", D::amplitude), "FLOAT");
    add("--spacing", args->spacing, "plane grid spacing", fmt::format("{}", D::spacing), "FLOAT");
    add("--seed", args->seed, "random seed of the noisy and irregular shapes", fmt::format("{}", D::seed), "UINT");
    sub->callback([args, &action] { action = [args] { return run_generate(*args); }; });
}

}  // namespace meshdiff::cli
