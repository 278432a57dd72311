// SPDX-License-Identifier: MIT
#pragma once
// How allocateLarge (sandcore/large_pages.hpp) places its blocks: from half a huge page up they
// are rounded up to whole 2 MiB pages, aligned to them and offered to the kernel as transparent
// huge pages (madvise), so a sweep over a grid of a million cells, or a step writing the records
// of grains all over the id range, takes a few TLB entries instead of hundreds or thousands of
// 4 KiB ones. Freed blocks are kept, up to kLargeBlockCacheBytes, for the next allocation of a
// similar size: fresh memory costs a page fault per page and the kernel's clearing of every
// byte. Smaller blocks come from operator new as usual.

#include "sandcore/large_pages.hpp"

#include <cstddef>

namespace sandcore {

/// A huge page, bytes.
inline constexpr std::size_t kLargePageBytes = std::size_t{2} << 20;
/// Smallest block handed to huge pages (rounded up to a whole one), bytes.
inline constexpr std::size_t kSmallestLargeBlock = kLargePageBytes / 2;

/// Freed large blocks kept for reuse at most, bytes (none under AddressSanitizer).
inline constexpr std::size_t kLargeBlockCacheBytes = std::size_t{256} << 20;

/// Returns every kept block to the system (when memory is needed elsewhere).
void releaseLargeBlockCache() noexcept;
/// Bytes of the blocks kept for reuse.
std::size_t largeBlockCacheBytes() noexcept;

} // namespace sandcore
