// SPDX-License-Identifier: MIT
#include "sandcore/mask_cleanup.hpp"

#include "layer_neighbourhood.hpp"

#include <algorithm>
#include <vector>

namespace sandcore {

std::int64_t removeNoise(InsideMask& mask, int threshold) {
    const Int3 s = mask.size;
    auto insideAt = [&](int x, int y, int z) {
        return x >= 0 && y >= 0 && z >= 0 && x < s.x && y < s.y && z < s.z && mask.at(x, y, z);
    };
    std::int64_t removedTotal = 0;
    std::vector<std::size_t> doomed;
    do {
        // Decide a whole pass on the unchanged mask, so the result does not depend on scan order.
        doomed.clear();
        for (int y = 0; y < s.y; ++y)
            for (int z = 0; z < s.z; ++z)
                for (int x = 0; x < s.x; ++x) {
                    if (!mask.at(x, y, z)) continue;
                    const int neighbours = insideAt(x - 1, y, z) + insideAt(x + 1, y, z) + insideAt(x, y - 1, z) +
                                           insideAt(x, y + 1, z) + insideAt(x, y, z - 1) + insideAt(x, y, z + 1);
                    if (neighbours <= threshold) doomed.push_back(mask.indexOf(x, y, z));
                }
        for (std::size_t i : doomed) mask.inside[i] = 0;
        removedTotal += std::int64_t(doomed.size());
    } while (!doomed.empty());
    return removedTotal;
}

std::int64_t removeSharpEdges(InsideMask& mask, int fromLayer, int toLayer) {
    const Int3 s = mask.size;
    fromLayer = std::max(fromLayer, 0);
    toLayer = std::min(toLayer, s.y - 1);
    std::int64_t removedTotal = 0;
    bool changed = true;
    while (changed) {
        changed = false;
        // Bottom-up, so a removal in one layer is seen by the layer above in the same pass.
        for (int y = fromLayer + 1; y <= toLayer; ++y)
            for (int z = 0; z < s.z; ++z)
                for (int x = 0; x < s.x; ++x) {
                    if (!mask.at(x, y, z)) continue;
                    // Supported: some cell of the 3x3 below is inside, so sand here can slip on.
                    const LayerNeighbourhood around(x, z, s.x, s.z);
                    const bool supported =
                        around.anyWithCentre([&](int dx, int dz) { return mask.at(x + dx, y - 1, z + dz); });
                    if (!supported) {
                        mask.set(x, y, z, false);
                        ++removedTotal;
                        changed = true;
                    }
                }
    }
    return removedTotal;
}

} // namespace sandcore
