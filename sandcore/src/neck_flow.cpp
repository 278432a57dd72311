// SPDX-License-Identifier: MIT
#include "neck_flow.hpp"

#include <algorithm>
#include <cmath>

namespace sandcore {

NeckFlow::NeckFlow(std::int64_t neckCells, double gravity) {
    area_ = double(neckCells);
    diameter_ = 2.0 * std::sqrt(area_ / M_PI);
    const auto law = [&](double diameter) { return kBeverlooC * std::sqrt(gravity) * std::pow(diameter - kBeverlooK, 2.5); };
    const double narrowestArea = M_PI * kNarrowestLawDiameter * kNarrowestLawDiameter / 4.0;
    rate_ = diameter_ >= kNarrowestLawDiameter ? law(diameter_) : area_ * law(kNarrowestLawDiameter) / narrowestArea;
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
