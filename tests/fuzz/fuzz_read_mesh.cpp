// libFuzzer entry point: the bytes as a mesh file of one format (the extension
// MESHDIFF_FUZZ_EXT, set per target), read with meshdiff::read_mesh. Any
// meshdiff::Error is a correct answer; a crash, a sanitizer report, a hang
// (-timeout) or runaway memory (-rss_limit_mb) is a bug. See scripts/fuzz.sh.
#include "meshdiff/error.h"
#include "meshdiff/io/io.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    // read_mesh reads files: one per process, in memory-backed /dev/shm when there is one.
    static const std::string path = std::string(access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp") +
                                    "/meshdiff-fuzz-" + std::to_string(getpid()) + MESHDIFF_FUZZ_EXT;
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return 0;
    if (size > 0) std::fwrite(data, 1, size, f);
    std::fclose(f);
    try {
        const meshdiff::LoadedMesh m = meshdiff::read_mesh(path);
        // What read_mesh returns is a valid mesh (meshdiff::validate's contract).
        meshdiff::validate(m.mesh, "fuzz");
    } catch (const meshdiff::Error&) {}
    return 0;
}
