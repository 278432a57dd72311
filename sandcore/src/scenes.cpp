// SPDX-License-Identifier: MIT
#include "sandcore/scenes.hpp"

#include "hourglass_split.hpp"
#include "sandcore/mask_cleanup.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sandcore {

namespace {

// Cells outside the shape are INVALID: no grain ever leaves the vessel.
CellGrid layoutFromMask(const InsideMask& mask) {
    CellGrid grid(mask.size, kInvalid);
    for (std::size_t n = 0; n < mask.inside.size(); ++n)
        if (mask.inside[n]) grid[std::uint32_t(n)] = kEmpty;
    return grid;
}

void requireInside(const InsideMask& mask, const char* what) {
    if (mask.countInside() == 0) throw std::invalid_argument(std::string(what) + " has no inside cells");
}

// The bulb's cells from the outlet up, whole layers at a time, until fillFraction of them are taken.
std::vector<std::uint32_t> fillFromBottom(const InsideMask& mask, float fillFraction) {
    if (!(fillFraction > 0.0f && fillFraction <= 1.0f))
        throw std::invalid_argument("fill fraction must lie in (0, 1]");
    const auto wanted = std::int64_t(double(fillFraction) * double(mask.countInside()) + 0.5);
    std::vector<std::uint32_t> cells;
    for (int y = 0; y < mask.size.y && std::int64_t(cells.size()) < wanted; ++y)
        for (int z = 0; z < mask.size.z; ++z)
            for (int x = 0; x < mask.size.x; ++x)
                if (mask.at(x, y, z)) cells.push_back(std::uint32_t(mask.indexOf(x, y, z)));
    return cells;
}

InsideMask mirroredInY(const InsideMask& mask) {
    InsideMask out = InsideMask::empty(mask.size);
    for (int y = 0; y < mask.size.y; ++y)
        for (int z = 0; z < mask.size.z; ++z)
            for (int x = 0; x < mask.size.x; ++x) out.set(x, mask.size.y - 1 - y, z, mask.at(x, y, z));
    return out;
}

// The mask without its empty bottom and top layers, so a plain vessel's floor is its outlet.
InsideMask trimmedToInsideLayers(const InsideMask& mask) {
    int bottom = 0, top = mask.size.y - 1;
    while (mask.countInsideLayer(bottom) == 0) ++bottom;
    while (mask.countInsideLayer(top) == 0) --top;
    return sliceLayers(mask, bottom, top);
}

// The bulb above the neck layer of `vessel`, carved (S3) so that sand anywhere in it finds a way
// down. The neck layer drains only where a cell of the layer below lies under it: a neck cell over
// the lower bulb's shoulder would hold its grains for ever.
InsideMask drainedBulbAbove(const InsideMask& vessel, int neck) {
    InsideMask carved = vessel;
    removeSharpEdges(carved, neck - 1, vessel.size.y - 1);
    return sliceLayers(carved, neck, vessel.size.y - 1);
}

// The cells of a lower bulb (its top layer the neck) that a grain can reach from the neck cell
// (apexX, apexZ): one layer down and at most one cell aside in x and z per step (R2's
// successors), through the bulb's own cells. Under the granular rules (PH2) a move counts only
// when the cell beside the grain in its own layer lies in the bulb too: a slide needs its path
// open, so a grain under the bulb's roof, which narrows up to the neck, cannot slide outwards.
// This is no strict bound there: a slide of one column along a diagonal may need two open cells
// below (its threshold sqrt(2) T is above 1 from about 30 degrees), so a few grains may rest in
// the neck of a bulb the sand fills to the top (docs/shapes.md gives how many).
std::int64_t reachableBelow(const InsideMask& lower, int apexX, int apexZ, PhysicsLevel rules) {
    const bool granular = rules == PhysicsLevel::Granular;
    const int neck = lower.size.y - 1;
    std::vector<std::uint32_t> layer{std::uint32_t(lower.indexOf(apexX, neck, apexZ))}, next;
    std::vector<std::uint8_t> reached(lower.inside.size(), 0);
    std::int64_t cells = 0;
    for (int y = neck; y > 0 && !layer.empty(); --y) {
        next.clear();
        for (std::uint32_t n : layer) {
            const int x = int(n % std::uint32_t(lower.size.x)), z = int((n / std::uint32_t(lower.size.x)) % std::uint32_t(lower.size.z));
            for (int dz = -1; dz <= 1; ++dz)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int bx = x + dx, bz = z + dz;
                    if (bx < 0 || bz < 0 || bx >= lower.size.x || bz >= lower.size.z || !lower.at(bx, y - 1, bz)) continue;
                    if (granular && !lower.at(bx, y, bz)) continue;
                    const std::size_t m = lower.indexOf(bx, y - 1, bz);
                    if (!reached[m]) {
                        reached[m] = 1;
                        next.push_back(std::uint32_t(m));
                    }
                }
        }
        cells += std::int64_t(next.size());
        layer.swap(next);
    }
    return cells;
}

