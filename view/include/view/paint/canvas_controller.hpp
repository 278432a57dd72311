// SPDX-License-Identifier: MIT
#pragma once
// The canvas as the user works on it: the mouse path into strokes (through the id picker), the
// draft image, undo and box obstacles, all on the running scene of a SceneHost. The window loop
// feeds it samples and the painting commands; the tests drive the same object.

#include "view/app_state.hpp"
#include "view/paint/canvas_input.hpp"
#include "view/render/draft_overlay.hpp"

#include "scene/scene_host.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace sandglass {

class CanvasController {
public:
    /// Loads the picking shaders (a current GL context is needed); `undo` caps the stroke history.
    CanvasController(const std::filesystem::path& shaderFolder, UndoLimits undo) : input_(shaderFolder, undo) {}

    /// One mouse sample on the canvas: begins, continues or ends a stroke with the panel's
    /// painting settings. Returns true when the grains changed. Nothing happens outside the
    /// canvas scene or while a new scene is being built.
    bool handlePointer(SceneHost& host, const PointerSample& sample, const CanvasView& view,
                       const PaintingSettings& painting);
    /// The column under a cursor position on the surface the painting settings pick.
    std::optional<CanvasColumn> columnUnderCursor(const SceneHost& host, double cursorX, double cursorY,
                                                  const CanvasView& view, const PaintingSettings& painting);

    /// Loads a PNG or JPEG as the draft; throws with the one-line reason, and the previous draft stays.
    const DraftImage& loadDraft(const std::string& path);
    const DraftImage* draft() const { return input_.draft(); } ///< none until one loads

    /// Saves the canvas for undo before an edit that is not a stroke (a digger's drag), so Undo
    /// takes the whole edit back as one step.
    void rememberForUndo(const SceneHost& host) {
        if (host.kind() == sandcore::SceneKind::Canvas) input_.rememberForUndo(host.scene());
    }
    /// Takes back the last stroke; false when there is none.
    bool undo(SceneHost& host);
    /// E3: brings back the last undone stroke; false when there is none or no canvas runs.
    bool redo(SceneHost& host);
    /// Adds a box of INVALID cells (lower-grid cells, max exclusive) to the canvas; returns a
    /// status line (the grains it removed, or why the box is refused).
    std::string addObstacle(SceneHost& host, const std::array<int, 3>& min, const std::array<int, 3>& max);
    /// Removes every obstacle of the canvas.
    void clearObstacles(SceneHost& host);
    /// The scene was rebuilt or reset: ends any stroke and forgets the undo history.
    void sceneReplaced() { input_.sceneReplaced(); }

    /// Where the draft lies over the canvas and how opaque, for the renderer.
    DraftPlacement draftPlacement(const SceneHost& host, const PaintingSettings& painting, float cellSize) const;
    /// The painter's undo depth and memory, for the panel.
    void publishUndoState(PaintingSettings& painting) const;
    /// The stroke settings the panel's choices stand for.
    PaintSettings paintSettings(const PaintingSettings& painting) const;

    const CanvasInput& input() const { return input_; } ///< picker and painter, for tests

private:
    CanvasInput input_;
};

} // namespace sandglass
