// SPDX-License-Identifier: MIT
#pragma once
// Which cells of one grid are awake (R5): visited in their layer's next turn of the sweep. Only a
// grain whose options have widened since it last stayed put can move, so every change that can
// widen a grain's options wakes it (grid_sweep.hpp says who wakes whom), and the sweep visits
// the awake cells only. Private to sandcore.

#include "sandcore/large_pages.hpp"
#include "sandcore/vec3.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace sandcore {

class AwakeCells {
public:
    /// Per 64 cells of a row: the awake bits, and the cells that may hold a grain (set by every
    /// wakeAt: each grain that enters a cell is woken there; cleared when a visit finds the cell
    /// EMPTY or its grain leaves). Waking the cells above an emptied cell ANDs with the second,
    /// so EMPTY and INVALID cells stay asleep. Side by side, a visit or a wake that reads one
    /// word finds the other in the same cache line.
    struct Word {
        std::uint64_t awake = 0;
        std::uint64_t occupied = 0;
        std::uint64_t sleeping() const { return occupied & ~awake; } ///< cells that hold a grain, not awake
    };

    AwakeCells() = default;
    explicit AwakeCells(Int3 gridSize)
        : size_(gridSize), rowWords_((gridSize.x + 63) / 64),
          words_(std::size_t(gridSize.y) * std::size_t(gridSize.z) * std::size_t(rowWords_)),
          rowAwake_(std::size_t(gridSize.y) * std::size_t(gridSize.z), 0) {}

    Int3 size() const { return size_; }
    int rowWords() const { return rowWords_; } ///< 64-bit words per row, the last one padded
    std::size_t rowOf(int y, int z) const { return std::size_t(y) * std::size_t(size_.z) + std::size_t(z); }
    /// The word of cell x in row `row` (rowOf): the same index finds it in any array kept per word
    /// like this one's (the granular in-motion bits).
    std::size_t wordOf(std::size_t row, int x) const { return row * std::size_t(rowWords_) + std::size_t(x >> 6); }
    std::size_t wordCount() const { return words_.size(); }
    Word* words() { return words_.data(); }
    const Word* words() const { return words_.data(); }
    Word* rowWords(std::size_t row) { return words_.data() + row * std::size_t(rowWords_); }
    const Word* rowWords(std::size_t row) const { return words_.data() + row * std::size_t(rowWords_); }
    /// One flag a row, 1 when the row may hold awake bits: a sweep skips the rows without.
    std::uint8_t* rowFlags() { return rowAwake_.data(); }
    bool rowAwake(std::size_t row) const { return rowAwake_[row] != 0; }

