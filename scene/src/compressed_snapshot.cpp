// SPDX-License-Identifier: MIT
#include "scene/compressed_snapshot.hpp"

#include "byte_codec.hpp"
#include "compression.hpp"
#include "snapshot_codec.hpp"

#include <algorithm>

namespace sandglass {

using sandcore::CellBox;
using sandcore::GridLevel;

namespace {

// Undo snapshots are taken when a stroke begins, so speed matters more than the last percent.
constexpr int kUndoCompressionLevel = 1;

void writeBoxes(ByteWriter& out, const std::vector<CellBox>& boxes) {
    out.put<std::uint64_t>(boxes.size());
    for (const CellBox& box : boxes) out.put(box);
}

std::vector<CellBox> readBoxes(ByteReader& in) {
    const auto count = in.get<std::uint64_t>("obstacles");
    if (count > in.remaining() / sizeof(CellBox)) throw FormatError("obstacles: the data ends early");
    std::vector<CellBox> boxes;
    for (std::uint64_t i = 0; i < count; ++i) boxes.push_back(in.get<CellBox>("obstacles"));
    return boxes;
}

// Scene's rule for its live cells: the layout, obstacles INVALID (clipped to the grid), grains by id.
void rebuildGrid(sandcore::CellGrid& grid, const std::vector<CellBox>& obstacles) {
    const sandcore::Int3 s = grid.size();
    for (const CellBox& box : obstacles)
        for (int y = std::max(box.min.y, 0); y < std::min(box.max.y, s.y); ++y)
            for (int z = std::max(box.min.z, 0); z < std::min(box.max.z, s.z); ++z)
                for (int x = std::max(box.min.x, 0); x < std::min(box.max.x, s.x); ++x) grid[grid.index(x, y, z)] = sandcore::kInvalid;
}

void writeBodies(ByteWriter& out, const std::vector<sandcore::MovingBody>& bodies) {
    out.put<std::uint64_t>(bodies.size());
    for (const sandcore::MovingBody& body : bodies) {
        out.put(body.position);
        out.put<std::int32_t>(body.quarterTurns);
        out.put(body.shape.size);
        out.putArray(std::span<const std::uint8_t>(body.shape.inside.data(), body.shape.inside.size()));
    }
}

std::vector<sandcore::MovingBody> readBodies(ByteReader& in) {
    const auto count = in.get<std::uint64_t>("bodies");
    if (count > in.remaining()) throw FormatError("bodies: the data ends early");
    std::vector<sandcore::MovingBody> bodies(static_cast<std::size_t>(count));
    for (sandcore::MovingBody& body : bodies) {
        body.position = in.get<sandcore::Int3>("bodies");
        body.quarterTurns = in.get<std::int32_t>("bodies") & 3;
        body.shape = sandcore::InsideMask::empty(in.get<sandcore::Int3>("bodies"));
        in.getArrayInto("bodies", std::span<std::uint8_t>(body.shape.inside.data(), body.shape.inside.size()));
    }
    return bodies;
}

// A body's cells are INVALID where it stands (Scene::bodyCells), within the grid.
void blockBodies(sandcore::CellGrid& grid, const std::vector<sandcore::MovingBody>& bodies) {
    for (const sandcore::MovingBody& body : bodies)
        for (const sandcore::Int3 offset : sandcore::bodyOffsets(body.shape, body.quarterTurns)) {
            const sandcore::Int3 c{body.position.x + offset.x, body.position.y + offset.y, body.position.z + offset.z};
            if (!grid.contains(c.x, c.y, c.z)) throw FormatError("a body reaches outside its grid");
            grid[grid.index(c)] = sandcore::kInvalid;
        }
}

} // namespace

CompressedSnapshot::CompressedSnapshot(const sandcore::Scene& scene) {
    ByteWriter out;
    writeGrains(out, scene);
    out.put<std::uint32_t>(scene.nextIdentity());
    out.put(scene.counters());
    writeBoxes(out, scene.obstacles(GridLevel::Upper));
    writeBoxes(out, scene.obstacles(GridLevel::Lower));
    writeBodies(out, scene.bodies());
    rawBytes_ = out.bytes().size();
    compressed_ = compressBytes(out.bytes(), kUndoCompressionLevel);
}

sandcore::SceneSnapshot CompressedSnapshot::expand(const sandcore::Scene& scene) const {
    const std::vector<std::uint8_t> raw = decompressBytes(compressed_, rawBytes_);
    ByteReader in(raw);
    sandcore::GrainStore g = readGrains(in);
    sandcore::SceneSnapshot s{scene.layout(GridLevel::Upper), scene.layout(GridLevel::Lower), std::move(g), 0, {}, {}, {}, false, {}};
    s.nextIdentity = in.get<std::uint32_t>("next identity");
    s.counters = in.get<sandcore::SceneCounters>("counters");
    s.upperObstacles = readBoxes(in);
    s.lowerObstacles = readBoxes(in);
    rebuildGrid(s.upper, s.upperObstacles);
    rebuildGrid(s.lower, s.lowerObstacles);
    s.bodies = readBodies(in);
    blockBodies(s.lower, s.bodies);
    for (std::uint32_t id = 0; id < s.grains.size(); ++id) {
        sandcore::CellGrid& grid = s.grains.level[id] == GridLevel::Upper ? s.upper : s.lower;
        if (s.grains.place[id].cell >= grid.cellCount()) throw FormatError("a grain lies outside its grid");
        grid[s.grains.place[id].cell] = sandcore::CellValue(id);
    }
    return s;
}

} // namespace sandglass
