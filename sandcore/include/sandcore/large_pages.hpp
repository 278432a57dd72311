// SPDX-License-Identifier: MIT
#pragma once
// Memory for the big arrays of a scene (cell grids, the grain records a step writes by id, the
// sweeps' awake words and the granular sweeps' bits, the surface's cell bits) and of the
// voxelizer: blocks from half a huge page up are rounded up to whole 2 MiB pages, aligned to
// them and offered to the kernel as transparent huge pages (madvise), so a sweep over a grid of a million cells, or a step writing
// the records of grains all over the id range, takes a few TLB entries instead of hundreds or
// thousands of 4 KiB ones. Freed blocks are kept, up to kLargeBlockCacheBytes, for the next
// allocation of a similar size: fresh memory costs a page fault per page and the kernel's
// clearing of every byte. Smaller blocks come from operator new as usual.

#include <cstddef>
#include <new>
#include <utility>

namespace sandcore {

/// A huge page, bytes.
inline constexpr std::size_t kLargePageBytes = std::size_t{2} << 20;
/// Smallest block handed to huge pages (rounded up to a whole one), bytes.
inline constexpr std::size_t kSmallestLargeBlock = kLargePageBytes / 2;

/// Freed large blocks kept for reuse at most, bytes (none under AddressSanitizer).
inline constexpr std::size_t kLargeBlockCacheBytes = std::size_t{256} << 20;

/// bytes of memory, 2 MiB aligned and advised as huge pages when bytes >= kSmallestLargeBlock.
/// Throws std::bad_alloc when no memory is left.
void* allocateLarge(std::size_t bytes);
/// Frees a block of allocateLarge(bytes), given the same byte count: kept for reuse while the
/// kept blocks stay within kLargeBlockCacheBytes, returned to the system otherwise.
void freeLarge(void* block, std::size_t bytes) noexcept;
/// Returns every kept block to the system (when memory is needed elsewhere).
void releaseLargeBlockCache() noexcept;
/// Bytes of the blocks kept for reuse.
std::size_t largeBlockCacheBytes() noexcept;

/// A std::allocator that takes its memory from allocateLarge.
template <class T> struct LargePageAllocator {
    using value_type = T;
    LargePageAllocator() = default;
    template <class U> LargePageAllocator(const LargePageAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) { return static_cast<T*>(allocateLarge(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { freeLarge(p, n * sizeof(T)); }
    template <class U> bool operator==(const LargePageAllocator<U>&) const noexcept { return true; }
};

/// LargePageAllocator whose resize leaves the new elements default-initialised (unwritten, for
/// arrays a parallel pass fills): writing zeros first would touch every page twice, on one
/// thread. A vector sized without a value holds indeterminate elements until they are written.
template <class T> struct FillLaterAllocator : LargePageAllocator<T> {
    using value_type = T;
    FillLaterAllocator() = default;
    template <class U> FillLaterAllocator(const FillLaterAllocator<U>&) noexcept {}
    template <class U> void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; }
    template <class U, class... Args> void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

} // namespace sandcore
