#include "cli.h"

#include <csignal>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    // Past a file-size limit a write fails (EFBIG) instead of killing the
    // process, so the output's temporary file is removed and the old file kept.
    std::signal(SIGXFSZ, SIG_IGN);
    std::vector<std::string> args(argv, argv + argc);
    return meshdiff::cli::run(args);
}
