// SPDX-License-Identifier: MIT
#pragma once
// SPEC S10: a model drawn as modelled. Frame and static parts are opaque, lit in their colour and
// written to the depth buffer with the sand; glass parts come last, blended without depth
// writes, their triangles sorted back to front from the eye whenever the eye moves, so every
// glass wall (outer and inner, far and near) blends over the sand and over the walls behind it.

#include "scene/model_drawing.hpp"
#include "view/render/gl_objects.hpp"
#include "view/render/studio_look.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

namespace sandglass {

/// What a draw of the model needs from the frame.
struct ModelLight {
    const float* viewProjection = nullptr; ///< column-major 4x4
    glm::vec3 eye{0.0f};                   ///< camera position, world units
    glm::vec3 light{0.0f};                 ///< point light position, world units
    bool blackBackground = false;          ///< the glass tint reads on either background
    const StudioLook* look = nullptr;      ///< the studio look (null: the thesis's)
};

class ModelSurfaces {
public:
    /// Loads shaders/model.{vert,frag}; needs a current GL 3.3 context.
    explicit ModelSurfaces(const std::filesystem::path& shaderFolder);

    /// Uploads a drawing (null: nothing to draw) at cellSize world units per cell, mirrored in
    /// y within its height when the hourglass is turned over.
    void set(const ModelDrawing* drawing, bool turnedOver, float cellSize);
    bool empty() const { return opaqueVertices_ == 0 && glassTriangles_.empty(); } ///< nothing uploaded

    /// Opaque parts, depth test and writes on.
    void drawOpaque(const ModelLight& frame);
    /// Draws the opaque parts into the bound shadow map (depth only) with the light's clip matrix.
    void drawShadowCasters(const float* lightClip);
    /// The box around every uploaded vertex (world units); empty: nothing uploaded.
    const WorldBox& bounds() const { return bounds_; }
    /// Glass parts, blended over what is drawn, depth test on and writes off.
    void drawGlass(const ModelLight& frame);
    /// Sorts the glass for this eye if it moved since the last sort (drawGlass does it too).
    void sortGlassFor(const glm::vec3& eye);

    std::int64_t glassTriangles() const { return std::int64_t(glassTriangles_.size()); } ///< uploaded glass triangles
    std::int64_t opaqueTriangles() const { return opaqueVertices_ / 3; }                ///< uploaded opaque triangles

private:
    struct GpuVertex {
        float x, y, z;    // world units
        float nx, ny, nz; // unit normal
        float r, g, b;    // colour 0..1
    };
    void sortGlass(const glm::vec3& eye);
    // Binds the program with the frame's matrices and light; glass picks the glass shading.
    void useProgram(const ModelLight& frame, bool glass) const;

    GlProgram program_;
    GlVertexArray opaqueArray_, glassArray_;
    GlBuffer opaqueBuffer_, glassBuffer_, glassOrder_;
    std::int64_t opaqueVertices_ = 0;
    std::vector<glm::vec3> glassTriangles_; // centroids, world units
    std::vector<std::uint32_t> order_;      // vertex indices, farthest triangle first
    glm::vec3 sortedFor_{1e30f};
    WorldBox bounds_;
};

} // namespace sandglass
