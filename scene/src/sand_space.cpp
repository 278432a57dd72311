#include "scene/sand_space.hpp"

#include "sandcore/cavity.hpp"

#include <chrono>

namespace sandglass {

const char* vesselKindName(VesselKind kind) { return kind == VesselKind::Cavity ? "cavity" : "solid"; }

namespace {

using Clock = std::chrono::steady_clock;

void addInto(sandcore::InsideMask& into, const sandcore::InsideMask& cells) {
    for (std::size_t n = 0; n < into.inside.size(); ++n) into.inside[n] |= cells.inside[n];
}

// The cells a part occupies in the model's grid: its parity inside when it is closed, and every
// cell its surface touches, so thin walls seal.
sandcore::InsideMask partCells(const ModelPart& part, const sandcore::VoxelPlacement& placement,
                               const sandcore::VoxelizeSettings& settings, bool surface) {
    const sandcore::TriangleMesh grid = sandcore::toGridSpace(part.mesh, placement);
    sandcore::InsideMask cells = part.closed ? sandcore::voxelizeGridSpace(grid, placement.size, settings)
                                             : sandcore::InsideMask::empty(placement.size);
    if (surface) addInto(cells, sandcore::surfaceCells(grid, placement.size));
    return cells;
}

bool isWall(PartRole role) { return role != PartRole::Sand; }

} // namespace

SandSpace loadSandSpace(const std::string& path, const sandcore::VoxelizeSettings& settings, ModelUse use,
                        const ModelShapeRequest& request, std::uint64_t memoryLimit) {
    SandSpace out;
    out.parts = loadModelParts(path);
    chooseRoles(out.parts, request.kind, request.roles);
    out.model = voxelizeLoadedMesh(path, mergedMesh(out.parts), settings, use, memoryLimit);
    const sandcore::VoxelPlacement& placement = out.model.voxels.placement;
    const bool onePart = out.parts.size() == 1;
    if (request.kind == sandcore::SceneKind::Hourglass) {
        const auto start = Clock::now();
        // One part: the model's own inside cells are the part's.
        sandcore::InsideMask walls = onePart ? out.model.voxels.mask : sandcore::InsideMask::empty(placement.size);
        for (const ModelPart& part : out.parts) {
            if (!isWall(part.role)) continue;
            if (onePart) addInto(walls, sandcore::surfaceCells(sandcore::toGridSpace(part.mesh, placement), placement.size));
            else addInto(walls, partCells(part, placement, settings, true));
        }
        sandcore::CavitySearch search = sandcore::findCavities(walls);
        out.cavityMilliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        out.cavities = search.cavities;
        if (search.largestCells >= kMinCavityCells) {
            out.vessel = VesselKind::Cavity;
            out.space = std::move(search.largest);
        } else {
            out.space = out.model.voxels.mask;
        }
    } else {
        bool allSand = true;
        for (const ModelPart& part : out.parts) allSand = allSand && part.role == PartRole::Sand;
        if (allSand) {
            out.space = out.model.voxels.mask;
        } else {
            out.space = sandcore::InsideMask::empty(placement.size);
            out.obstacles = sandcore::InsideMask::empty(placement.size);
            for (const ModelPart& part : out.parts) {
                if (part.role == PartRole::Sand) addInto(out.space, partCells(part, placement, settings, false));
                else addInto(out.obstacles, partCells(part, placement, settings, true));
            }
            // An obstacle cell holds no sand.
            for (std::size_t n = 0; n < out.space.inside.size(); ++n)
                if (out.obstacles.inside[n]) out.space.inside[n] = 0;
        }
    }
    if (request.up) {
        out.up = *request.up;
    } else if (request.kind == sandcore::SceneKind::Hourglass) {
        out.up = sandcore::findUpAxis(out.space);
        out.upFound = true;
    }
    out.space = sandcore::turnToUp(out.space, out.up);
    out.model.voxels.mask = sandcore::turnToUp(out.model.voxels.mask, out.up);
    if (!out.obstacles.inside.empty()) out.obstacles = sandcore::turnToUp(out.obstacles, out.up);
    return out;
}

} // namespace sandglass
