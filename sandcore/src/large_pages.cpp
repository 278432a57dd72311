#include "sandcore/large_pages.hpp"

#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace sandcore {

void* allocateLarge(std::size_t bytes) {
    if (bytes < kLargePageBytes) return ::operator new(bytes);
    const std::size_t rounded = (bytes + kLargePageBytes - 1) / kLargePageBytes * kLargePageBytes;
    void* block = std::aligned_alloc(kLargePageBytes, rounded);
    if (!block) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
    // Only advice: where the kernel has no huge pages to give, the block works as it is.
    madvise(block, rounded, MADV_HUGEPAGE);
#endif
    return block;
}

void freeLarge(void* block, std::size_t bytes) noexcept {
    if (bytes < kLargePageBytes)
        ::operator delete(block);
    else
        std::free(block);
}

} // namespace sandcore
