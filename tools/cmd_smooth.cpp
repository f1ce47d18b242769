#include "commands.h"
#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/smoothing.h"

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <string>

namespace meshdiff::cli {

namespace {

struct SmoothArgs
{
    std::string in;
    std::string out;
    std::string method = "laplacian";
    std::string update = "post";
    SmoothingOptions options;  // numeric fields bound to the options below
    // TODO(profile): --profile-every K --json FILE. Record the roughness
    // profile (levels 1, 5, 10, 20 and global) at iteration 0 and every K
    // iterations through SmoothingOptions::callback, and write
    // {"schema": "meshdiff.smoothing/1", "method", "update", "iterations": [...],
    //  "levels": [...], "sigma": [[...] per recorded iteration],
    //  "sigma_global": [...]}. Waits for the committed roughness_profile API.
};

int run_smooth(const SmoothArgs& a)
{
    SmoothingOptions options = a.options;
    options.method = parse_smoothing_method(a.method);
    options.update = parse_smoothing_update(a.update);
    LoadedMesh loaded = read_mesh(a.in);
    smooth(loaded.mesh, options);
    write_mesh(a.out, loaded.mesh);
    std::cout << fmt::format("{}: {} {}-updating, {} iterations, {} vertices\n", a.out, a.method, a.update,
                             options.iterations, loaded.mesh.n_vertices());
    return 0;
}

}  // namespace

void add_smooth_command(CLI::App& app, Action& action)
{
    auto args = std::make_shared<SmoothArgs>();
    auto* sub =
        app.add_subcommand("smooth", "smooth a mesh (boundary vertices fixed) with one of the paper's five methods");
    sub->add_option("IN", args->in, "input mesh (.ply .obj .off .stl)")->required();
    sub->add_option("OUT", args->out, "output mesh (.ply .obj .off .stl)")->required();
    sub->add_option("--method", args->method, "laplacian | taubin | bilaplacian | mcf | modified-mcf")
        ->capture_default_str();
    sub->add_option("--update", args->update,
                    "post (Jacobi, from the previous positions) | pre (Gauss-Seidel, in "
                    "place in vertex order)")
        ->capture_default_str();
    SmoothingOptions& o = args->options;
    sub->add_option("--iterations", o.iterations, "iterations (a Taubin iteration is a lambda and a mu step)")
        ->capture_default_str();
    sub->add_option("--lambda", o.lambda, "Laplacian / Taubin step, in (0, 1]")->capture_default_str();
    sub->add_option("--mu", o.mu, "Taubin negative step, < -lambda")->capture_default_str();
    sub->add_option("--step", o.step, "mcf / modified-mcf time step in units of the squared mean edge length")
        ->capture_default_str();
    sub->add_option("--damping", o.damping, "bilaplacian relaxation factor, in (0, 1]")->capture_default_str();
    sub->add_option("--epsilon", o.epsilon,
                    "modified-mcf: vertices whose umbrella is within acos(eps) of "
                    "perpendicular to the curvature normal do not move")
        ->capture_default_str();
    sub->callback([args, &action] { action = [args] { return run_smooth(*args); }; });
}

}  // namespace meshdiff::cli
