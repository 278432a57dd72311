// SPDX-License-Identifier: MIT
#pragma once
// SPEC P1, picking by colour id: the canvas columns are drawn offscreen into an integer
// (GL_R32UI) image, one id per column, so any canvas size works (the thesis's RGB code stopped
// at 65k cells). The image is read back once and cached; lookups while the button is held
// are array reads. A new view, window size or canvas draws it again.

#include "scene/canvas_surface.hpp"
#include "view/render/gl_objects.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace sandglass {

/// Everything the id image depends on; a different key means the cache is stale.
struct PickView {
    glm::mat4 view{1.0f};       ///< world to eye
    glm::mat4 projection{1.0f}; ///< eye to clip
    int width = 0;              ///< framebuffer pixels
    int height = 0;             ///< framebuffer pixels
    CanvasSurface surface;      ///< the rectangle drawn
    friend bool operator==(const PickView&, const PickView&) = default;
};

class ColumnPicker {
public:
    /// Loads shaders/pick.{vert,frag}; needs a current GL 3.3 context. Throws std::runtime_error on a shader problem.
    explicit ColumnPicker(const std::filesystem::path& shaderFolder);

    /// Makes the cached id image match `view`: draws and reads it back only when the view,
    /// size or surface changed since the last call, or after invalidate(). Restores the
    /// caller's framebuffer and viewport.
    void prepare(const PickView& view);
    /// The column under framebuffer pixel (x right, y down from the top row) of the cached
    /// image; none off the canvas or outside the image. Call prepare() first.
    std::optional<CanvasColumn> columnAt(int pixelX, int pixelY) const;
    /// Forgets the cached image (the scene was rebuilt or edited in its geometry).
    void invalidate() { cached_.reset(); }

    /// How often the id image was drawn and read back (for tests: once per view).
    std::int64_t redraws() const { return redraws_; }
    /// The raw cached ids, rows from the bottom (GL order): column index + 1, 0 = nothing.
    const std::vector<std::uint32_t>& ids() const { return ids_; }

private:
    void resizeTarget(int width, int height);
    void drawIds(const PickView& view);

    GlProgram program_;
    GlVertexArray emptyArray_;
    GlFramebuffer framebuffer_;
    GlTexture idTexture_;
    GlRenderbuffer depth_;
    int targetWidth_ = 0, targetHeight_ = 0;
    std::optional<PickView> cached_;
    std::vector<std::uint32_t> ids_;
    std::int64_t redraws_ = 0;
};

/// Window (cursor) coordinates to framebuffer pixels: on HiDPI screens the framebuffer has
/// more pixels than the window has screen coordinates.
void cursorToFramebuffer(double cursorX, double cursorY, int windowWidth, int windowHeight, int framebufferWidth,
                         int framebufferHeight, int& pixelX, int& pixelY);

} // namespace sandglass
