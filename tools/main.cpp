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
    // Freed memory up to 64 MiB stays at the top of each heap (the main one
    // and the worker threads'), where the next stage's blocks are carved from
    // it without fresh pages: glibc otherwise returns it at each free and the
    // next block faults and zeroes its pages anew. Default compare of igea and
    // its 10 % decimation: 4.1 -> 2.7 s, page faults 158K -> 43K, peak memory
    // 108 -> 160 MB; docs/performance.md, "Issue 30, lever 4".
    mallopt(M_TOP_PAD, 64 * 1024 * 1024);
    // One heap for every thread. Each further heap (glibc makes one per thread
    // that allocates while the others hold theirs: the OpenMP workers, the
    // tasks beside them) keeps its own freed pages, up to the pad above,
    // which no other thread's blocks can reuse. 1M-vertex profile: peak 273
    // -> 210 MB; 2 x 1M compare 885 -> 806 MB; default compare of igea and its
    // 10 % decimation 2 % slower (more page faults), the others unchanged:
    // the workers allocate outside their loops. docs/performance.md, "Issue
    // 30, huge pages, one heap and the serial steps".
    mallopt(M_ARENA_MAX, 1);
#endif
    std::vector<std::string> args(argv, argv + argc);
    return meshdiff::cli::run(args);
}
