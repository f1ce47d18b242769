#include "cli.h"

#include <csignal>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

int main(int argc, char** argv)
{
    // Past a file-size limit a write fails (EFBIG) instead of killing the
    // process, so the output's temporary file is removed and the old file kept.
    std::signal(SIGXFSZ, SIG_IGN);
#if defined(__GLIBC__)
    // Blocks of 128 KiB and more are mapped on their own and unmapped when
    // freed. glibc otherwise raises this threshold to the largest block freed
    // (up to 32 MiB), after which the arrays of one stage (a topology report's
    // half-edges, a curvature fit's buffers) stay in the heap when freed and
    // count in the process's peak memory (1M-vertex profile: 478 -> 428 MB).
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
    std::vector<std::string> args(argv, argv + argc);
    return meshdiff::cli::run(args);
}