// The sand a lower bulb takes without choking its neck (S3, W1). A grain rests in a neck cell
// only when the 9 cells below it are full, and so on down: only when every cell a grain can
// reach from that neck cell is full. Less sand than the fewest cells reachable from any neck cell
// therefore all runs through (strictly so under the classic rules; see reachableBelow). The
// fewest are found at the neck's rim: its middle and its farthest cells along the four axis and
// four diagonal directions stand for the rest.
std::int64_t heapCapacity(const InsideMask& lower, PhysicsLevel rules) {
    const int neck = lower.size.y - 1;
    std::vector<std::array<int, 2>> cells;
    double cx = 0.0, cz = 0.0;
    for (int z = 0; z < lower.size.z; ++z)
        for (int x = 0; x < lower.size.x; ++x)
            if (lower.at(x, neck, z)) {
                cells.push_back({x, z});
                cx += x, cz += z;
            }
    if (cells.empty()) return 0;
    cx /= double(cells.size());
    cz /= double(cells.size());
    constexpr std::array<std::array<int, 2>, 8> kDirections{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}};
    std::vector<std::array<int, 2>> apexes;
    // The middle: the neck cell nearest the neck's centre.
    auto nearCentre = [&](const std::array<int, 2>& c) { return (c[0] - cx) * (c[0] - cx) + (c[1] - cz) * (c[1] - cz); };
    apexes.push_back(*std::min_element(cells.begin(), cells.end(), [&](const auto& p, const auto& q) { return nearCentre(p) < nearCentre(q); }));
    for (const std::array<int, 2>& d : kDirections)
        apexes.push_back(*std::max_element(cells.begin(), cells.end(), [&](const auto& p, const auto& q) {
            return d[0] * p[0] + d[1] * p[1] < d[0] * q[0] + d[1] * q[1];
        }));
    std::int64_t fewest = INT64_MAX;
    for (const std::array<int, 2>& apex : apexes) fewest = std::min(fewest, reachableBelow(lower, apex[0], apex[1], rules));
    return fewest;
}

} // namespace

Scene makeCanvasScene(const CanvasSettings& canvas, const StepSettings& step) {
    return Scene(SceneKind::Canvas, CellGrid(canvas.upperSize), CellGrid(canvas.lowerSize), {}, step);
}

int defaultSandboxBedDepth(const CanvasSettings& canvas) { return std::max(1, canvas.lowerSize.y / 3); }

Scene makeSandboxScene(const CanvasSettings& canvas, int bedDepth, const StepSettings& step) {
    Scene scene = makeCanvasScene(canvas, step);
    const CellGrid& box = scene.grid(GridLevel::Lower);
    if (bedDepth < 1 || bedDepth > box.size().y)
        throw std::invalid_argument("the sand bed must be 1.." + std::to_string(box.size().y) + " layers deep, got " +
                                    std::to_string(bedDepth));
    // Full layers lie still under every rule set: the bed is at rest from the first step.
    for (std::uint32_t n = 0; n < box.layerSize() * std::uint32_t(bedDepth); ++n) scene.addGrain(GridLevel::Lower, n);
    return scene;
}

Scene makeHourglassScene(const InsideMask& untrimmed, const HourglassSettings& hourglass, const StepSettings& step) {
    return makeHourglassScene(untrimmed, InsideMask{}, hourglass, step);
}

