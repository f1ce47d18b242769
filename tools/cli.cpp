#include "cli.h"

namespace meshdiff::cli {
int run(const std::vector<std::string>&) { return kOk; }
}  // namespace meshdiff::cli
