// SPDX-License-Identifier: MIT
#include "scene/sand_space.hpp"

#include "scene/mesh_loader.hpp"

#include "sandcore/cavity.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace sandglass {

namespace {

using Clock = std::chrono::steady_clock;

void addInto(sandcore::InsideMask& into, const sandcore::InsideMask& cells) {
    for (std::size_t n = 0; n < into.inside.size(); ++n) into.inside[n] |= cells.inside[n];
}

// The cells a part occupies in the model's grid: its inside (parity when it is closed, the
// robust vote when it is open: W4) and, for obstacles, every cell its surface touches.
sandcore::InsideMask partCells(const ModelPart& part, const sandcore::VoxelPlacement& placement,
                               sandcore::VoxelizeSettings settings, bool surface) {
    const sandcore::TriangleMesh grid = sandcore::toGridSpace(part.mesh, placement);
    settings.robust = settings.robust || !part.closed;
    sandcore::InsideMask cells = sandcore::voxelizeGridSpace(grid, placement.size, settings);
    if (surface) addInto(cells, sandcore::surfaceCells(grid, placement.size));
    return cells;
}

sandcore::ShellRole shellRoleOf(PartRole role) {
    switch (role) {
    case PartRole::Vessel: return sandcore::ShellRole::Glass;
    case PartRole::Sand: return sandcore::ShellRole::Sand;
    case PartRole::Frame:
    case PartRole::Static: return sandcore::ShellRole::Frame;
    }
    return sandcore::ShellRole::Glass;
}

PartRole partRoleOf(sandcore::ShellRole role) {
    switch (role) {
    case sandcore::ShellRole::Glass: return PartRole::Vessel;
    case sandcore::ShellRole::Frame: return PartRole::Frame;
    case sandcore::ShellRole::Sand: return PartRole::Sand;
    }
    return PartRole::Vessel;
}

void findHourglass(SandSpace& out, const sandcore::VoxelizeSettings& settings, const ModelShapeRequest& request) {
    const auto start = Clock::now();
    std::vector<sandcore::ModelShell> shells;
    shells.reserve(out.parts.size());
    for (const ModelPart& part : out.parts) shells.push_back({part.mesh, shellRoleOf(part.role), part.roleFixed, part.closed});
    sandcore::HourglassSpaceSettings search;
    search.voxelize = settings;
    search.up = request.up;
    sandcore::HourglassSpace found = sandcore::findHourglassSpace(shells, search);
    out.cavityMilliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    for (std::size_t i = 0; i < out.parts.size(); ++i) out.parts[i].role = partRoleOf(found.roles[i]);
    out.space = std::move(found.space);
    if (found.modelledSand.countInside() > 0) out.modelledSand = std::move(found.modelledSand);
    out.vessel = found.kind;
    out.up = found.up;
    out.upFound = found.upFound;
    out.cavities = found.enclosedSpaces;
    out.closingCells = found.closingCells;
    out.neckOpened = found.neckOpened;
    out.note = found.note;
}

void findSculpture(SandSpace& out, const sandcore::VoxelizeSettings& settings, const ModelShapeRequest& request) {
    const sandcore::VoxelPlacement& placement = out.model.voxels.placement;
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
    // W4: parts thinner than a cell hold a cell centre or not depending on where they lie, so
    // some may be missing from the statue: say so, with the resolution that holds them all.
    if (const std::string hint = thinPartsHint(out.parts, placement, settings.resolution, 1.0); !hint.empty())
        out.note = "some parts may hold no sand: " + hint;
    if (request.up) {
        out.up = *request.up;
    } else {
        out.up = sculptureUpAxis(sandcore::boundsOf(mergedMesh(out.parts)));
        out.upFound = out.up != sandcore::UpAxis::PlusY;
    }
}

} // namespace

sandcore::UpAxis sculptureUpAxis(const sandcore::MeshBounds& bounds) {
    const double x = bounds.extent(0), y = bounds.extent(1), z = bounds.extent(2);
    return z > 1.1 * std::max(x, y) ? sandcore::UpAxis::PlusZ : sandcore::UpAxis::PlusY;
}

SandSpace loadSandSpace(const std::string& path, const sandcore::VoxelizeSettings& requested, ModelUse use,
                        const ModelShapeRequest& request, std::uint64_t memoryLimit, BuildProgress* progress) {
    SandSpace out;
    checkpoint(progress, BuildPhase::Loading);
    const auto loadStart = Clock::now();
    out.parts = loadModelParts(path);
    out.loadMilliseconds = std::chrono::duration<double, std::milli>(Clock::now() - loadStart).count();
    chooseRoles(out.parts, request.kind, request.roles);
    sandcore::VoxelizeSettings settings = requested;
    // W4: an open sculpture gets the robust inside test; parity would leave holes through it.
    const bool sculpture = request.kind == sandcore::SceneKind::Sculpture;
    if (sculpture)
        for (const ModelPart& part : out.parts) settings.robust = settings.robust || !part.closed;
    checkpoint(progress, BuildPhase::Voxelizing);
    out.model = voxelizeLoadedMesh(path, mergedMesh(out.parts), settings, use, memoryLimit);
    checkpoint(progress, BuildPhase::FindingSandSpace);
    try {
        if (sculpture) findSculpture(out, settings, request);
        else findHourglass(out, settings, request);
    } catch (const std::invalid_argument& e) {
        throw ModelError(path, e.what());
    }
    // The hourglass's space comes turned from its search.
    if (sculpture) out.space = sandcore::turnToUp(out.space, out.up);
    out.model.voxels.mask = sandcore::turnToUp(out.model.voxels.mask, out.up);
    if (!out.obstacles.inside.empty()) out.obstacles = sandcore::turnToUp(out.obstacles, out.up);
    return out;
}

std::string thinPartsHint(const std::vector<ModelPart>& parts, const sandcore::VoxelPlacement& placement, int resolution,
                          double thinnerThanCells) {
    // Each part's thinnest extent in cells; the median part decides the resolution to suggest.
    std::vector<double> thinnest;
    for (const ModelPart& part : parts) {
        const sandcore::MeshBounds b = sandcore::boundsOf(part.mesh);
        double cells = 1e300;
        for (int a = 0; a < 3; ++a) cells = std::min(cells, b.extent(a) * placement.scale[std::size_t(a)]);
        thinnest.push_back(cells);
    }
    std::sort(thinnest.begin(), thinnest.end());
    const double median = thinnest.empty() ? 0.0 : thinnest[thinnest.size() / 2];
    if (!(median > 0.0 && median < thinnerThanCells)) return "";
    const int needed = int(std::ceil(resolution * 2.0 / median));
    char text[200];
    std::snprintf(text, sizeof text, "its %zu part%s are about %.2f cells thin; --res %d would give them two cells across",
                  parts.size(), parts.size() == 1 ? "" : "s", median, needed);
    return text;
}

std::string noCellInsideMessage(const std::vector<ModelPart>& parts, const sandcore::VoxelPlacement& placement,
                                int resolution, bool closed) {
    std::string message = "no cell lies inside the model at resolution " + std::to_string(resolution);
    if (const std::string hint = thinPartsHint(parts, placement, resolution, 2.0); !hint.empty()) message += ": " + hint;
    else if (!closed) message += " (the mesh is open; try --robust)";
    return message;
}

} // namespace sandglass
