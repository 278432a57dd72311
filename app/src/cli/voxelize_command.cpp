// SPEC C2: `sandglass voxelize FILE --res N` loads a model, voxelizes it and reports the grid,
// the inside cells, the mesh and voxel volumes and whether the mesh is closed.
#include "app/cli/checked_options.hpp"
#include "app/cli/commands.hpp"
#include "scene/file_io.hpp"
#include "app/cli/terminal_progress.hpp"
#include "scene/model_voxelizer.hpp"
#include "scene/scene_export.hpp"
#include "scene/scene_request.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

namespace sandglass {

namespace {

struct VoxelizeOptions {
    std::string file;
    sandcore::VoxelizeSettings settings;
    bool json = false;
    std::string out; ///< E2: write the inside cells here (.vox or .binvox)
};

int runVoxelize(const VoxelizeOptions& options) {
    if (!options.out.empty()) {
        const std::string extension = std::filesystem::path(options.out).extension().string();
        if (extension != ".vox" && extension != ".binvox")
            throw std::invalid_argument("--out " + options.out + ": the voxels go to a .vox or .binvox file");
        requireWritableFileTarget(options.out);
    }
    const ModelVoxelization model = [&] {
        const ElapsedTicker ticker("voxelize " + std::filesystem::path(options.file).filename().string(), std::cerr);
        return voxelizeModelFile(options.file, options.settings, ModelUse::MaskOnly);
    }();
    if (!options.out.empty()) writeInsideMask(options.out, model.voxels.mask, &model.voxels.placement);
    const sandcore::VoxelizeResult& v = model.voxels;
    const sandcore::Int3 g = v.mask.size;
    const bool closed = v.closedness.closed;
    const bool volumeKnown = v.volumeMeaningful; // closed and consistently orientable
    if (options.json) {
        nlohmann::ordered_json out;
        out["grid"] = {g.x, g.y, g.z};
        out["cells_inside"] = v.cellsInside;
        out["mesh_volume"] = volumeKnown ? nlohmann::ordered_json(v.meshVolume) : nlohmann::ordered_json(nullptr);
        out["voxel_volume"] = double(v.cellsInside);
        out["relative_error"] = volumeKnown ? nlohmann::ordered_json(v.relativeError()) : nlohmann::ordered_json(nullptr);
        out["closed"] = closed;
        out["boundary_edges"] = v.closedness.boundaryEdges;
        out["milliseconds"] = model.milliseconds;
        out["triangles"] = model.triangles;
        out["threads"] = options.settings.threads;
        out["robust"] = options.settings.robust;
        if (!options.out.empty()) out["out"] = options.out;
        std::cout << out.dump() << "\n";
        return 0;
    }
    std::printf("%s: %lld triangles, %s (%lld boundary edges)\n", options.file.c_str(), (long long)model.triangles,
                closed ? "closed" : "open", (long long)v.closedness.boundaryEdges);
    std::printf("grid %dx%dx%d, %lld cells inside\n", g.x, g.y, g.z, (long long)v.cellsInside);
    if (volumeKnown)
        std::printf("mesh volume %.1f cells, voxel volume %lld cells, relative error %+.4f%%\n", v.meshVolume,
                    (long long)v.cellsInside, 100.0 * v.relativeError());
    else if (closed)
        std::printf("no mesh volume: the faces' orientation is inconsistent and cannot be repaired, so a signed "
                    "volume means nothing\n");
    else
        std::printf("no mesh volume: the mesh is open%s\n", options.settings.robust ? "" : " (try --robust)");
    std::printf("voxelized in %.2f ms with %d thread(s)\n", model.milliseconds, options.settings.threads);
    if (!options.out.empty()) std::printf("wrote the inside cells to %s\n", options.out.c_str());
    return 0;
}

} // namespace

void addVoxelizeCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<VoxelizeOptions>();
    CLI::App* cmd = app.add_subcommand("voxelize", "Voxelize a model file and report its grid, volumes and closedness");
    cmd->add_option("file", options->file, "model file (OBJ, STL, PLY, glTF, ...)")->required();
    addNumberOption(*cmd, "--res", options->settings.resolution, 1, sandcore::kMaxVoxelResolution,
                    "cells along the model's largest extent (default " + std::to_string(options->settings.resolution) + ")");
    cmd->add_flag("--robust", options->settings.robust, "majority vote of parity along x, y and z (open meshes)");
    cmd->add_flag("--stretch", options->settings.stretch, "scale every axis to --res cells (aspect not kept)");
    addNumberOption(*cmd, "--threads", options->settings.threads, kThreadsRange.min, kThreadsRange.max,
                    "threads that share the rows (default 1; same result for any count)");
    cmd->add_flag("--json", options->json, "print one JSON object");
    cmd->add_option("--out", options->out, "write the inside cells to this .vox (MagicaVoxel) or .binvox file");
    cmd->callback([options, &exitCode] { exitCode = runVoxelize(*options); });
}

} // namespace sandglass
