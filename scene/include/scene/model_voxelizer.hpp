// SPDX-License-Identifier: MIT
#pragma once
// The model half of the data flow: model file -> mesh -> inside mask, with the memory check of
// S1 done before anything large is allocated. Shared by `sandglass voxelize`, buildScene and the GUI.

#include "sandcore/scene.hpp"
#include "sandcore/voxelizer.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace sandglass {

/// What a model needs memory for: only its mask, or a whole scene built from it.
enum class ModelUse : std::uint8_t {
    MaskOnly,  ///< `sandglass voxelize`: the inside mask alone
    Hourglass, ///< upper and lower grids of the vessel's size
    Sculpture, ///< the sculpture's grids (sandcore::sceneGridSizes)
};

/// A voxelized model file and what the user is shown about it (C2, G2).
struct ModelVoxelization {
    std::string path;                ///< the file as given
    std::int64_t triangles = 0;      ///< triangles loaded
    sandcore::VoxelizeResult voxels; ///< mask, placement, closedness, volumes
    double milliseconds = 0.0;       ///< time of the voxelization alone (not loading), ms
};

/// Memory this process may still use, bytes: MemAvailable from /proc/meminfo, else physical memory.
std::uint64_t availableMemoryBytes();

/// Loads and voxelizes a model file. memoryLimit 0 means availableMemoryBytes(). Throws ModelError
/// ("FILE: cause") for every S1 bad input, including a grid that would not fit in memory or
/// exceed 2^31 cells at the requested resolution; the check runs before allocating.
ModelVoxelization voxelizeModelFile(const std::string& path, const sandcore::VoxelizeSettings& settings,
                                    ModelUse use, std::uint64_t memoryLimit = 0);

/// As voxelizeModelFile for a mesh already loaded from `path` (named in messages).
ModelVoxelization voxelizeLoadedMesh(const std::string& path, const sandcore::TriangleMesh& mesh,
                                     const sandcore::VoxelizeSettings& settings, ModelUse use,
                                     std::uint64_t memoryLimit = 0);

} // namespace sandglass
