// SPDX-License-Identifier: MIT
#pragma once
// Moving bodies (sandcore/moving_body.hpp) drawn as solids: opaque, lit like the model's frame
// parts, written to the depth buffer with the sand and cast into the key light's shadow map.
// Each body's mesh holds the faces between its cells and the cells around, built once per shape
// and heading in the body's own frame; a move only changes the offset it is drawn at.

#include "view/render/gl_objects.hpp"
#include "view/render/model_surfaces.hpp"

#include "sandcore/moving_body.hpp"
#include "sandcore/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sandglass {

/// One body-mesh vertex, relative to the body's anchor cell (world units).
struct BodyVertex {
    float x, y, z;    ///< world units from the anchor cell's low corner
    float nx, ny, nz; ///< unit normal, pointing out of the body
};

/// The boundary faces of a body's cells (6 vertices a face) at cellSize world units per cell,
/// relative to its anchor, with normals smoothed over each cell's neighbourhood so a ball shades
/// round while a blade's faces stay flat.
std::vector<BodyVertex> buildBodyMesh(const sandcore::InsideMask& shape, int quarterTurns, float cellSize);

class BodySurfaces {
public:
    /// Loads shaders/model.{vert,frag}; needs a current GL 3.3 context.
    explicit BodySurfaces(const std::filesystem::path& shaderFolder);

    /// Follows the scene's bodies: a body whose shape or heading changed gets a new mesh.
    void update(const sandcore::Scene& scene, float cellSize);
    /// Opaque, depth test and writes on.
    void draw(const ModelLight& frame) const;
    /// Into the bound shadow map (depth only) with the light's clip matrix.
    void drawShadowCasters(const float* lightClip) const;
    std::int64_t triangles() const; ///< triangles of every body's mesh

private:
    struct Mesh {
        sandcore::InsideMask shape;
        int quarterTurns = 0;
        GlVertexArray array;
        GlBuffer buffer;
        std::int64_t vertices = 0;
        glm::vec3 offset{0.0f}; // the anchor cell's low corner, world units
    };
    void drawMeshes(const float* viewProjection) const;

    GlProgram program_;
    std::vector<Mesh> meshes_; // one per body, by index
};

} // namespace sandglass
