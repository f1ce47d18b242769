#include "commands.h"

namespace meshdiff::cli {

void add_batch_command(CLI::App& app, Action& action)
{
    auto* sub = app.add_subcommand("batch", "(not yet implemented)");
    sub->callback([&action] { action = [] { return 0; }; });
}

}  // namespace meshdiff::cli
