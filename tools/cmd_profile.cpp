#include "commands.h"

namespace meshdiff::cli {

void add_profile_command(CLI::App& app, Action& action)
{
    auto* sub = app.add_subcommand("profile", "(not yet implemented)");
    sub->callback([&action] { action = [] { return 0; }; });
}

}  // namespace meshdiff::cli
