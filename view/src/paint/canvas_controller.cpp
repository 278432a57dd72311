// SPDX-License-Identifier: MIT
#include "view/paint/canvas_controller.hpp"

#include <algorithm>
#include <cmath>

namespace sandglass {

namespace {

std::uint32_t packColor(const std::array<float, 3>& rgb) {
    std::uint32_t packed = 0xff000000u; // opaque, so never 0 ("default sand")
    for (int channel = 0; channel < 3; ++channel) {
        const auto byte = std::uint32_t(std::lround(std::clamp(rgb[std::size_t(channel)], 0.0f, 1.0f) * 255.0f));
        packed |= byte << (8 * channel);
    }
    return packed;
}

bool isCanvas(const SceneHost& host) { return host.kind() == sandcore::SceneKind::Canvas; }

PaintTarget targetOf(const PaintingSettings& painting) {
    return painting.pickAtTarget ? PaintTarget::Bottom : PaintTarget::Top;
}

} // namespace

PaintSettings CanvasController::paintSettings(const PaintingSettings& painting) const {
    PaintSettings settings;
    settings.action = painting.erase ? PaintAction::Erase : PaintAction::Draw;
    settings.target = targetOf(painting);
    settings.thinLines = painting.thinLines;
    settings.brushRadius = std::max(0, painting.brushRadius);
    settings.color = painting.defaultSandColor ? 0u : packColor(painting.sandColor);
    settings.colorFromDraft = painting.colorFromDraft && input_.draft() != nullptr;
    return settings;
}

bool CanvasController::handlePointer(SceneHost& host, const PointerSample& sample, const CanvasView& view,
                                     const PaintingSettings& painting) {
    if (!isCanvas(host) || host.building()) return false;
    // Only a held button may paint; hovering leaves the grains (and their revision) alone.
    if (!sample.leftDown) {
        input_.endStroke();
        return false;
    }
    return input_.handlePointer(host.editScene(), sample, view, paintSettings(painting));
}

std::optional<CanvasColumn> CanvasController::columnUnderCursor(const SceneHost& host, double cursorX, double cursorY,
                                                                const CanvasView& view, const PaintingSettings& painting) {
    if (!isCanvas(host)) return std::nullopt;
    return input_.columnUnderCursor(host.scene(), cursorX, cursorY, view, targetOf(painting));
}

const DraftImage& CanvasController::loadDraft(const std::string& path) {
    input_.setDraft(DraftImage::load(path));
    return *input_.draft();
}

bool CanvasController::undo(SceneHost& host) {
    if (!isCanvas(host) || input_.painter().undoDepth() == 0) return false;
    // A snapshot holds the obstacles too, so an undo may change the layout.
    return input_.undo(host.editLayout());
}

bool CanvasController::redo(SceneHost& host) {
    if (!isCanvas(host) || input_.painter().redoDepth() == 0) return false;
    return input_.redo(host.editLayout());
}

std::string CanvasController::addObstacle(SceneHost& host, const std::array<int, 3>& lo, const std::array<int, 3>& hi) {
    if (!isCanvas(host)) return "obstacles are placed on the canvas";
    if (lo[0] >= hi[0] || lo[1] >= hi[1] || lo[2] >= hi[2]) return "obstacle: each max must be larger than its min";
    const std::int64_t removed =
        host.editLayout().addObstacle(sandcore::GridLevel::Lower, {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}});
    return "obstacle added (" + std::to_string(removed) + " grains inside removed)";
}

void CanvasController::clearObstacles(SceneHost& host) {
    if (isCanvas(host)) host.editLayout().clearObstacles(sandcore::GridLevel::Lower);
}

DraftPlacement CanvasController::draftPlacement(const SceneHost& host, const PaintingSettings& painting,
                                                float cellSize) const {
    const sandcore::Scene& scene = host.scene();
    const bool canvas = isCanvas(host);
    DraftPlacement placement;
    placement.visible = canvas && painting.showDraft && input_.draft() != nullptr;
    const PaintTarget target = targetOf(painting);
    if (canvas) placement.surface = canvasSurface(scene, target, cellSize);
    // Thesis §3.5: half-transparent over the release row, so the sand below stays visible.
    placement.opacity = target == PaintTarget::Top ? 0.5f : 1.0f;
    return placement;
}

void CanvasController::publishUndoState(PaintingSettings& painting) const {
    painting.undoSteps = input_.painter().undoDepth();
    painting.undoBytes = input_.painter().undoBytes();
    painting.redoSteps = input_.painter().redoDepth();
}

} // namespace sandglass
