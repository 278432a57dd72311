// SPDX-License-Identifier: MIT
#pragma once
// SPEC E2: the sand for other tools. A point cloud (.ply), MagicaVoxel voxels (.vox), the sand's
// surface as a mesh through assimp's exporter (.obj, .stl, .glb), and a voxelized model's inside
// cells (.vox, .binvox). Every file is written through a temporary file renamed into place;
// every failure is a FileError, one line "FILE: cause".

#include "scene/model_drawing.hpp"

#include "sandcore/display_positions.hpp"
#include "sandcore/inside_mask.hpp"
#include "sandcore/scene.hpp"
#include "sandcore/voxelizer.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sandglass {

/// Cells in world space coloured by palette index: what the .vox writer takes.
struct VoxelVolume {
    sandcore::Int3 size;                    ///< cells per axis, y up
    std::vector<std::uint8_t> index;        ///< per cell in CellGrid's layout: 0 = empty, else a palette index 1..255
    std::array<std::uint32_t, 256> palette{}; ///< RGBA8 of index i at palette[i]; palette[0] unused
};

/// Both grids of a scene merged into world cells (the shared row once); each filled cell gets the
/// colour of its grain (grainExportColor), quantised to at most 255 palette colours (median cut;
/// exact when there are no more than 255 distinct colours).
VoxelVolume sceneVoxels(const sandcore::Scene& scene);

/// Quantises colours (RGBA8, with how many cells use each) to at most 255; returns for each input
/// colour its palette index 1..255, and fills palette.
std::vector<std::uint8_t> quantiseColors(const std::vector<std::uint32_t>& colors,
                                         const std::vector<std::uint64_t>& counts,
                                         std::array<std::uint32_t, 256>& palette);

/// The bytes of a MagicaVoxel file (version 150) for a volume: one model per 256-cell tile,
/// placed by a scene graph (nTRN/nGRP/nSHP) so the tiles join up; MagicaVoxel's z is our y.
std::vector<std::uint8_t> encodeVox(const VoxelVolume& volume);

/// The formats `--export` writes, chosen by the file's extension.
enum class ExportFormat : std::uint8_t { Ply, Vox, Obj, Stl, Glb };
/// The format of a file name's extension (any case); throws FileError for any other.
ExportFormat exportFormatOf(const std::filesystem::path& file);

/// W6: where exported sand is written. Without a model, world units (cells times the cell size);
/// with one, the loaded model's own coordinates and units, turned back from the up axis the
/// scene stood it on (and from a turn-over), so the sand sits inside the glass in the modeller.
struct ExportFrame {
    sandcore::DisplaySettings display;    ///< cell size and jitter of the world units
    const ModelToWorld* model = nullptr;  ///< the loaded model's placement; null: world units
};

/// Writes the scene in the format its extension names (exportFormatOf). .vox stays in cells.
void exportScene(const std::filesystem::path& file, const sandcore::Scene& scene, const ExportFrame& frame = {});

/// Binary PLY: one vertex per grain at its display position (stepFraction 1: at rest where it
/// is) with its colour as red green blue uchar; the header states the cell size in the frame's units.
void writePointCloud(const std::filesystem::path& file, const sandcore::Scene& scene, const ExportFrame& frame = {});

/// The surface between grain cells and the rest, as a closed mesh of squares split into
/// triangles with shared corners, outward-facing, through assimp's exporter: .obj (without a
/// material file), .stl (binary) or .glb.
void writeSurfaceMesh(const std::filesystem::path& file, const sandcore::Scene& scene, const ExportFrame& frame = {});

/// A point in world cells of the scene as the frame writes it (see ExportFrame).
std::array<double, 3> exportedPoint(const sandcore::Scene& scene, const ExportFrame& frame, sandcore::Vec3 worldCells);

/// `voxelize --out`: a mask's inside cells as .vox (one sand colour) or .binvox (a cube of the
/// mask's largest size; translate and scale in model units when placement is given).
void writeInsideMask(const std::filesystem::path& file, const sandcore::InsideMask& mask,
                     const sandcore::VoxelPlacement* placement = nullptr);

} // namespace sandglass