    /// The cell is visited in its layer's next turn; it may hold a grain.
    void wakeAt(int x, int y, int z) {
        const std::size_t row = rowOf(y, z);
        Word& word = words_[wordOf(row, x)];
        const std::uint64_t bit = std::uint64_t{1} << (x & 63);
        word.awake |= bit;
        word.occupied |= bit; // every grain that enters a cell is woken there
        rowAwake_[row] = 1;
    }
    /// wakeAt, but only when the cell's occupied bit is set.
    void wakeIfOccupied(int x, int y, int z) {
        const std::size_t row = rowOf(y, z);
        Word& word = words_[wordOf(row, x)];
        const std::uint64_t bit = word.occupied & std::uint64_t{1} << (x & 63);
        word.awake |= bit;
        if (bit) rowAwake_[row] = 1;
    }
    /// Wakes the cells x0..x1 (at most 63 apart) of one row that may hold a grain, with one or
    /// two word operations. EMPTY and INVALID cells stay asleep: that is exact, since a grain
    /// that enters one of them later is woken by its move.
    void wakeSpan(std::size_t row, int x0, int x1) {
        Word* words = rowWords(row);
        const int first = x0 >> 6, last = x1 >> 6;
        std::uint64_t woken;
        if (first == last) {
            woken = (((std::uint64_t{2} << (x1 - x0)) - 1) << (x0 & 63)) & words[first].occupied;
            words[first].awake |= woken;
        } else {
            const std::uint64_t low = (~std::uint64_t{0} << (x0 & 63)) & words[first].occupied;
            const std::uint64_t high = ((std::uint64_t{2} << (x1 & 63)) - 1) & words[last].occupied;
            words[first].awake |= low;
            words[last].awake |= high;
            woken = low | high;
        }
        if (woken) rowAwake_[row] = 1;
    }
    /// The 9 cells above (x, y, z): the grains that may fall or slip into it under the classic rules.
    void wakePredecessorsOf(int x, int y, int z) {
        if (y + 1 >= size_.y) return;
        const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, size_.x - 1);
        const int z0 = std::max(z - 1, 0), z1 = std::min(z + 1, size_.z - 1);
        const std::size_t layerRow = rowOf(y + 1, 0);
        for (int zz = z0; zz <= z1; ++zz) wakeSpan(layerRow + std::size_t(zz), x0, x1);
    }
    /// Puts the row to sleep (its occupied bits stay).
    void clearRow(std::size_t row) {
        if (!rowAwake_[row]) return;
        Word* words = rowWords(row);
        for (int w = 0; w < rowWords_; ++w) words[w].awake = 0;
        rowAwake_[row] = 0;
    }
    /// Bits of every cell of a row in word w.
    std::uint64_t wholeWord(int w) const {
        const int cellsInWord = std::min(size_.x - w * 64, 64);
        return cellsInWord == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << cellsInWord) - 1;
    }
    /// Whether a row z0..z1-1 of layer y may hold awake cells, eight flags a load.
    bool anyRowAwake(int y, int z0, int z1) const {
        const std::uint8_t* flag = rowAwake_.data() + rowOf(y, z0);
        const std::uint8_t* const end = flag + (z1 - z0);
        for (; end - flag >= 8; flag += 8) {
            std::uint64_t flags;
            std::memcpy(&flags, flag, sizeof flags);
            if (flags) return true;
        }
        return std::any_of(flag, end, [](std::uint8_t f) { return f != 0; });
    }
    int awakeRowsInLayer(int y) const;
    /// Rows (of all layers) that may hold awake cells: a cheap measure of the next sweep's work.
    std::int64_t awakeRowCount() const;
    void clear(); ///< nothing awake, nothing occupied

    /// Calls visit(cell index) for every cell of layer 0 that is awake (or every cell, when not
    /// sleeping), in index order, and puts them to sleep.
    template <class Visit> void forEachInBottomLayer(bool sleeping, Visit&& visit) {
        const int sizeX = size_.x;
        for (int z = 0; z < size_.z; ++z) {
            const std::size_t row = std::size_t(z);
            if (!sleeping) {
                clearRow(row);
                for (int x = 0; x < sizeX; ++x) visit(std::uint32_t(x) + std::uint32_t(sizeX) * std::uint32_t(z));
                continue;
            }
            if (!rowAwake_[row]) continue;
            rowAwake_[row] = 0;
            Word* words = rowWords(row);
            for (int w = 0; w < rowWords_; ++w) {
                std::uint64_t bits = words[w].awake;
                words[w].awake = 0;
                for (; bits; bits &= bits - 1) {
                    const int x = w * 64 + std::countr_zero(bits);
                    visit(std::uint32_t(x) + std::uint32_t(sizeX) * std::uint32_t(z));
                }
            }
        }
    }

private:
    Int3 size_{};
    int rowWords_ = 0;
    std::vector<Word, LargePageAllocator<Word>> words_; // row = y * sizeZ + z, padded to whole words
    std::vector<std::uint8_t> rowAwake_;
};

/// Where the cells a grid empties in its top layer are woken in the grid above it (the lower
/// grid wakes the upper grid's outlet row, layer 0, at the same x and z).
class OutletWakes {
public:
    /// above: the awake cells of the grid above, or null; gridSize: the grid that empties.
    void setAbove(AwakeCells* above, Int3 gridSize) {
        above_ = above;
        size_ = gridSize;
    }
    /// While deferred, the wakes are kept until applyDeferred(), so the grid above may be swept at
    /// the same time on another thread.
    void setDeferred(bool defer) { defer_ = defer; }
    /// Cell (x, y, z) of the grid emptied.
    void emptied(int x, int y, int z) {
        if (!above_ || y != size_.y - 1) return;
        if (defer_)
            deferred_.push_back(std::uint32_t(x) + std::uint32_t(size_.x) * std::uint32_t(z));
        else
            above_->wakeAt(x, 0, z);
    }
    /// The grain in cell (x, y, z) changed its fall without leaving the cell: a grain of the grid
    /// above may rest on it across the seam and ride it (Scene::transitionGranular).
    void fallChanged(int x, int y, int z) { emptied(x, y, z); }
    void applyDeferred() {
        for (const std::uint32_t column : deferred_)
            above_->wakeAt(int(column % std::uint32_t(size_.x)), 0, int(column / std::uint32_t(size_.x)));
        deferred_.clear();
    }

private:
    AwakeCells* above_ = nullptr;
    Int3 size_{};
    bool defer_ = false;
    std::vector<std::uint32_t> deferred_; // x + sizeX * z of the outlet cells to wake
};

} // namespace sandcore
