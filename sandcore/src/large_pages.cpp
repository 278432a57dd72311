// SPDX-License-Identifier: MIT
#include "large_blocks.hpp"

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#if defined(__has_feature)
#define SANDCORE_HAS_ADDRESS_SANITIZER __has_feature(address_sanitizer)
#else
#define SANDCORE_HAS_ADDRESS_SANITIZER 0
#endif

namespace sandcore {

namespace {

std::size_t roundedToLargePages(std::size_t bytes) {
    return (bytes + kLargePageBytes - 1) / kLargePageBytes * kLargePageBytes;
}

// Freed blocks kept for the next large allocation. A fresh block costs a page fault per page
// and the kernel's clearing of every byte: for the voxelizer's arrays that was a third of its
// time on a cold process, and a scene rebuilt at the same size asks for the same blocks again.
// Under AddressSanitizer nothing is kept, so a use after free is still caught.
class BlockCache {
public:
    // A cached block serves a request of at least half its size (the rest of it lies idle
    // while it is in use).
    void* take(std::size_t rounded) {
        const std::lock_guard<std::mutex> lock(mutex_);
        auto best = blocks_.end();
        for (auto it = blocks_.begin(); it != blocks_.end(); ++it)
            if (it->bytes >= rounded && it->bytes <= 2 * rounded && (best == blocks_.end() || it->bytes < best->bytes))
                best = it;
        if (best == blocks_.end()) return nullptr;
        Block block = *best;
        blocks_.erase(best);
        cachedBytes_ -= block.bytes;
        lent_.push_back(block);
        return block.address;
    }

    // Remembers that `address` is a fresh block of `rounded` bytes, so its true size is known when it comes back.
    void lend(void* address, std::size_t rounded) {
        const std::lock_guard<std::mutex> lock(mutex_);
        lent_.push_back({address, rounded});
    }

    // Takes the block back; returns false when it does not fit in the cache (the caller frees it).
    bool keep(void* address) {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto it = std::find_if(lent_.begin(), lent_.end(), [&](const Block& b) { return b.address == address; });
        const Block block = *it;
        lent_.erase(it);
        if (!kEnabled || cachedBytes_ + block.bytes > kLargeBlockCacheBytes) return false;
        try {
            blocks_.push_back(block);
        } catch (const std::bad_alloc&) {
            return false;
        }
        cachedBytes_ += block.bytes;
        return true;
    }

    void release() {
        std::vector<Block> blocks;
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            blocks.swap(blocks_);
            cachedBytes_ = 0;
        }
        for (const Block& block : blocks) std::free(block.address);
    }

    std::size_t cachedBytes() {
        const std::lock_guard<std::mutex> lock(mutex_);
        return cachedBytes_;
    }

private:
#if defined(__SANITIZE_ADDRESS__) || SANDCORE_HAS_ADDRESS_SANITIZER
    static constexpr bool kEnabled = false;
#else
    static constexpr bool kEnabled = true;
#endif
    struct Block {
        void* address;
        std::size_t bytes;
    };
    std::mutex mutex_;
    std::vector<Block> blocks_; // a few dozen at most: a list is enough
    std::vector<Block> lent_;
    std::size_t cachedBytes_ = 0;
};

// Never destroyed: grids in static objects may be freed after every other static.
BlockCache& blockCache() {
    static BlockCache* cache = new BlockCache;
    return *cache;
}

} // namespace

void* allocateLarge(std::size_t bytes) {
    if (bytes < kSmallestLargeBlock) return ::operator new(bytes);
    const std::size_t rounded = roundedToLargePages(bytes);
    if (void* reused = blockCache().take(rounded)) return reused;
    void* block = std::aligned_alloc(kLargePageBytes, rounded);
    if (!block) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
    // Only advice: where the kernel has no huge pages to give, the block works as it is.
    madvise(block, rounded, MADV_HUGEPAGE);
#endif
    try {
        blockCache().lend(block, rounded);
    } catch (...) {
        std::free(block);
        throw;
    }
    return block;
}

void freeLarge(void* block, std::size_t bytes) noexcept {
    if (bytes < kSmallestLargeBlock) {
        ::operator delete(block);
        return;
    }
    if (!blockCache().keep(block)) std::free(block);
}

void releaseLargeBlockCache() noexcept { blockCache().release(); }

std::size_t largeBlockCacheBytes() noexcept { return blockCache().cachedBytes(); }

} // namespace sandcore
