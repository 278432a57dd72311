// SPDX-License-Identifier: MIT
#include "sandcore/up_axis.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sandcore {

const char* upAxisName(UpAxis axis) {
    switch (axis) {
    case UpAxis::PlusX: return "+x";
    case UpAxis::MinusX: return "-x";
    case UpAxis::PlusY: return "+y";
    case UpAxis::MinusY: return "-y";
    case UpAxis::PlusZ: return "+z";
    case UpAxis::MinusZ: return "-z";
    }
    return "+y";
}

std::optional<UpAxis> parseUpAxis(std::string_view name) {
    for (UpAxis axis : {UpAxis::PlusX, UpAxis::MinusX, UpAxis::PlusY, UpAxis::MinusY, UpAxis::PlusZ, UpAxis::MinusZ})
        if (name == upAxisName(axis) || (name.size() == 1 && name == upAxisName(axis) + 1 && upAxisName(axis)[0] == '+'))
            return axis;
    return std::nullopt;
}

AxisTurn axisTurnFor(UpAxis up) {
    switch (up) {
    case UpAxis::PlusY: return {{0, 1, 2}, {1, 1, 1}};
    case UpAxis::MinusY: return {{0, 1, 2}, {1, -1, -1}};  // half turn about x
    case UpAxis::PlusZ: return {{0, 2, 1}, {1, 1, -1}};   // quarter turn about x
    case UpAxis::MinusZ: return {{0, 2, 1}, {1, -1, 1}};
    case UpAxis::PlusX: return {{1, 0, 2}, {-1, 1, 1}};   // quarter turn about z
    case UpAxis::MinusX: return {{1, 0, 2}, {1, -1, 1}};
    }
    return {{0, 1, 2}, {1, 1, 1}};
}

InsideMask turnToUp(const InsideMask& mask, UpAxis up) {
    if (up == UpAxis::PlusY) return mask;
    const AxisTurn turn = axisTurnFor(up);
    const int old[3] = {mask.size.x, mask.size.y, mask.size.z};
    InsideMask out = InsideMask::empty({old[turn.source[0]], old[turn.source[1]], old[turn.source[2]]});
    const int size[3] = {out.size.x, out.size.y, out.size.z};
    int p[3];
    for (p[1] = 0; p[1] < size[1]; ++p[1])
        for (p[2] = 0; p[2] < size[2]; ++p[2])
            for (p[0] = 0; p[0] < size[0]; ++p[0]) {
                int q[3];
                for (int a = 0; a < 3; ++a) q[turn.source[a]] = turn.sign[a] > 0 ? p[a] : size[a] - 1 - p[a];
                out.inside[out.indexOf(p[0], p[1], p[2])] = mask.inside[mask.indexOf(q[0], q[1], q[2])];
            }
    return out;
}

NeckProfile neckAlong(const InsideMask& mask, int axis) {
    const int size[3] = {mask.size.x, mask.size.y, mask.size.z};
    std::vector<std::int64_t> area(std::size_t(size[axis]), 0);
    for (int y = 0; y < mask.size.y; ++y)
        for (int z = 0; z < mask.size.z; ++z)
            for (int x = 0; x < mask.size.x; ++x)
                if (mask.at(x, y, z)) ++area[std::size_t(axis == 0 ? x : axis == 1 ? y : z)];
    return neckOfAreas(area);
}

NeckProfile neckOfAreas(const std::vector<std::int64_t>& area) {
    const int length = int(area.size());
    NeckProfile profile;
    int low = 0, high = length - 1;
    while (low <= high && area[std::size_t(low)] == 0) ++low;
    while (high >= low && area[std::size_t(high)] == 0) --high;
    if (high - low < 4) return profile;
    const int span = high - low + 1;
    const int first = low + span / 4, last = low + (3 * span - 1) / 4;
    const double middle = (low + high) / 2.0;
    for (int i = first; i <= last; ++i) {
        const std::int64_t a = area[std::size_t(i)];
        if (a == 0) continue;
        const std::int64_t best = profile.neckLayer < 0 ? 0 : area[std::size_t(profile.neckLayer)];
        if (profile.neckLayer < 0 || a < best ||
            (a == best && std::abs(i - middle) < std::abs(profile.neckLayer - middle)))
            profile.neckLayer = i;
    }
    if (profile.neckLayer < 0) return profile;
    const std::int64_t neck = area[std::size_t(profile.neckLayer)];
    const std::int64_t below = *std::max_element(area.begin() + low, area.begin() + profile.neckLayer + 1);
    const std::int64_t above = *std::max_element(area.begin() + profile.neckLayer, area.begin() + high + 1);
    profile.hasNeck = neck < below && neck < above;
    profile.ratio = double(neck) / double(std::min(below, above));
    return profile;
}

UpAxis findUpAxis(const InsideMask& mask) {
    const UpAxis plus[3] = {UpAxis::PlusX, UpAxis::PlusY, UpAxis::PlusZ};
    int bestAxis = -1;
    double bestRatio = 1.0;
    for (int axis : {1, 0, 2}) { // y first: ties keep the model's own up
        const NeckProfile profile = neckAlong(mask, axis);
        if (profile.hasNeck && (bestAxis < 0 || profile.ratio < bestRatio)) {
            bestAxis = axis;
            bestRatio = profile.ratio;
        }
    }
    return bestAxis < 0 ? UpAxis::PlusY : plus[bestAxis];
}

} // namespace sandcore
