#include "commands.h"
#include "meshdiff/frontend/options.h"
#include "meshdiff/io/io.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/text.h"
#include "meshdiff/studies/noise.h"
#include "options.h"

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <string>

namespace meshdiff::cli {

namespace {

struct NoiseArgs
{
    std::string in;
    std::string out;
    std::string unit = "edge";
    std::string direction = "normal";
    std::string distribution = "uniform";
    NoiseOptions options;  // amplitude and move_boundary bound to the options below
    Given seed;
};

int run_noise(const NoiseArgs& a)
{
    refuse_overwriting_inputs("OUT", a.out, {a.in});
    NoiseOptions options = a.options;
    options.unit = parse_enum<NoiseUnit>(a.unit);
    options.direction = parse_enum<NoiseDirection>(a.direction);
    options.distribution = parse_enum<NoiseDistribution>(a.distribution);
    if (a.seed.given()) options.seed = parse_whole_number("noise.seed", a.seed.text);
    LoadedMesh loaded = read_mesh(a.in);
    const NoiseReport r = add_noise(loaded.mesh, options);
    write_mesh(a.out, loaded.mesh, {}, {noise_comment(a.in, options, r)});
    std::cout << noise_text(a.out, options, r);
    return 0;
}

}  // namespace

void add_noise_command(CLI::App& app, Action& action)
{
    auto args = std::make_shared<NoiseArgs>();
    auto* sub = app.add_subcommand(
        "noise", "add seeded random noise to the vertex positions of a mesh (boundary vertices fixed by default)");
    sub->add_option("IN", args->in, "input mesh (.ply .obj .off .stl)")->required();
    sub->add_option("OUT", args->out, "output mesh (.ply keeps double precision; .obj .off .stl)")->required();
    NoiseOptions& o = args->options;
    sub->add_option("--amplitude", o.amplitude,
                    "noise amplitude A in units of --unit: uniform in [-A, A) or gaussian with sigma A")
        ->required();
    sub->add_option("--unit", args->unit,
                    "edge (the mean edge length) | diagonal (the bounding-box diagonal) | absolute (mesh units)")
        ->check(CLI::IsMember(enum_names<NoiseUnit>()))
        ->capture_default_str();
    sub->add_option("--direction", args->direction,
                    "normal (angle-weighted vertex normal) | random (uniform random unit vector per vertex)")
        ->check(CLI::IsMember(enum_names<NoiseDirection>()))
        ->capture_default_str();
    sub->add_option("--distribution", args->distribution, "uniform | gaussian")
        ->check(CLI::IsMember(enum_names<NoiseDistribution>()))
        ->capture_default_str();
    args->seed.option = sub->add_option("--seed", args->seed.text, "random seed (std::mt19937_64)")
                            ->type_name("UINT")
                            ->default_str(fmt::format("{}", NoiseOptions{}.seed));
    sub->add_flag("--move-boundary", o.move_boundary, "also move boundary and non-manifold-edge vertices");
    sub->callback([args, &action] { action = [args] { return run_noise(*args); }; });
}

}  // namespace meshdiff::cli
