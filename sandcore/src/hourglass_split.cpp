// SPDX-License-Identifier: MIT
#include "hourglass_split.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace sandcore {

int findNeckLayer(const InsideMask& mask) {
    const int height = mask.size.y;
    const int first = height / 4, last = std::max(first, (3 * height - 1) / 4);
    const double middle = (height - 1) / 2.0;
    int best = -1;
    std::int64_t bestCount = 0;
    for (int y = first; y <= last; ++y) {
        const std::int64_t count = mask.countInsideLayer(y);
        if (count == 0) continue;
        const bool better = best < 0 || count < bestCount ||
                            (count == bestCount && std::abs(y - middle) < std::abs(best - middle));
        if (better) {
            best = y;
            bestCount = count;
        }
    }
    return best;
}

bool hasNeck(const InsideMask& mask, int neckLayer) {
    if (neckLayer < 0) return false;
    const std::int64_t neck = mask.countInsideLayer(neckLayer);
    std::int64_t widestBelow = 0, widestAbove = 0;
    for (int y = 0; y < neckLayer; ++y) widestBelow = std::max(widestBelow, mask.countInsideLayer(y));
    for (int y = neckLayer + 1; y < mask.size.y; ++y) widestAbove = std::max(widestAbove, mask.countInsideLayer(y));
    return neck < widestBelow && neck < widestAbove;
}

InsideMask sliceLayers(const InsideMask& mask, int fromLayer, int toLayer) {
    if (fromLayer < 0 || toLayer >= mask.size.y || fromLayer > toLayer)
        throw std::invalid_argument("layer range outside the mask");
    InsideMask slice = InsideMask::empty({mask.size.x, toLayer - fromLayer + 1, mask.size.z});
    const std::size_t layer = std::size_t(mask.size.x) * std::size_t(mask.size.z);
    std::copy_n(mask.inside.begin() + std::ptrdiff_t(layer * std::size_t(fromLayer)),
                std::ptrdiff_t(layer * std::size_t(slice.size.y)), slice.inside.begin());
    return slice;
}

} // namespace sandcore
