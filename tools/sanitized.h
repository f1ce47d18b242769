// MESHDIFF_SANITIZED: defined when the build runs under AddressSanitizer,
// MemorySanitizer or ThreadSanitizer (clang's __has_feature, GCC's
// __SANITIZE_*__ macros). The tool's operator new (huge_pages.cpp) stands
// aside there, so that the sanitizers' own allocator checks every new against
// its delete; its test (tests/huge_pages_test.cpp) is skipped likewise.
#pragma once

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
#define MESHDIFF_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define MESHDIFF_SANITIZED 1
#endif
