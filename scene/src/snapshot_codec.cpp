// SPDX-License-Identifier: MIT
#include "snapshot_codec.hpp"

#include <cstdlib>
#include <string>

namespace sandglass {

using sandcore::CellBox;
using sandcore::CellGrid;
using sandcore::GridLevel;
using sandcore::Int3;

namespace {

// Obstacles a grid may list: each is a box the user placed, so far fewer than this.
constexpr std::uint64_t kMaxObstacles = std::uint64_t{1} << 20;

void writeSize(ByteWriter& out, Int3 size) {
    out.put<std::int32_t>(size.x);
    out.put<std::int32_t>(size.y);
    out.put<std::int32_t>(size.z);
}

Int3 readSize(ByteReader& in, const char* what) {
    Int3 size;
    size.x = in.get<std::int32_t>(what);
    size.y = in.get<std::int32_t>(what);
    size.z = in.get<std::int32_t>(what);
    try {
        sandcore::validateGridSize(size);
    } catch (const std::invalid_argument& e) {
        throw FormatError(std::string(what) + ": " + e.what());
    }
    return size;
}

void writeBoxes(ByteWriter& out, const std::vector<CellBox>& boxes) {
    out.put<std::uint64_t>(boxes.size());
    for (const CellBox& box : boxes)
        for (int v : {box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z}) out.put<std::int32_t>(v);
}

std::vector<CellBox> readBoxes(ByteReader& in, const char* what) {
    const auto count = in.get<std::uint64_t>(what);
    if (count > kMaxObstacles || count * 24 > in.remaining())
        throw FormatError(std::string(what) + ": " + std::to_string(count) + " obstacles cannot be right");
    std::vector<CellBox> boxes(static_cast<std::size_t>(count));
    for (CellBox& box : boxes) {
        box.min = {in.get<std::int32_t>(what), in.get<std::int32_t>(what), in.get<std::int32_t>(what)};
        box.max = {in.get<std::int32_t>(what), in.get<std::int32_t>(what), in.get<std::int32_t>(what)};
    }
    return boxes;
}

CellGrid readGrid(ByteReader& in, const char* sizeWhat, const char* cellsWhat) {
    const Int3 size = readSize(in, sizeWhat);
    const std::uint64_t cells = std::uint64_t(size.x) * std::uint64_t(size.y) * std::uint64_t(size.z);
    // Checked before CellGrid allocates: the cells must be in the input.
    if (cells > in.remaining() / sizeof(sandcore::CellValue)) throw FormatError(std::string(cellsWhat) + ": the data ends early");
    CellGrid grid(size);
    in.getArrayInto<sandcore::CellValue>(cellsWhat, grid.cells());
    return grid;
}

} // namespace

std::size_t encodedSnapshotBytes(const sandcore::Scene& scene) {
    const std::size_t grains = scene.grains().size();
    return 2 * (12 + 8) + scene.grid(GridLevel::Upper).cells().size_bytes() +
           scene.grid(GridLevel::Lower).cells().size_bytes() + 6 * 8 + grains * 22 + 4 + 5 * 8 + 2 * 8 +
           (scene.obstacles(GridLevel::Upper).size() + scene.obstacles(GridLevel::Lower).size()) * 24;
}

void writeSnapshot(ByteWriter& out, const sandcore::Scene& scene) {
    out.reserve(out.bytes().size() + encodedSnapshotBytes(scene));
    for (const GridLevel level : {GridLevel::Upper, GridLevel::Lower}) {
        writeSize(out, scene.grid(level).size());
        if (level == GridLevel::Lower && !scene.bodies().empty()) {
            // A file keeps no moving bodies: their cells are saved as the EMPTY cells they cover.
            sandcore::CellGrid lower = scene.grid(level);
            for (std::size_t b = 0; b < scene.bodies().size(); ++b)
                for (std::uint32_t n : scene.bodyCells(b)) lower[n] = sandcore::kEmpty;
            out.putArray(std::span<const sandcore::CellValue>(lower.cells()));
        } else {
            out.putArray(scene.grid(level).cells());
        }
    }
    writeGrains(out, scene);
    const sandcore::SceneCounters& c = scene.counters();
    out.put<std::uint32_t>(scene.nextIdentity());
    out.put<std::int64_t>(c.grainsUpper);
    out.put<std::int64_t>(c.grainsLower);
    out.put<std::int64_t>(c.movesLastStep);
    out.put<std::int64_t>(c.visitedLastStep);
    out.put<std::uint64_t>(c.stepsDone);
    writeBoxes(out, scene.obstacles(GridLevel::Upper));
    writeBoxes(out, scene.obstacles(GridLevel::Lower));
}

void writeGrains(ByteWriter& out, const sandcore::Scene& scene) {
    const sandcore::GrainStore& g = scene.grains();
    // The file keeps one array per field (the format before places and falls shared records):
    // each field of a record is gathered into an array of its own.
    auto putField = [&](auto field) {
        std::vector<decltype(field(0u))> values(g.size());
        for (std::uint32_t id = 0; id < g.size(); ++id) values[id] = field(id);
        out.putArray(values);
    };
    out.putArray(g.level);
    putField([&](std::uint32_t id) { return g.place[id].cell; });
    putField([&](std::uint32_t id) { return g.place[id].cameFrom; });
    putField([&](std::uint32_t id) { return g.place[id].movedAtStep; });
    out.putArray(g.identity);
    out.putArray(g.color);
    putField([&](std::uint32_t id) { return scene.fallOf(id).speed; });
    putField([&](std::uint32_t id) { return scene.fallOf(id).fraction; });
}

sandcore::GrainStore readGrains(ByteReader& in) {
    sandcore::GrainStore g;
    g.level = in.getArray<GridLevel>("grain grids");
    const std::uint64_t grains = g.level.size();
    const std::vector<std::uint32_t> cells = in.getArray<std::uint32_t>("grain cells", grains);
    const std::vector<sandcore::MoveCode> moves = in.getArray<sandcore::MoveCode>("grain moves", grains);
    const std::vector<std::uint64_t> moveSteps = in.getArray<std::uint64_t>("grain move steps", grains);
    g.place.resize(cells.size());
    for (std::size_t id = 0; id < cells.size(); ++id) g.place[id] = {cells[id], moves[id], moveSteps[id]};
    g.identity = in.getArray<std::uint32_t>("grain identities", grains);
    g.color = in.getArray<std::uint32_t>("grain colours", grains);
    const std::vector<std::uint32_t> speeds = in.getArray<std::uint32_t>("grain fall speeds", grains);
    const std::vector<std::uint16_t> fractions = in.getArray<std::uint16_t>("grain fall fractions", grains);
    // Into the array of each grain's grid; a damaged grid byte (which the consistency checks
    // refuse later) picks the lower one rather than an array that is not there.
    for (sandcore::FallStates& grid : g.fall) grid.assign(speeds.size(), {});
    for (std::uint32_t id = 0; id < g.size(); ++id)
        g.fall[g.level[id] == GridLevel::Upper ? 1 : 0][id] = {speeds[id], fractions[id]};
    return g;
}

sandcore::SceneSnapshot readSnapshot(ByteReader& in) {
    CellGrid upper = readGrid(in, "upper grid size", "upper grid cells");
    CellGrid lower = readGrid(in, "lower grid size", "lower grid cells");
    sandcore::GrainStore g = readGrains(in);
    sandcore::SceneSnapshot s{std::move(upper), std::move(lower), std::move(g), 0, {}, {}, {}, false, {}};
    s.nextIdentity = in.get<std::uint32_t>("next identity");
    s.counters.grainsUpper = in.get<std::int64_t>("counters");
    s.counters.grainsLower = in.get<std::int64_t>("counters");
    s.counters.movesLastStep = in.get<std::int64_t>("counters");
    s.counters.visitedLastStep = in.get<std::int64_t>("counters");
    s.counters.stepsDone = in.get<std::uint64_t>("counters");
    s.upperObstacles = readBoxes(in, "upper obstacles");
    s.lowerObstacles = readBoxes(in, "lower obstacles");
    return s;
}

void requireConsistentSnapshot(const sandcore::SceneSnapshot& s, const CellGrid& upperLayout,
                               const CellGrid& lowerLayout) {
    if (!(s.upper.size() == upperLayout.size()) || !(s.lower.size() == lowerLayout.size()))
        throw FormatError("the grids' sizes differ from the layouts'");
    const sandcore::GrainStore& g = s.grains;
    const std::uint64_t grains = g.size();
    std::int64_t counted[2] = {0, 0};
    for (const GridLevel level : {GridLevel::Lower, GridLevel::Upper}) {
        const CellGrid& grid = level == GridLevel::Upper ? s.upper : s.lower;
        const CellGrid& layout = level == GridLevel::Upper ? upperLayout : lowerLayout;
        const char* name = level == GridLevel::Upper ? "upper" : "lower";
        for (std::uint32_t n = 0; n < grid.cellCount(); ++n) {
            const sandcore::CellValue v = grid[n];
            if (v == sandcore::kInvalid) continue; // layout or obstacle
            if (v < sandcore::kInvalid || layout[n] != sandcore::kEmpty)
                throw FormatError(std::string(name) + " grid cell " + std::to_string(n) + " holds " + std::to_string(v) +
                                  " where its layout allows none");
            if (v == sandcore::kEmpty) continue;
            const auto id = std::uint64_t(v);
            if (id >= grains || g.level[id] != level || g.place[id].cell != n)
                throw FormatError(std::string(name) + " grid cell " + std::to_string(n) + " names grain " +
                                  std::to_string(v) + ", which lies elsewhere");
            ++counted[int(level)];
        }
    }
    for (std::uint64_t id = 0; id < grains; ++id) {
        if (g.level[id] != GridLevel::Lower && g.level[id] != GridLevel::Upper)
            throw FormatError("grain " + std::to_string(id) + " lies in no grid");
        const sandcore::MoveCode move = g.place[id].cameFrom;
        if (std::abs(sandcore::moveDx(move)) > sandcore::kMaxMoveSideways ||
            std::abs(sandcore::moveDz(move)) > sandcore::kMaxMoveSideways ||
            std::abs(sandcore::moveDy(move)) > sandcore::kMaxMoveVertical)
            throw FormatError("grain " + std::to_string(id) + " has an invalid last move");
    }
    // Every cell naming a grain is named back by it (checked above), and the counts match: so
    // every grain sits in exactly one cell.
    if (std::uint64_t(counted[0] + counted[1]) != grains)
        throw FormatError(std::to_string(grains) + " grain records for " + std::to_string(counted[0] + counted[1]) +
                          " grain cells");
    if (s.counters.grainsLower != counted[int(GridLevel::Lower)] || s.counters.grainsUpper != counted[int(GridLevel::Upper)])
        throw FormatError("the grain counters disagree with the grids");
}

} // namespace sandglass
