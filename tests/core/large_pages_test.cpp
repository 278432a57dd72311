// Large blocks: aligned for huge pages, and freed ones kept (within a bound) for the next
// allocation of a similar size, except under AddressSanitizer.
#include "sandcore/large_pages.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <vector>

using namespace sandcore;

namespace {
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kKeepsBlocks = false;
#elif defined(__has_feature)
constexpr bool kKeepsBlocks = !__has_feature(address_sanitizer);
#else
constexpr bool kKeepsBlocks = true;
#endif
constexpr std::size_t kMiB = std::size_t{1} << 20;
} // namespace

TEST_CASE("a freed large block serves the next allocation of a similar size") {
    releaseLargeBlockCache();
    REQUIRE(largeBlockCacheBytes() == 0);
    void* first = allocateLarge(5 * kMiB); // 6 MiB once rounded to huge pages
    CHECK(reinterpret_cast<std::uintptr_t>(first) % kLargePageBytes == 0);
    std::memset(first, 7, 5 * kMiB);
    freeLarge(first, 5 * kMiB);
    if (!kKeepsBlocks) {
        CHECK(largeBlockCacheBytes() == 0); // nothing kept: a use after free is still caught
        return;
    }
    CHECK(largeBlockCacheBytes() == 6 * kMiB);
    // A block more than twice the size asked for is not lent out: a new one is made.
    void* small = allocateLarge(2 * kMiB);
    CHECK(small != first);
    CHECK(largeBlockCacheBytes() == 6 * kMiB);
    freeLarge(small, 2 * kMiB);
    CHECK(largeBlockCacheBytes() == 8 * kMiB);
    // The smallest kept block that fits is reused, and its whole size comes back with it.
    void* again = allocateLarge(3 * kMiB + 1); // 4 MiB: the 6 MiB block, not the 2 MiB one
    CHECK(again == first);
    CHECK(largeBlockCacheBytes() == 2 * kMiB);
    freeLarge(again, 3 * kMiB + 1);
    CHECK(largeBlockCacheBytes() == 8 * kMiB);
    releaseLargeBlockCache();
    CHECK(largeBlockCacheBytes() == 0);
}

TEST_CASE("the kept large blocks never exceed their bound") {
    releaseLargeBlockCache();
    const std::size_t blockBytes = 64 * kMiB; // untouched: address space only
    std::vector<void*> blocks;
    for (std::size_t n = 0; n < kLargeBlockCacheBytes / blockBytes + 2; ++n) blocks.push_back(allocateLarge(blockBytes));
    for (void* block : blocks) freeLarge(block, blockBytes);
    CHECK(largeBlockCacheBytes() <= kLargeBlockCacheBytes);
    if (kKeepsBlocks) CHECK(largeBlockCacheBytes() == kLargeBlockCacheBytes / blockBytes * blockBytes);
    releaseLargeBlockCache();
    CHECK(largeBlockCacheBytes() == 0);
}
