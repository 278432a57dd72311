// SPDX-License-Identifier: MIT
#include "scene/model_voxelizer.hpp"

#include "scene/mesh_loader.hpp"

#include "sandcore/cell_grid.hpp"
#include "sandcore/scene_geometry.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace sandglass {

namespace {

std::string gigabytes(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1ull << 30));
    return text;
}

std::string sizeText(sandcore::Int3 s) {
    return std::to_string(s.x) + "x" + std::to_string(s.y) + "x" + std::to_string(s.z);
}

} // namespace

namespace {
// The memory a use of a model grid needs, from the library that allocates it.
std::uint64_t bytesFor(ModelUse use, sandcore::Int3 g) {
    switch (use) {
    case ModelUse::MaskOnly: return sandcore::estimateMaskBytes(g);
    case ModelUse::Hourglass: return sandcore::estimateSceneBytes(sandcore::SceneKind::Hourglass, g);
    case ModelUse::Sculpture: return sandcore::estimateSceneBytes(sandcore::SceneKind::Sculpture, g);
    }
    return sandcore::estimateSceneBytes(sandcore::SceneKind::Sculpture, g);
}
} // namespace

std::uint64_t availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string line;
    while (std::getline(meminfo, line)) {
        std::istringstream fields(line);
        std::string key;
        std::uint64_t kibibytes = 0;
        if (fields >> key >> kibibytes && key == "MemAvailable:") return kibibytes * 1024;
    }
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0 ? std::uint64_t(pages) * std::uint64_t(pageSize) : 0;
}

ModelVoxelization voxelizeModelFile(const std::string& path, const sandcore::VoxelizeSettings& settings, ModelUse use,
                                    std::uint64_t memoryLimit) {
    return voxelizeLoadedMesh(path, loadMesh(path), settings, use, memoryLimit);
}

ModelVoxelization voxelizeLoadedMesh(const std::string& path, const sandcore::TriangleMesh& mesh,
                                     const sandcore::VoxelizeSettings& settings, ModelUse use, std::uint64_t memoryLimit) {
    ModelVoxelization out;
    out.path = path;
    out.triangles = std::int64_t(mesh.triangles.size());
    try {
        const sandcore::VoxelPlacement placement = sandcore::placeInGrid(mesh, settings);
        const sandcore::Int3 g = placement.size;
        if (use != ModelUse::MaskOnly)
            sandcore::validateSceneGridSizes(use == ModelUse::Hourglass ? sandcore::SceneKind::Hourglass
                                                                        : sandcore::SceneKind::Sculpture, g);
        const std::uint64_t needed = bytesFor(use, g);
        const std::uint64_t limit = memoryLimit != 0 ? memoryLimit : availableMemoryBytes();
        if (limit != 0 && needed > limit)
            throw ModelError(path, "too large for memory at resolution " + std::to_string(settings.resolution) +
                                       ": a " + sizeText(g) + " grid needs about " + gigabytes(needed) + ", " +
                                       gigabytes(limit) + " available; choose a lower resolution");
        const auto start = std::chrono::steady_clock::now();
        out.voxels = sandcore::voxelize(mesh, settings);
        out.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    } catch (const std::invalid_argument& e) {
        throw ModelError(path, e.what());
    }
    return out;
}

} // namespace sandglass
