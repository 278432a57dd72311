// SPDX-License-Identifier: MIT
#pragma once
// The allocators of the big arrays of a scene (cell grids, grain records, masks): blocks from
// about a megabyte up sit on transparent huge pages, so a sweep over a grid of a million cells
// takes a few TLB entries instead of thousands, and freed blocks are kept for reuse (the page
// sizes and the cache: sandcore/src/large_blocks.hpp).

#include <cstddef>
#include <new>
#include <utility>

namespace sandcore {

/// bytes of memory, on huge pages from about a megabyte up (large_blocks.hpp). Throws
/// std::bad_alloc when no memory is left.
void* allocateLarge(std::size_t bytes);
/// Frees a block of allocateLarge(bytes), given the same byte count (it may be kept for reuse).
void freeLarge(void* block, std::size_t bytes) noexcept;

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
