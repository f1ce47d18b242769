#include "commands.h"
#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/noise.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
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
    NoiseOptions options;  // amplitude, seed and move_boundary bound to the options below
};

// What was done, for the PLY comment and the summary line: "uniform [-0.5, 0.5) x mean edge length 0.0123".
std::string describe(const NoiseOptions& o, const NoiseReport& r)
{
    const std::string law = o.distribution == NoiseDistribution::Uniform
                                ? fmt::format("uniform [-{}, {})", o.amplitude, o.amplitude)
                                : fmt::format("gaussian sigma {}", o.amplitude);
    switch (o.unit) {
        case NoiseUnit::MeanEdge:
            return fmt::format("{} x mean edge length {:.6g}", law, r.unit_length);
        case NoiseUnit::BBoxDiagonal:
            return fmt::format("{} x bbox diagonal {:.6g}", law, r.unit_length);
        case NoiseUnit::Absolute:
            break;
    }
    return law + " in mesh units";
}

int run_noise(const NoiseArgs& a)
{
    NoiseOptions options = a.options;
    options.unit = parse_noise_unit(a.unit);
    options.direction = parse_noise_direction(a.direction);
    options.distribution = parse_noise_distribution(a.distribution);
    LoadedMesh loaded = read_mesh(a.in);
    const NoiseReport r = add_noise(loaded.mesh, options);

    const std::string along =
        options.direction == NoiseDirection::Normal ? "along vertex normals" : "along random directions";
    const std::filesystem::path out(a.out);
    std::string ext = out.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".ply") {
        std::string comment =
            fmt::format("meshdiff noise: {} moved {} by {} = amplitude {:.6g}, seed {}, boundary {}", a.in, along,
                        describe(options, r), r.amplitude, options.seed, options.move_boundary ? "moved" : "fixed");
        std::replace_if(
            comment.begin(), comment.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
        write_ply(out, loaded.mesh, {}, {}, {comment});
    } else {
        write_mesh(out, loaded.mesh);
    }
    std::cout << fmt::format(
        "{}: {} vertices moved, {} skipped ({} boundary, {} without direction, {} isolated); amplitude {:.6g} ({}) "
        "{}, seed {}\n",
        a.out, r.moved, r.skipped(), r.skipped_boundary, r.skipped_no_direction, r.skipped_isolated, r.amplitude,
        describe(options, r), along, options.seed);
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
        ->capture_default_str();
    sub->add_option("--direction", args->direction,
                    "normal (angle-weighted vertex normal) | random (uniform random unit vector per vertex)")
        ->capture_default_str();
    sub->add_option("--distribution", args->distribution, "uniform | gaussian")->capture_default_str();
    sub->add_option("--seed", o.seed, "random seed (std::mt19937_64)")->capture_default_str();
    sub->add_flag("--move-boundary", o.move_boundary, "also move boundary and non-manifold-edge vertices");
    sub->callback([args, &action] { action = [args] { return run_noise(*args); }; });
}

}  // namespace meshdiff::cli
