// SPDX-License-Identifier: MIT
#include "scene/scene_export.hpp"

#include "scene/file_io.hpp"
#include "scene/sand_patterns.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <string>
#include <unordered_map>

namespace sandglass {

using sandcore::GridLevel;
using sandcore::Int3;

namespace {

std::string lowerExtension(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

void appendBytes(std::vector<std::uint8_t>& out, const void* data, std::size_t size) {
    const auto* raw = static_cast<const std::uint8_t*>(data);
    out.insert(out.end(), raw, raw + size);
}

// binvox: a cube of side D, voxels run-length encoded as (value, count) byte pairs in the order
// x slowest, then z, then y fastest (y up).
std::vector<std::uint8_t> encodeBinvox(const sandcore::InsideMask& mask, const sandcore::VoxelPlacement* placement) {
    const int side = std::max({mask.size.x, mask.size.y, mask.size.z});
    double translate[3] = {0, 0, 0}, scale = side;
    if (placement && placement->scale[0] > 0) {
        for (int k = 0; k < 3; ++k) translate[k] = placement->modelMin[std::size_t(k)] - placement->padding[std::size_t(k)] / placement->scale[std::size_t(k)];
        scale = side / placement->scale[0];
    }
    char header[256];
    std::snprintf(header, sizeof header, "#binvox 1\ndim %d %d %d\ntranslate %.9g %.9g %.9g\nscale %.9g\ndata\n", side, side,
                  side, translate[0], translate[1], translate[2], scale);
    std::vector<std::uint8_t> out(header, header + std::strlen(header));
    std::uint8_t value = 0;
    int run = 0;
    const auto emit = [&] {
        if (run > 0) out.insert(out.end(), {value, std::uint8_t(run)});
    };
    for (int x = 0; x < side; ++x)
        for (int z = 0; z < side; ++z)
            for (int y = 0; y < side; ++y) {
                const bool inside = x < mask.size.x && y < mask.size.y && z < mask.size.z && mask.at(x, y, z);
                const std::uint8_t v = inside ? 1 : 0;
                if (v != value || run == 255) {
                    emit();
                    value = v;
                    run = 0;
                }
                ++run;
            }
    emit();
    return out;
}

} // namespace

VoxelVolume sceneVoxels(const sandcore::Scene& scene) {
    const sandcore::CellGrid& lower = scene.grid(GridLevel::Lower);
    const sandcore::CellGrid& upper = scene.grid(GridLevel::Upper);
    VoxelVolume volume;
    volume.size = {lower.size().x, lower.size().y + upper.size().y - 1, lower.size().z};
    const std::size_t cells = std::size_t(volume.size.x) * std::size_t(volume.size.y) * std::size_t(volume.size.z);
    // First the grain colour per world cell (a lower-grid grain wins in the shared row), then the palette.
    std::vector<std::int64_t> grainAt(cells, -1);
    const sandcore::GrainStore& grains = scene.grains();
    for (std::uint32_t id = 0; id < grains.size(); ++id) {
        const sandcore::CellGrid& grid = grains.level[id] == GridLevel::Upper ? upper : lower;
        const Int3 c = grid.coordinate(grains.place[id].cell);
        const Int3 origin = scene.gridOrigin(grains.level[id]);
        const std::size_t at = std::size_t(c.x) + std::size_t(volume.size.x) * (std::size_t(c.z) + std::size_t(volume.size.z) * std::size_t(c.y + origin.y));
        if (grainAt[at] < 0 || grains.level[id] == GridLevel::Lower) grainAt[at] = id;
    }
    const std::vector<SandPattern> patterns = makeSandPatterns();
    std::unordered_map<std::uint32_t, std::size_t> slot;
    std::vector<std::uint32_t> colors;
    std::vector<std::uint64_t> counts;
    std::vector<std::uint32_t> cellColor(cells, 0);
    for (std::size_t n = 0; n < cells; ++n) {
        if (grainAt[n] < 0) continue;
        const auto id = std::size_t(grainAt[n]);
        const std::uint32_t color = grainExportColor(patterns, grains.identity[id], grains.color[id]);
        cellColor[n] = color;
        const auto [it, added] = slot.try_emplace(color, colors.size());
        if (added) {
            colors.push_back(color);
            counts.push_back(0);
        }
        ++counts[it->second];
    }
    const std::vector<std::uint8_t> indexOf = quantiseColors(colors, counts, volume.palette);
    volume.index.assign(cells, 0);
    for (std::size_t n = 0; n < cells; ++n)
        if (grainAt[n] >= 0) volume.index[n] = indexOf[slot.at(cellColor[n])];
    return volume;
}

ExportFormat exportFormatOf(const std::filesystem::path& file) {
    const std::string extension = lowerExtension(file);
    if (extension == ".ply") return ExportFormat::Ply;
    if (extension == ".vox") return ExportFormat::Vox;
    if (extension == ".obj") return ExportFormat::Obj;
    if (extension == ".stl") return ExportFormat::Stl;
    if (extension == ".glb") return ExportFormat::Glb;
    throw FileError(file, "unknown export format '" + extension + "' (.ply, .vox, .obj, .stl or .glb)");
}

std::array<double, 3> exportedPoint(const sandcore::Scene& scene, const ExportFrame& frame, sandcore::Vec3 world) {
    if (!frame.model) {
        const double size = frame.display.cellSize;
        return {world.x * size, world.y * size, world.z * size};
    }
    if (scene.flipped()) {
        // Turned over, the world is the upright one mirrored in y within the grids' height.
        const float height = float(scene.gridOrigin(sandcore::GridLevel::Upper).y +
                                   scene.grid(sandcore::GridLevel::Upper).size().y);
        world.y = height - world.y;
    }
    return frame.model->toFile(world);
}

void exportScene(const std::filesystem::path& file, const sandcore::Scene& scene, const ExportFrame& frame) {
    switch (exportFormatOf(file)) {
    case ExportFormat::Ply: return writePointCloud(file, scene, frame);
    case ExportFormat::Vox: {
        requireWritableFileTarget(file);
        const std::vector<std::uint8_t> bytes = encodeVox(sceneVoxels(scene));
        return writeFileAtomically(file, std::span<const std::uint8_t>(bytes));
    }
    case ExportFormat::Obj:
    case ExportFormat::Stl:
    case ExportFormat::Glb: return writeSurfaceMesh(file, scene, frame);
    }
}

void writePointCloud(const std::filesystem::path& file, const sandcore::Scene& scene, const ExportFrame& frame) {
    requireWritableFileTarget(file);
    const std::uint32_t count = std::uint32_t(scene.grainCount());
    const sandcore::DisplaySettings& display = frame.display;
    // The cell size in the frame's units: the model's cells are 1 / scale model units along the
    // model axis that stands up (axes differ only with --stretch).
    const double cellSize = frame.model
                                ? 1.0 / frame.model->placement.scale[std::size_t(sandcore::axisTurnFor(frame.model->up).source[1])]
                                : double(display.cellSize);
    char header[512];
    std::snprintf(header, sizeof header,
                  "ply\nformat binary_little_endian 1.0\ncomment sandglass grains at their display positions, %s\n"
                  "comment cell_size %.9g\nelement vertex %u\nproperty float x\nproperty float y\nproperty float z\n"
                  "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n",
                  frame.model ? "the model's own coordinates and units" : "world units", cellSize, count);
    std::vector<sandcore::Vec3> positions(count);
    sandcore::writeDisplayPositions(scene, 1.0f, display, positions);
    if (frame.model)
        for (sandcore::Vec3& p : positions) {
            const float size = display.cellSize;
            const std::array<double, 3> model = exportedPoint(scene, frame, {p.x / size, p.y / size, p.z / size});
            p = {float(model[0]), float(model[1]), float(model[2])};
        }
    std::vector<std::uint8_t> out(header, header + std::strlen(header));
    out.reserve(out.size() + std::size_t(count) * 15);
    const std::vector<SandPattern> patterns = makeSandPatterns();
    const sandcore::GrainStore& grains = scene.grains();
    for (std::uint32_t id = 0; id < count; ++id) {
        const float xyz[3] = {positions[id].x, positions[id].y, positions[id].z};
        appendBytes(out, xyz, sizeof xyz);
        const std::uint32_t color = grainExportColor(patterns, grains.identity[id], grains.color[id]);
        out.insert(out.end(), {std::uint8_t(color), std::uint8_t(color >> 8), std::uint8_t(color >> 16)});
    }
    writeFileAtomically(file, std::span<const std::uint8_t>(out));
}

void writeInsideMask(const std::filesystem::path& file, const sandcore::InsideMask& mask,
                     const sandcore::VoxelPlacement* placement) {
    const std::string extension = lowerExtension(file);
    if (extension != ".vox" && extension != ".binvox")
        throw FileError(file, "unknown voxel format '" + extension + "' (.vox or .binvox)");
    requireWritableFileTarget(file);
    std::vector<std::uint8_t> bytes;
    if (extension == ".binvox") {
        bytes = encodeBinvox(mask, placement);
    } else {
        VoxelVolume volume;
        volume.size = mask.size;
        volume.index.assign(mask.inside.size(), 0);
        for (std::size_t n = 0; n < mask.inside.size(); ++n) volume.index[n] = mask.inside[n] ? 1 : 0;
        volume.palette[1] = grainExportColor(makeSandPatterns(), 0, 0);
        bytes = encodeVox(volume);
    }
    writeFileAtomically(file, std::span<const std::uint8_t>(bytes));
}

} // namespace sandglass
