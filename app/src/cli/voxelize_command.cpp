// SPDX-License-Identifier: MIT
// SPEC C2: `sandglass voxelize FILE --res N` loads a model, voxelizes it and reports the grid,
// the inside cells, the mesh and voxel volumes and whether the mesh is closed.
#include "app/cli/checked_options.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/model_shape_json.hpp"
#include "scene/file_io.hpp"
#include "app/cli/terminal_progress.hpp"
#include "scene/model_voxelizer.hpp"
#include "scene/sand_space.hpp"
#include "scene/scene_export.hpp"
#include "scene/scene_request.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace sandglass {

namespace {

struct VoxelizeOptions {
    std::string file;
    sandcore::VoxelizeSettings settings;
    std::string scene = "hourglass";
    std::vector<std::string> parts;
    std::string up;
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
    ModelShapeRequest request;
    request.kind = parseSceneKind(options.scene);
    if (request.kind == sandcore::SceneKind::Canvas) throw std::invalid_argument("--scene: the canvas has no model");
    for (const std::string& part : options.parts) request.roles.push_back(parsePartRoleChoice(part));
    if (!options.up.empty()) {
        request.up = sandcore::parseUpAxis(options.up);
        if (!request.up) throw std::invalid_argument("--up must be one of +x, -x, +y, -y, +z, -z, got '" + options.up + "'");
    }
    const SandSpace space = [&] {
        const ElapsedTicker ticker("voxelize " + std::filesystem::path(options.file).filename().string(), std::cerr);
        return loadSandSpace(options.file, options.settings, ModelUse::MaskOnly, request);
    }();
    const ModelVoxelization& model = space.model;
    // The placement is in the model's axes; a turned mask is written without it.
    if (!options.out.empty())
        writeInsideMask(options.out, model.voxels.mask,
                        space.up == sandcore::UpAxis::PlusY ? &model.voxels.placement : nullptr);
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
        out["parts"] = partsJson(summarize(space.parts));
        out["vessel"] = vesselKindName(space.vessel);
        out["up_axis"] = sandcore::upAxisName(space.up);
        out["up_axis_found"] = space.upFound;
        out["sand_space_cells"] = space.space.countInside();
        out["cavities"] = space.cavities;
        out["cavity_milliseconds"] = space.cavityMilliseconds;
        out["closing_cells"] = space.closingCells;
        out["neck_opened"] = space.neckOpened;
        out["modelled_sand_cells"] = space.modelledSand.inside.empty() ? 0 : space.modelledSand.countInside();
        out["note"] = space.note;
        out["load_milliseconds"] = space.loadMilliseconds;
        out["total_milliseconds"] = space.loadMilliseconds + model.milliseconds + space.cavityMilliseconds;
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
    for (const ModelPart& part : space.parts)
        std::printf("part %s: %zu triangles, %s, %s\n", part.name.c_str(), part.mesh.triangles.size(),
                    part.closed ? "closed" : "open", partRoleName(part.role));
    std::printf("sand space: %s, %lld cells, %d cavities (%.2f ms), up axis %s%s\n", vesselKindName(space.vessel),
                (long long)space.space.countInside(), space.cavities, space.cavityMilliseconds,
                sandcore::upAxisName(space.up), space.upFound ? " (found)" : "");
    if (!space.note.empty()) std::printf("%s\n", space.note.c_str());
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
    cmd->add_option("--scene", options->scene, "hourglass (finds the cavity and up axis) or sculpture")->capture_default_str();
    cmd->add_option("--part", options->parts, "set a part's role, NAME=ROLE (vessel, frame, sand, static; repeatable)");
    cmd->add_option("--up", options->up, "the axis that points up: +x -x +y -y +z -z (default: found for the hourglass)");
    cmd->add_flag("--json", options->json, "print one JSON object");
    cmd->add_option("--out", options->out, "write the inside cells to this .vox (MagicaVoxel) or .binvox file");
    cmd->callback([options, &exitCode] { exitCode = runVoxelize(*options); });
}

} // namespace sandglass
