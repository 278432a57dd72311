#pragma once
// Which of 8 consecutive cells are EMPTY, as 8 bits. The granular slides and wakes read 7x7
// windows of cells a row of 8 at a time; on x86-64 (SSE2 is part of it) a row is two compares of
// 4 cells and one mask, elsewhere 8 compares. Private to sandcore.

#include "sandcore/cell_grid.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sandcore {

/// Bit i is set when cells[i] is EMPTY, for i = 0..7; cells[0..7] must be readable.
inline unsigned emptyBitsOf8(const CellValue* cells) {
#if defined(__SSE2__)
    const __m128i empty = _mm_set1_epi32(kEmpty);
    const __m128i low = _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(cells)), empty);
    const __m128i high = _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(cells + 4)), empty);
    // Each compare gives 0 or -1 per cell: packed to bytes with sign saturation they stay 0 or -1.
    const __m128i bytes = _mm_packs_epi16(_mm_packs_epi32(low, high), _mm_setzero_si128());
    return unsigned(_mm_movemask_epi8(bytes));
#else
    unsigned bits = 0;
    for (int i = 0; i < 8; ++i) bits |= unsigned(cells[i] == kEmpty) << i;
    return bits;
#endif
}

} // namespace sandcore
