// SPDX-License-Identifier: MIT
#include "layout_bits.hpp"

#include <bit>

namespace sandcore {

LayoutBits::LayoutBits(const CellGrid& grid) : size_(grid.size()), open_((std::size_t(grid.cellCount()) + 63) / 64, 0) {
    const auto cells = grid.cells();
    for (std::size_t n = 0; n < cells.size(); ++n)
        open_[n >> 6] |= std::uint64_t(cells[n] != kInvalid) << (n & 63);
}

LayoutBits::LayoutBits(Int3 size) : size_(size), open_((std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z) + 63) / 64, 0) {}

bool LayoutBits::matches(const CellGrid& grid) const {
    if (grid.size() != size_) return false;
    const auto cells = grid.cells();
    for (std::size_t n = 0; n < cells.size(); ++n)
        if (open(std::uint32_t(n)) != (cells[n] != kInvalid)) return false;
    return true;
}

std::int64_t LayoutBits::openCellsOfBottomLayer() const {
    const std::uint32_t layer = std::uint32_t(size_.x) * std::uint32_t(size_.z);
    std::int64_t count = 0;
    for (std::uint32_t n = 0; n < layer; ++n) count += open(n) ? 1 : 0;
    return count;
}

void LayoutBits::writeInto(CellGrid& grid) const {
    const auto cells = grid.cells();
    // kInvalid + 1 == kEmpty: a bit selects the marker without a branch.
    static_assert(kInvalid + 1 == kEmpty);
    for (std::size_t n = 0; n < cells.size(); ++n) cells[n] = kInvalid + CellValue((open_[n >> 6] >> (n & 63)) & 1u);
}

CellGrid LayoutBits::grid() const {
    CellGrid out(size_, kInvalid);
    writeInto(out);
    return out;
}

} // namespace sandcore
