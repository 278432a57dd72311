// SPDX-License-Identifier: MIT
#pragma once
// SPEC P5: the draft image as one textured quad stretched over the canvas rectangle,
// half-transparent over the release row (PAINT_TOP) so the sand below stays visible, opaque
// on the lower floor (PAINT_BOTTOM) where the sand lands on it.

#include "scene/canvas_surface.hpp"
#include "scene/draft_image.hpp"
#include "view/render/gl_objects.hpp"

#include <filesystem>

namespace sandglass {

/// Where and whether the draft is shown.
struct DraftPlacement {
    bool visible = false;    ///< a draft is loaded and shown
    CanvasSurface surface;   ///< the rectangle it covers
    float opacity = 1.0f;    ///< 0..1; 0.5 over the release row
};

class DraftOverlay {
public:
    /// Loads shaders/draft.{vert,frag}; needs a current GL context.
    explicit DraftOverlay(const std::filesystem::path& shaderFolder);
    /// Uploads the image as the quad's texture.
    void setImage(const DraftImage& image);
    bool hasImage() const { return hasImage_; } ///< setImage was called
    /// Draws the quad with depth test on and depth writes off (it never hides sand drawn later).
    void draw(const DraftPlacement& placement, const float* viewProjection) const;

private:
    GlProgram program_;
    GlVertexArray emptyArray_;
    GlTexture texture_;
    bool hasImage_ = false;
};

} // namespace sandglass
