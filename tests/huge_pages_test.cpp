// The command-line tool's operator new (tools/huge_pages.cpp), linked into
// this test alone: a block of 2 MiB and more is advised for transparent huge
// pages, whether it comes from the plain or the over-aligned form (the
// closest-point index's 64-byte nodes): the kernel marks the mapping "hg" in
// /proc/self/smaps.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sanitized.h"  // tools/

#if !defined(MESHDIFF_SANITIZED) && defined(__linux__)
namespace {

// The VmFlags line of the mapping of /proc/self/smaps that holds \p p, or "".
std::string vm_flags_of(const void* p)
{
    std::ifstream smaps("/proc/self/smaps");
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> begin >> dash >> end && dash == '-') {
            inside = begin <= at && at < end;
            continue;
        }
        if (inside && line.rfind("VmFlags:", 0) == 0) return line + " ";
    }
    return "";
}

struct alignas(64) Wide
{
    unsigned char bytes[64];
};

}  // namespace
#endif

TEST(HugePages, LargeBlocksAreAdvisedInThePlainAndTheOverAlignedForm)
{
#if defined(MESHDIFF_SANITIZED) || !defined(__linux__)
    GTEST_SKIP() << "the sanitizers' operator new is kept (and huge pages are Linux's)";
#else
    if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled")) GTEST_SKIP() << "no transparent huge pages";
    std::vector<double> plain(std::size_t(1) << 20);  // 8 MiB
    std::vector<Wide> wide(std::size_t(1) << 17);     // 8 MiB, aligned to 64 bytes
    ASSERT_EQ(reinterpret_cast<std::uintptr_t>(wide.data()) % 64, 0u);
    // The middle of each block lies in an aligned 2 MiB stretch of it.
    EXPECT_NE(vm_flags_of(plain.data() + plain.size() / 2).find(" hg "), std::string::npos)
        << vm_flags_of(plain.data() + plain.size() / 2);
    EXPECT_NE(vm_flags_of(wide.data() + wide.size() / 2).find(" hg "), std::string::npos)
        << vm_flags_of(wide.data() + wide.size() / 2);
#endif
}
