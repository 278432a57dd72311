// SPDX-License-Identifier: MIT
#pragma once
// Which entries of a buffer mirrored on the GPU changed, one bit per entry: marking costs a bit,
// and the marked entries come back as ascending runs without sorting them (a step lists the
// grains it moved in no particular order, ~39,000 of them at a million grains).

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace sandglass {

class IndexRuns {
public:
    /// Room for entries 0..count-1, none marked.
    void resize(std::uint32_t count) {
        words_.assign((std::size_t(count) + 63) / 64, 0);
        clearBounds();
    }
    std::uint32_t capacity() const { return std::uint32_t(words_.size() * 64); } ///< entries it can mark
    void mark(std::uint32_t index) {
        const std::uint32_t word = index >> 6;
        words_[word] |= std::uint64_t{1} << (index & 63u);
        low_ = std::min(low_, word);
        high_ = std::max(high_, word);
    }
    bool empty() const { return low_ > high_; } ///< nothing marked

    /// Calls run(first, end) for each run of marked entries [first, end), ascending, joining two
    /// runs at most maxGap unmarked entries apart; clears every mark.
    template <class Run> void take(std::uint32_t maxGap, Run&& run) {
        if (empty()) return;
        bool open = false;
        std::uint32_t first = 0, end = 0;
        for (std::uint32_t word = low_; word <= high_; ++word) {
            std::uint64_t bits = words_[word];
            words_[word] = 0;
            while (bits != 0) {
                const int start = std::countr_zero(bits);
                const int length = std::countr_one(bits >> start);
                const std::uint32_t from = word * 64 + std::uint32_t(start), to = from + std::uint32_t(length);
                if (open && from <= end + maxGap) {
                    end = to;
                } else {
                    if (open) run(first, end);
                    first = from;
                    end = to;
                    open = true;
                }
                bits = start + length >= 64 ? 0 : bits & ~(((std::uint64_t{1} << length) - 1) << start);
            }
        }
        if (open) run(first, end);
        clearBounds();
    }

private:
    void clearBounds() {
        low_ = UINT32_MAX;
        high_ = 0;
    }
    std::vector<std::uint64_t> words_;
    std::uint32_t low_ = UINT32_MAX, high_ = 0; // the words with marks lie within these
};

} // namespace sandglass
