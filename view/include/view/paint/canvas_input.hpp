// SPDX-License-Identifier: MIT
#pragma once
// The mouse on the canvas (SPEC P1-P4, P7): a cursor position becomes a canvas column through
// the id picker, and button down / held / up become the painter's begin / continue / end.
// The window's mouse handling and the tests both drive this class, so a scripted stroke takes
// the same path as a hand-drawn one.

#include "view/paint/column_picker.hpp"
#include "scene/draft_image.hpp"
#include "scene/sand_painter.hpp"

#include "sandcore/scene.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>

namespace sandglass {

/// One mouse sample as the canvas sees it.
struct PointerSample {
    double cursorX = 0.0;       ///< window coordinates (screen units), x right
    double cursorY = 0.0;       ///< window coordinates (screen units), y down
    bool leftDown = false;      ///< the left button is held
    bool altHeld = false;       ///< Alt held: the mouse drives the camera, never the brush
    bool guiWantsMouse = false; ///< ImGui wants the mouse (io.WantCaptureMouse)
};

/// The view the canvas is seen in this frame.
struct CanvasView {
    glm::mat4 view{1.0f};         ///< world to eye
    glm::mat4 projection{1.0f};   ///< eye to clip
    int windowWidth = 0;          ///< screen units (cursor coordinates)
    int windowHeight = 0;         ///< screen units
    int framebufferWidth = 0;     ///< pixels (more than the window's on HiDPI screens)
    int framebufferHeight = 0;    ///< pixels
    float cellSize = 1.0f;        ///< world units per cell, as the renderer draws
};

/// The cursor position (window coordinates) over the centre of a column of a surface, or none
/// when that point lies behind the camera. Scripted strokes and tests aim with it.
std::optional<glm::dvec2> cursorOverColumn(const CanvasView& view, const CanvasSurface& surface, CanvasColumn column);

class CanvasInput {
public:
    /// Loads the picking shaders; needs a current GL context. `undo` caps the stroke history.
    explicit CanvasInput(const std::filesystem::path& shaderFolder, UndoLimits undo = {})
        : picker_(shaderFolder), painter_(undo) {}

    /// The column of the chosen surface under the cursor, or none off the canvas. Draws the id
    /// image only when the view, window or surface changed since it was last drawn.
    std::optional<CanvasColumn> columnUnderCursor(const sandcore::Scene& scene, double cursorX, double cursorY,
                                                  const CanvasView& view, PaintTarget target);
    /// Feeds one mouse sample: button down on the canvas begins a stroke, held continues it
    /// (joined to the last column), up ends it. Returns true when the scene's grains changed.
    bool handlePointer(sandcore::Scene& scene, const PointerSample& sample, const CanvasView& view,
                       const PaintSettings& settings);
    /// Ends a stroke under way (the button came up).
    void endStroke() { painter_.endStroke(); }
    /// P7: undoes the last stroke; false when there is none.
    bool undo(sandcore::Scene& scene) { return painter_.undo(scene); }
    /// E3: redoes the last undone stroke; false when there is none.
    bool redo(sandcore::Scene& scene) { return painter_.redo(scene); }
    /// The scene was rebuilt or reset: ends any stroke, forgets undo history and the id image.
    void sceneReplaced();

    /// P5: the draft image for "colour from draft" (the renderer shows its own copy).
    void setDraft(DraftImage draft) { draft_ = std::move(draft); }
    const DraftImage* draft() const { return draft_ ? &*draft_ : nullptr; } ///< none until one loads

    const ColumnPicker& picker() const { return picker_; } ///< the id picker (redraw count for tests)
    const SandPainter& painter() const { return painter_; } ///< stroke state and undo depth
    /// Saves the scene for undo, as a stroke's start does (a digger's drag).
    void rememberForUndo(const sandcore::Scene& scene) { painter_.rememberForUndo(scene); }

private:
    ColumnPicker picker_;
    SandPainter painter_;
    std::optional<DraftImage> draft_;
};

} // namespace sandglass