Scene makeHourglassScene(const InsideMask& untrimmed, const InsideMask& initialSand, const HourglassSettings& hourglass,
                         const StepSettings& step) {
    requireInside(untrimmed, "the vessel");
    const bool modelled = !initialSand.inside.empty();
    if (modelled && !(initialSand.size == untrimmed.size))
        throw std::invalid_argument("the initial sand's mask differs in size from the vessel's");
    int bottom = 0;
    while (untrimmed.countInsideLayer(bottom) == 0) ++bottom;
    const InsideMask vessel = trimmedToInsideLayers(untrimmed);
    const int top = vessel.size.y - 1;
    const int neck = findNeckLayer(vessel);
    const bool split = hasNeck(vessel, neck);
    InsideMask upper = split ? sliceLayers(vessel, neck, top) : vessel;
    // The modelled sand of the upper bulb, counted before carving (and with the cells it shares
    // with the glass's wall): the hourglass holds as much sand as was modelled.
    const int firstLayer = bottom + (split ? neck : 0);
    std::int64_t modelledCells = 0;
    if (modelled)
        for (int y = 0; y < upper.size.y; ++y)
            for (int z = 0; z < upper.size.z; ++z)
                for (int x = 0; x < upper.size.x; ++x) modelledCells += initialSand.at(x, y + firstLayer, z) ? 1 : 0;
    if (hourglass.drainCompletely) {
        if (split) upper = drainedBulbAbove(vessel, neck);
        else removeSharpEdges(upper, 0, upper.size.y - 1);
    }
    requireInside(upper, "the upper bulb");
    CellGrid lowerLayout(vessel.size, kEmpty);
    std::int64_t capacity = INT64_MAX;
    if (split) {
        // Turned over (T1), the lower bulb drains too: carve it as the upper bulb it then becomes.
        const InsideMask lower = hourglass.drainCompletely ? mirroredInY(drainedBulbAbove(mirroredInY(vessel), top - neck))
                                                           : sliceLayers(vessel, 0, neck);
        capacity = heapCapacity(lower, step.physics.level);
        lowerLayout = layoutFromMask(lower);
    }
    std::vector<std::uint32_t> fill;
    if (modelledCells > 0) {
        // The modelled sand where the carved bulb still has it; what carving took is poured in
        // from the bottom up, so the hourglass holds as much sand as was modelled.
        std::vector<std::uint8_t> taken(upper.inside.size(), 0);
        for (int y = 0; y < upper.size.y; ++y)
            for (int z = 0; z < upper.size.z; ++z)
                for (int x = 0; x < upper.size.x; ++x)
                    if (upper.at(x, y, z) && initialSand.at(x, y + firstLayer, z)) {
                        fill.push_back(std::uint32_t(upper.indexOf(x, y, z)));
                        taken[fill.back()] = 1;
                    }
        for (std::uint32_t cell : fillFromBottom(upper, 1.0f)) {
            if (std::int64_t(fill.size()) >= modelledCells) break;
            if (!taken[cell]) fill.push_back(cell);
        }
        std::sort(fill.begin(), fill.end());
    }
    if (fill.empty()) fill = fillFromBottom(upper, hourglass.fillFraction);
    // No more sand than the lower bulb's heap takes, so all of it runs through (W1, S3).
    if (hourglass.fitLowerBulb && std::int64_t(fill.size()) > capacity) {
        fill = fillFromBottom(upper, 1.0f);
        fill.resize(std::size_t(capacity));
        std::sort(fill.begin(), fill.end());
    }
    return Scene(SceneKind::Hourglass, layoutFromMask(upper), std::move(lowerLayout), std::move(fill), step);
}

Scene makeSculptureScene(const InsideMask& model, const StepSettings& step) {
    return makeSculptureScene(model, InsideMask{}, step);
}

Scene makeSculptureScene(const InsideMask& model, const InsideMask& obstacles, const StepSettings& step) {
    requireInside(model, "the model");
    if (!obstacles.inside.empty() && !(obstacles.size == model.size))
        throw std::invalid_argument("the obstacles' mask differs in size from the model's");
    const Int3 m = model.size;
    const SceneGridSizes sizes = sceneGridSizes(SceneKind::Sculpture, m);
    CellGrid upper(sizes.upper, kEmpty);
    CellGrid lower(sizes.lower, kEmpty);
    // The model in the middle of the upper grid.
    const int offsetX = (sizes.upper.x - m.x) / 2, offsetZ = (sizes.upper.z - m.z) / 2;
    std::vector<std::uint32_t> fill;
    for (int y = 0; y < m.y; ++y)
        for (int z = 0; z < m.z; ++z)
            for (int x = 0; x < m.x; ++x)
                if (model.at(x, y, z)) fill.push_back(upper.index(x + offsetX, y, z + offsetZ));
                else if (!obstacles.inside.empty() && obstacles.at(x, y, z))
                    upper[upper.index(x + offsetX, y, z + offsetZ)] = kInvalid;
    return Scene(SceneKind::Sculpture, std::move(upper), std::move(lower), std::move(fill), step);
}

Int3 maskOriginInScene(SceneKind kind, const InsideMask& mask) {
    requireInside(mask, "the mask");
    if (kind == SceneKind::Hourglass) {
        int bottom = 0;
        while (mask.countInsideLayer(bottom) == 0) ++bottom;
        const InsideMask vessel = trimmedToInsideLayers(mask);
        // Split at the neck, world height is the trimmed mask's; without a neck the vessel is the
        // upper grid over a lower box of its own height (the shared row counted once).
        const bool split = hasNeck(vessel, findNeckLayer(vessel));
        return {0, -bottom + (split ? 0 : vessel.size.y - 1), 0};
    }
    if (kind == SceneKind::Sculpture) {
        const SceneGridSizes sizes = sceneGridSizes(SceneKind::Sculpture, mask.size);
        return {(sizes.upper.x - mask.size.x) / 2, sizes.lower.y - 1, (sizes.upper.z - mask.size.z) / 2};
    }
    throw std::invalid_argument("the canvas is built from no mask");
}

std::uint32_t pourCell(const Scene& scene) {
    const CellGrid& upper = scene.grid(GridLevel::Upper);
    const Int3 s = upper.size();
    return upper.index(s.x / 2, s.y - 1, s.z / 2);
}

} // namespace sandcore
