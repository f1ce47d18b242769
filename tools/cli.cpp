#include "cli.h"

#include "commands.h"
#include "interrupt.h"
#include "meshdiff/error.h"
#include "meshdiff/frontend/options.h"
#include "meshdiff/version.h"
#include "options.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <csignal>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <set>

namespace meshdiff::cli {

namespace {

bool is_subcommand(const std::string& word)
{
    static const std::array<const char*, 7> names = {"profile",  "compare", "batch", "batch-summary",
                                                     "generate", "smooth",  "noise"};
    return std::any_of(names.begin(), names.end(), [&](const char* n) { return word == n; });
}

std::string g_command_line;

// \p word quoted for a POSIX shell where it needs it.
std::string shell_quoted(const std::string& word)
{
    const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || std::strchr("_./:=,+-@%^", c) != nullptr;
    });
    if (plain) return word;
    std::string q = "'";
    for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

const std::string& command_line()
{
    return g_command_line;
}

Failure failure_of(const std::exception& e)
{
    if (const auto* o = dynamic_cast<const OptionError*>(&e)) return {kUsage, worded(*o, cli_spelling)};
    if (dynamic_cast<const InvalidArgumentError*>(&e)) return {kUsage, e.what()};
    if (dynamic_cast<const IoError*>(&e)) return {kIoError, e.what()};
    if (dynamic_cast<const InvalidMeshError*>(&e)) return {kInvalidMesh, e.what()};
    if (dynamic_cast<const SolverError*>(&e)) return {kSolverError, e.what()};
    if (dynamic_cast<const Cancelled*>(&e))
        return {kInterrupted, fmt::format("interrupted by {}: stopped, no output file written",
                                          interrupt_signal() == SIGTERM ? "SIGTERM" : "SIGINT")};
    if (dynamic_cast<const std::bad_alloc*>(&e))
        return {kOutOfMemory, "out of memory: the meshes or the options ask for more than this machine has"};
    return {kInternal, std::string("internal error: ") + e.what()};
}

int run(const std::vector<std::string>& raw_args)
{
    std::vector<std::string> args = raw_args;
    if (args.empty()) args.emplace_back("meshdiff");
    g_command_line.clear();
    for (const std::string& a : args) g_command_line += (g_command_line.empty() ? "" : " ") + shell_quoted(a);
    // `meshdiff A B [options]` is `meshdiff compare A B [options]`.
    if (args.size() > 1 && !is_subcommand(args[1]) && args[1] != "-h" && args[1] != "--help" && args[1] != "--version")
        args.insert(args.begin() + 1, "compare");

    CLI::App app{
        "meshdiff: how much a processed triangle mesh differs from its original, and at which scale.\n"
        "  meshdiff ORIGINAL PROCESSED [options]   (same as: meshdiff compare ...)\n"
        "Exit codes: 0 ok, 2 usage, 3 unreadable input or unwritable output, 4 invalid mesh,\n"
        "5 numerical failure, 6 batch finished with failed pairs, 7 out of memory, 70 internal error,\n"
        "130 interrupted (Ctrl-C, SIGTERM).",
        "meshdiff"};
    app.set_version_flag("--version", std::string("meshdiff ") + MESHDIFF_VERSION);
    app.require_subcommand(1);
    Action action;
    add_profile_command(app, action);
    add_compare_command(app, action);
    add_batch_command(app, action);
    add_batch_summary_command(app, action);
    add_generate_command(app, action);
    add_smooth_command(app, action);
    add_noise_command(app, action);

    std::vector<std::string> reversed(args.rbegin(), args.rend() - 1);
    try {
        app.parse(std::move(reversed));
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "meshdiff: " << e.what() << " (see meshdiff --help)\n";
        return kUsage;
    } catch (const InvalidArgumentError& e) {
        const Failure f = failure_of(e);
        std::cerr << "meshdiff: " << f.message << "\n";
        return f.code;
    }
    // An option given an empty value ('--json ""', '--threads ""') is refused, not taken as "none" or 0;
    // only a list may be empty ('--levels ""': no ring level).
    static const std::set<std::string> lists = {"--levels", "--radii", "--fscore"};
    for (const CLI::App* sub : app.get_subcommands())
        for (const CLI::Option* o : sub->get_options())
            for (const std::string& value : o->results())
                if (value.empty() && !lists.count(o->get_name())) {
                    std::cerr << "meshdiff: " << o->get_name() << ": an empty value\n";
                    return kUsage;
                }
    if (!action) return kOk;
    try {
        return action();
    } catch (const std::exception& e) {
        const Failure f = failure_of(e);
        std::cerr << "meshdiff: " << f.message << "\n";
        return f.code;
    }
}

}  // namespace meshdiff::cli
