// SPDX-License-Identifier: MIT
#include "sandcore/scenes.hpp"

#include "granular_rules.hpp"
#include "hourglass_split.hpp"
#include "threshold_dither.hpp"
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

// How deep a slide's target column must be open for a grain at rest to take it. Classic rules
// (R2): one cell for every neighbour. Granular rules (PH2): a grain on sand needs
// max(1, floor(T|e| + u)) cells, u the lower grid's fixed dither of its column and offset under
// the scene's seed; a grain on the glass needs one, which only lets it go further.
class SlideNeeds {
public:
    explicit SlideNeeds(const StepSettings& step)
        : granular_(step.physics.level == PhysicsLevel::Granular), rules_(step.physics),
          dither_(step.seed, std::uint64_t(GridLevel::Lower)) {}

    bool granular() const { return granular_; }
    int cellsDeep(int x, int z, int dx, int dz) const {
        if (!granular_) return 1;
        const int k = GranularRules::offsetIndex(dx, dz);
        const int whole = int(rules_.offset(k).thresholdQ8 >> 8);
        return std::max(1, whole + (rules_.carries(dither_, x, z, k) ? 1 : 0));
    }

private:
    bool granular_;
    GranularRules rules_;
    ThresholdDither dither_;
};

// The cells of a lower bulb (its top layer the neck) that are surely full once a grain rests in
// the neck cell (apexX, apexZ) with everything below it at rest. A grain at rest has a full cell
// under it, and every slide it could take is shut: for the slide into a neighbouring column that
// needs n open cells, one of the n cells below the grain's layer there is full, and with it all
// the cells under that one, so the n-th is (when all n lie in the bulb). Slides whose path at the
// grain's level is the glass never open (granular rules), and the longer granular slides are
// left out: fewer successors only make the count smaller. So every counted cell is full, and
// the count is a strict bound under both rule sets for the scene's seed and physics.
std::int64_t reachableBelow(const InsideMask& lower, int apexX, int apexZ, const SlideNeeds& needs) {
    const int neck = lower.size.y - 1;
    std::vector<std::uint8_t> reached(lower.inside.size(), 0);
    // The reached cells by layer, as (x, z): successors lie one or more layers down, so going down
    // layer by layer sees every reached cell before its successors.
    std::vector<std::vector<std::array<int, 2>>> byLayer(std::size_t(neck + 1));
    byLayer[std::size_t(neck)].push_back({apexX, apexZ});
    reached[lower.indexOf(apexX, neck, apexZ)] = 1;
    std::int64_t cells = 0;
    for (int y = neck; y > 0; --y)
        for (const auto [x, z] : byLayer[std::size_t(y)])
            for (int dz = -1; dz <= 1; ++dz)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int bx = x + dx, bz = z + dz;
                    if (bx < 0 || bz < 0 || bx >= lower.size.x || bz >= lower.size.z) continue;
                    const bool straightDown = dx == 0 && dz == 0;
                    if (needs.granular() && !straightDown && !lower.at(bx, y, bz)) continue;
                    const int deep = straightDown ? 1 : needs.cellsDeep(x, z, dx, dz);
                    bool open = y - deep >= 0;
                    for (int d = 1; d <= deep && open; ++d) open = lower.at(bx, y - d, bz);
                    if (!open) continue;
                    std::uint8_t& target = reached[lower.indexOf(bx, y - deep, bz)];
                    if (target) continue;
                    target = 1;
                    ++cells;
                    byLayer[std::size_t(y - deep)].push_back({bx, bz});
                }
    return cells;
}

// The sand a lower bulb takes without choking its neck (S3, W1): less than the cells
// reachableBelow counts from any neck cell all runs through, as sand that stays above the neck
// rests on a neck cell and so on all the cells counted from it. Small necks are counted from
// every cell; wide ones from those that reach fewest, found at the rim: the middle and the
// farthest cells along the four axis and four diagonal directions.
std::int64_t heapCapacity(const InsideMask& lower, const StepSettings& step) {
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
    std::vector<std::array<int, 2>> apexes;
    constexpr std::size_t kEveryCellUpTo = 64;
    if (cells.size() <= kEveryCellUpTo) apexes = cells;
    else {
        constexpr std::array<std::array<int, 2>, 8> kDirections{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}};
        auto nearCentre = [&](const std::array<int, 2>& c) { return (c[0] - cx) * (c[0] - cx) + (c[1] - cz) * (c[1] - cz); };
        apexes.push_back(*std::min_element(cells.begin(), cells.end(), [&](const auto& p, const auto& q) { return nearCentre(p) < nearCentre(q); }));
        for (const std::array<int, 2>& d : kDirections)
            apexes.push_back(*std::max_element(cells.begin(), cells.end(), [&](const auto& p, const auto& q) {
                return d[0] * p[0] + d[1] * p[1] < d[0] * q[0] + d[1] * q[1];
            }));
    }
    const SlideNeeds needs(step);
    std::int64_t fewest = INT64_MAX;
    for (const std::array<int, 2>& apex : apexes) fewest = std::min(fewest, reachableBelow(lower, apex[0], apex[1], needs));
    return fewest;
}

} // namespace

SceneShape sceneShapeOf(SceneKind kind) {
    if (kind == SceneKind::Hourglass) return {.hourglassNeck = true, .turnsOver = true, .takesBodies = false};
    return {};
}

Scene makeCanvasScene(const CanvasSettings& canvas, const StepSettings& step) {
    return Scene(sceneShapeOf(SceneKind::Canvas), CellGrid(canvas.upperSize), CellGrid(canvas.lowerSize), {}, step);
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
        capacity = heapCapacity(lower, step);
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
    return Scene(sceneShapeOf(SceneKind::Hourglass), layoutFromMask(upper), std::move(lowerLayout), std::move(fill), step);
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
    return Scene(sceneShapeOf(SceneKind::Sculpture), std::move(upper), std::move(lower), std::move(fill), step);
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
