// SPDX-License-Identifier: MIT
#include "awake_cells.hpp"

#include <algorithm>

namespace sandcore {

int AwakeCells::awakeRowsInLayer(int y) const {
    const auto first = rowAwake_.begin() + std::ptrdiff_t(rowOf(y, 0));
    return int(std::count(first, first + size_.z, std::uint8_t{1}));
}

std::int64_t AwakeCells::awakeRowCount() const {
    // The flags are 0 or 1: eight at a time, a multiply sums a word's bytes into its top byte.
    const std::size_t rows = rowAwake_.size(), whole = rows / 8 * 8;
    std::int64_t count = 0;
    for (std::size_t at = 0; at < whole; at += 8) {
        std::uint64_t flags;
        std::memcpy(&flags, rowAwake_.data() + at, 8);
        count += std::int64_t((flags * 0x0101010101010101ull) >> 56);
    }
    return count + std::count(rowAwake_.begin() + std::ptrdiff_t(whole), rowAwake_.end(), std::uint8_t{1});
}

void AwakeCells::clear() {
    std::fill(words_.begin(), words_.end(), Word{});
    std::fill(rowAwake_.begin(), rowAwake_.end(), 0);
}

} // namespace sandcore
