// SPDX-License-Identifier: MIT
#pragma once
// The studio look shared by every shader that includes shaders/look.glsl (docs/rendering.md,
// Lighting to Glass environment): the lights, the switches, and the key light's shadow map.

#include "view/render/gl_objects.hpp"
#include "view/render/render_settings.hpp"

#include <glm/glm.hpp>

namespace sandglass {

/// An axis-aligned box in world units.
struct WorldBox {
    glm::vec3 min{0.0f}, max{0.0f};
};

/// What look.glsl's uniforms hold for one frame.
struct StudioLook {
    bool studio = false;      ///< the studio lights; false: the thesis's look
    bool toneMapping = false;
    bool environment = false; ///< glass reflects the sky
    bool shadows = false;     ///< the shadow map is drawn and read
    glm::vec3 keyDirection{0.0f, 1.0f, 0.0f}, keyColor{0.0f}; ///< toward the light; linear colour
    glm::vec3 fillDirection{0.0f, 1.0f, 0.0f}, fillColor{0.0f};
    glm::vec3 skyColor{0.0f}, groundColor{0.0f};
    glm::mat4 lightMatrix{1.0f}; ///< world to the shadow map's [0, 1] cube
    float shadowOffset = 1.0f;   ///< world units: one cell
};

/// The look for these settings, its lights fixed in the world (so shadows stay put while the
/// camera orbits) and chosen for the default view: the key from the upper left, in front.
StudioLook studioLookFor(const RenderSettings& settings, float cellSize);

/// Texture unit of the shadow map in every program that reads it.
inline constexpr int kShadowMapUnit = 10;

/// Sets look.glsl's uniforms of the program in use (its shadowMap sampler to kShadowMapUnit).
void setLookUniforms(GLuint program, const StudioLook& look);

/// A depth texture rendered from the key light, orthographic over the scene's box.
class ShadowMap {
public:
    ShadowMap();
    /// Fits the light's projection around box, binds the map as the framebuffer (depth only) and
    /// clears it; look's lightMatrix is set. Returns the light's clip matrix,
    /// to draw the casters with. A cell spans 1.5 to 3 texels (256 to 2048 a side).
    glm::mat4 begin(const WorldBox& box, float cellSize, StudioLook& look);
    /// Back to the framebuffer and viewport bound before begin.
    void end();
    /// Binds the map to kShadowMapUnit (or nothing, while it is drawn into).
    void bind(bool on) const;
    /// Texels per world unit of the last begin (casting grains are points this many per cell).
    float texelsPerUnit() const { return texelsPerUnit_; }
    /// False when this GL cannot draw into the depth texture (the framebuffer is incomplete): the
    /// frame is then drawn without shadows.
    bool usable() const { return usable_; }

private:
    GlFramebuffer framebuffer_;
    GlTexture depth_;
    int size_ = 0;
    float texelsPerUnit_ = 1.0f;
    bool usable_ = true;
    GLint previousFramebuffer_ = 0;
    GLint previousViewport_[4] = {0, 0, 0, 0};
};

} // namespace sandglass
