// SPDX-License-Identifier: MIT
#include "view/paint/canvas_input.hpp"

namespace sandglass {

std::optional<CanvasColumn> CanvasInput::columnUnderCursor(const sandcore::Scene& scene, double cursorX,
                                                           double cursorY, const CanvasView& view,
                                                           PaintTarget target) {
    PickView pickView;
    pickView.view = view.view;
    pickView.projection = view.projection;
    pickView.width = view.framebufferWidth;
    pickView.height = view.framebufferHeight;
    pickView.surface = canvasSurface(scene, target, view.cellSize);
    picker_.prepare(pickView);
    int pixelX = 0, pixelY = 0;
    cursorToFramebuffer(cursorX, cursorY, view.windowWidth, view.windowHeight, view.framebufferWidth,
                        view.framebufferHeight, pixelX, pixelY);
    return picker_.columnAt(pixelX, pixelY);
}

std::optional<glm::dvec2> cursorOverColumn(const CanvasView& view, const CanvasSurface& surface, CanvasColumn column) {
    const glm::vec4 world(surface.originX + (float(column.x) + 0.5f) * surface.cellSize, surface.y,
                          surface.originZ + (float(column.z) + 0.5f) * surface.cellSize, 1.0f);
    const glm::vec4 clip = view.projection * view.view * world;
    if (clip.w <= 0.0f) return std::nullopt;
    // Normalised device coordinates to framebuffer pixels (y down), then to window units.
    const double pixelX = (double(clip.x / clip.w) * 0.5 + 0.5) * view.framebufferWidth;
    const double pixelY = (0.5 - double(clip.y / clip.w) * 0.5) * view.framebufferHeight;
    const double scaleX = view.windowWidth > 0 ? double(view.framebufferWidth) / view.windowWidth : 1.0;
    const double scaleY = view.windowHeight > 0 ? double(view.framebufferHeight) / view.windowHeight : 1.0;
    return glm::dvec2(pixelX / scaleX, pixelY / scaleY);
}

bool CanvasInput::handlePointer(sandcore::Scene& scene, const PointerSample& sample, const CanvasView& view,
                                const PaintSettings& settings) {
    if (!sample.leftDown) {
        painter_.endStroke();
        return false;
    }
    // A press over a panel or with Alt belongs to ImGui or the camera; a stroke already under
    // way goes on until the button comes up.
    if (!painter_.stroking() && (sample.guiWantsMouse || sample.altHeld)) return false;
    const std::optional<CanvasColumn> column =
        columnUnderCursor(scene, sample.cursorX, sample.cursorY, view, settings.target);
    if (!column) return false;
    const auto edits = [this] { return painter_.grainsReleased() + painter_.grainsErased(); };
    if (!painter_.stroking()) {
        painter_.beginStroke(scene, *column, settings, draft());
        return edits() > 0;
    }
    const std::int64_t before = edits();
    painter_.continueStroke(scene, *column, settings, draft());
    return edits() != before;
}

void CanvasInput::sceneReplaced() {
    painter_.endStroke();
    painter_.clearHistory();
    picker_.invalidate();
}

} // namespace sandglass
