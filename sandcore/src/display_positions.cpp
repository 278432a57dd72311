// SPDX-License-Identifier: MIT
#include "sandcore/display_positions.hpp"

#include "sandcore/counter_random.hpp"

namespace sandcore {

Vec3 jitterOffset(std::uint32_t identity, float jitter) {
    const std::uint64_t r = mix64(std::uint64_t(identity) * 0x9e3779b97f4a7c15ull + 0x2545f4914f6cdd1dull);
    // Three 21-bit fields of one hash give the three axes.
    auto axis = [&](int shift) { return (float((r >> shift) & 0x1fffff) * (1.0f / float(0x1fffff)) - 0.5f) * jitter; };
    return {axis(0), axis(21), axis(42)};
}

namespace {
// World point of a cell offset by (dx, dy, dz) cells plus a jitter, computed in one fixed order
// so that a resting grain always lands on exactly the same float values.
Vec3 pointOf(const Int3& world, float fx, float fy, float fz, const Vec3& jitter, float cellSize) {
    return {(float(world.x) + 0.5f + jitter.x + fx) * cellSize, (float(world.y) + 0.5f + jitter.y + fy) * cellSize,
            (float(world.z) + 0.5f + jitter.z + fz) * cellSize};
}

Int3 worldCell(const Scene& scene, GridLevel level, std::uint32_t cell) {
    const Int3 c = scene.grid(level).coordinate(cell);
    const Int3 o = scene.gridOrigin(level);
    return {c.x + o.x, c.y + o.y, c.z + o.z};
}
} // namespace

Vec3 cellDisplayPoint(const Scene& scene, GridLevel level, std::uint32_t cell, std::uint32_t identity,
                      const DisplaySettings& display) {
    return pointOf(worldCell(scene, level, cell), 0.0f, 0.0f, 0.0f, jitterOffset(identity, display.jitter),
                   display.cellSize);
}

Vec3 grainDisplayPosition(const Scene& scene, std::uint32_t id, float stepFraction, const DisplaySettings& display) {
    const GrainStore& grains = scene.grains();
    const Int3 world = worldCell(scene, grains.level[id], grains.place[id].cell);
    const Vec3 jitter = jitterOffset(grains.identity[id], display.jitter);
    const bool gliding = grains.place[id].movedAtStep == scene.counters().stepsDone && stepFraction < 1.0f;
    if (!gliding || grains.place[id].cameFrom == kNoMove) return pointOf(world, 0.0f, 0.0f, 0.0f, jitter, display.cellSize);
    const float remaining = 1.0f - stepFraction; // share of the way still ahead
    const MoveCode from = grains.place[id].cameFrom;
    return pointOf(world, remaining * float(moveDx(from)), remaining * float(moveDy(from)),
                   remaining * float(moveDz(from)), jitter, display.cellSize);
}

void writeDisplayPositions(const Scene& scene, float stepFraction, const DisplaySettings& display,
                           std::span<Vec3> out) {
    const std::uint32_t count = scene.grains().size();
    for (std::uint32_t id = 0; id < count; ++id) out[id] = grainDisplayPosition(scene, id, stepFraction, display);
}

void sceneBounds(const Scene& scene, const DisplaySettings& display, Vec3& minCorner, Vec3& maxCorner) {
    const Int3 lower = scene.grid(GridLevel::Lower).size();
    const Int3 upper = scene.grid(GridLevel::Upper).size();
    const int top = scene.gridOrigin(GridLevel::Upper).y + upper.y;
    minCorner = {0.0f, 0.0f, 0.0f};
    maxCorner = {float(lower.x) * display.cellSize, float(top) * display.cellSize, float(lower.z) * display.cellSize};
}

} // namespace sandcore
