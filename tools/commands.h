//! \file commands.h
//! \brief One function per subcommand of the meshdiff tool. Each registers its
//! options on a CLI11 subcommand and returns the action to run once parsing has
//! succeeded. Each subcommand lives in its own tools/cmd_<name>.cpp.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace meshdiff::cli {

//! The work of a parsed subcommand; returns the process exit code.
using Action = std::function<int()>;

void add_profile_command(CLI::App& app, Action& action);        // tools/cmd_profile.cpp
void add_compare_command(CLI::App& app, Action& action);        // tools/cmd_compare.cpp (also the default command)
void add_batch_command(CLI::App& app, Action& action);          // tools/batch/cmd_batch.cpp
void add_batch_summary_command(CLI::App& app, Action& action);  // tools/batch/cmd_batch_summary.cpp
void add_generate_command(CLI::App& app, Action& action);       // tools/cmd_generate.cpp
void add_smooth_command(CLI::App& app, Action& action);         // tools/cmd_smooth.cpp
void add_noise_command(CLI::App& app, Action& action);          // tools/cmd_noise.cpp

}  // namespace meshdiff::cli
