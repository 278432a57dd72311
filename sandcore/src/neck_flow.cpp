// SPDX-License-Identifier: MIT
#include "neck_flow.hpp"

#include <algorithm>
#include <cmath>

namespace sandcore {

NeckFlow::NeckFlow(std::int64_t neckCells, double gravity) {
    area_ = double(neckCells);
    diameter_ = 2.0 * std::sqrt(area_ / M_PI);
    rate_ = kBeverlooC * std::sqrt(gravity) * std::pow(std::max(diameter_ - kBeverlooK, 0.0), 2.5);
    rateQ32_ = std::uint64_t(std::llround(rate_ * 4294967296.0));
    const double exitCellsPerStep = area_ > 0 ? std::max(1.0, kStreamCells * rate_ / area_) : 1.0;
    exitSpeed_ = std::uint32_t(std::lround(exitCellsPerStep * double(kFlowSpeed)));
}

std::int64_t NeckFlow::allowance(std::uint64_t step) const {
    // floor(n * rate) in integers, split so no product overflows 64 bits.
    const std::uint64_t whole = rateQ32_ >> 32, fraction = rateQ32_ & 0xffffffffu;
    const auto upTo = [&](std::uint64_t n) {
        return std::int64_t(n * whole + (n >> 32) * fraction + (((n & 0xffffffffu) * fraction) >> 32));
    };
    return upTo(step) - upTo(step - 1);
}

} // namespace sandcore
