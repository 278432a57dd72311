// SPDX-License-Identifier: MIT
#pragma once
// SPEC S10: a model drawn as modelled. The parts' own triangles, placed exactly where the
// voxelizer put their cells (the same scale and padding, the same quarter turns to the up axis,
// the same shift into the scene's grids), with smooth normals that keep sharp edges sharp.
// No GL here: the view uploads what this builds.

#include "scene/model_parts.hpp"

#include "sandcore/up_axis.hpp"
#include "sandcore/vec3.hpp"
#include "sandcore/voxelizer.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sandglass {

/// How a model point becomes a point of the scene's world, in cells (multiply by the cell size
/// for world units).
struct ModelToWorld {
    sandcore::VoxelPlacement placement;          ///< model units to the voxel grid (S2)
    sandcore::UpAxis up = sandcore::UpAxis::PlusY; ///< the quarter turns applied to the mask (S9)
    sandcore::Int3 maskOrigin;                   ///< where the turned mask's cell (0,0,0) lies (sandcore::maskOriginInScene)
    std::array<double, 3> fileCentre{};          ///< what the loader subtracted from the file's coordinates (ModelPart::fileCentre)

    /// The point in world cells.
    sandcore::Vec3 apply(const sandcore::Vec3& model) const;
    /// W6: a point in world cells back in the file's own coordinates and units (apply's inverse,
    /// with the loader's centring undone), in double: files far from the origin keep their digits.
    std::array<double, 3> toFile(const sandcore::Vec3& world) const;
};

/// A drawn vertex: world cells and a unit normal.
struct ModelVertex {
    float x, y, z;    ///< world cells
    float nx, ny, nz; ///< unit smooth normal (its sign follows the triangle's winding)
};

/// How a part is drawn.
enum class PartLook : std::uint8_t {
    Glass,  ///< transparent, Fresnel rim (vessel parts)
    Opaque, ///< lit in its colour (frame and static parts)
};

/// One drawn part: three vertices per triangle.
struct DrawnPart {
    std::string name;                 ///< the part's name
    PartLook look = PartLook::Glass;  ///< glass or opaque
    std::array<float, 3> colour{};    ///< material colour, or the wood / stone default
    std::vector<ModelVertex> vertices; ///< 3 per triangle
};

/// Every part that is drawn (sand parts of a sculpture are not: they become the sand).
struct ModelDrawing {
    std::vector<DrawnPart> parts; ///< in the file's order
    float heightCells = 0.0f;     ///< world height of the scene's grids together, cells (turning over mirrors y in it)
};

/// Default colours of parts whose material gives none: light wood for a frame, grey stone for a
/// static part, a cool grey tint for glass.
inline constexpr std::array<float, 3> kWoodColour{0.62f, 0.42f, 0.24f};
inline constexpr std::array<float, 3> kStoneColour{0.58f, 0.57f, 0.54f};
inline constexpr std::array<float, 3> kGlassColour{0.80f, 0.88f, 0.95f};

/// Edges between faces more than this many degrees apart stay sharp.
inline constexpr float kCreaseDegrees = 50.0f;

/// Grows the box lo..hi (world units) to hold the drawing at cellSize, mirrored in y within its
/// height when the hourglass is turned over: the camera frames the frame too, not only the sand.
void includeInBounds(const ModelDrawing& drawing, bool turnedOver, float cellSize, sandcore::Vec3& lo, sandcore::Vec3& hi);

/// The drawing of a model's parts (model units, as loadModelParts gives them, with roles).
ModelDrawing makeModelDrawing(const std::vector<ModelPart>& parts, const ModelToWorld& toWorld, float heightCells);

} // namespace sandglass
