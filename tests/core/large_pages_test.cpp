// SPDX-License-Identifier: MIT
// Large blocks: aligned for huge pages, and freed ones kept (within a bound) for the next
// allocation of a similar size, except under AddressSanitizer.
#include "cell_bits.hpp"
#include "large_blocks.hpp"
#include "sandcore/grain_store.hpp"

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

// What a step and the surface upkeep read or write at random (grain records by id, the sweeps'
// and the surface's bits by cell) sits in huge-page blocks once it is big enough to span many.
TEST_CASE("grain records, fall states and big cell bits start on huge-page boundaries") {
    auto onBoundary = [](const void* p) { return reinterpret_cast<std::uintptr_t>(p) % kLargePageBytes == 0; };
    GrainStore grains;
    grains.reserve(300'000); // 4.8 MB of place records, 2.4 MB of fall states per grid
    CHECK(onBoundary(grains.place.data()));
    CHECK(onBoundary(grains.fall[0].data()));
    CHECK(onBoundary(grains.fall[1].data()));
    CellBits big, half, small;
    big.assign(40'000'000);  // 5 MB
    half.assign(9'000'000);  // 1.1 MB: a whole huge page rather than 4 KiB pages
    small.assign(100'000);   // 12.5 KB: as any small vector
    CHECK(onBoundary(big.byteOf(0)));
    CHECK(onBoundary(half.byteOf(0)));
    // The bits stay usable past every boundary of the rounded block.
    half.set(8'999'999, true);
    CHECK(half.test(8'999'999));
    CHECK_FALSE(half.test(8'999'998));
    small.set(99'999, true);
    CHECK(small.test(99'999));
}
