// The canvas side of the application (SPEC P1-P7, G2 obstacles): the mouse path into the
// painter, the painting commands the panels raise, and where the draft is shown.
#include "app/application.hpp"

#include <GLFW/glfw3.h>

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
} // namespace

CanvasView Application::canvasView() const {
    CanvasView view;
    targetSize(view.framebufferWidth, view.framebufferHeight);
    glfwGetWindowSize(window_.handle(), &view.windowWidth, &view.windowHeight);
    const float aspect = view.framebufferHeight > 0 ? float(view.framebufferWidth) / float(view.framebufferHeight) : 1.0f;
    view.view = camera_.view();
    view.projection = camera_.projection(aspect);
    view.cellSize = state_.render.cellSize;
    return view;
}

PaintSettings Application::paintSettings() const {
    const PaintingSettings& painting = state_.painting;
    PaintSettings settings;
    settings.action = painting.erase ? PaintAction::Erase : PaintAction::Draw;
    settings.target = painting.pickAtTarget ? PaintTarget::Bottom : PaintTarget::Top;
    settings.thinLines = painting.thinLines;
    settings.brushRadius = std::max(0, painting.brushRadius);
    settings.color = painting.defaultSandColor ? 0u : packColor(painting.sandColor);
    settings.colorFromDraft = painting.colorFromDraft && canvasInput_.draft() != nullptr;
    return settings;
}

std::optional<CanvasColumn> Application::columnUnderCursor(double cursorX, double cursorY) {
    if (scene_->kind() != sandcore::SceneKind::Canvas) return std::nullopt;
    return canvasInput_.columnUnderCursor(*scene_, cursorX, cursorY, canvasView(), paintSettings().target);
}

bool Application::handleCanvasPointer(const PointerSample& sample) {
    if (scene_->kind() != sandcore::SceneKind::Canvas || pendingScene_.valid()) return false;
    const bool changed = canvasInput_.handlePointer(*scene_, sample, canvasView(), paintSettings());
    if (changed) renderer_.sceneChanged();
    state_.painting.undoSteps = canvasInput_.painter().undoDepth();
    state_.painting.undoBytes = canvasInput_.painter().undoBytes();
    return changed;
}

bool Application::loadDraft(const std::string& path) {
    try {
        DraftImage draft = DraftImage::load(path);
        renderer_.setDraftImage(draft);
        canvasInput_.setDraft(std::move(draft));
        state_.painting.loadedDraft = path;
        state_.painting.draftPath = path;
        state_.painting.showDraft = true;
        state_.statusLine = "draft " + path;
        return true;
    } catch (const std::exception& error) {
        state_.statusLine = error.what(); // the previous draft, if any, stays in use
        return false;
    }
}

void Application::runSteps(int steps) {
    for (int i = 0; i < steps; ++i) scene_->step();
    if (steps <= 0) return;
    lastStepOutsideClock_ = true;
    renderer_.sceneChanged();
}

void Application::servePaintingCommands() {
    PendingCommands& pending = state_.pending;
    PaintingSettings& painting = state_.painting;
    if (pending.loadDraft) loadDraft(painting.draftPath);
    pending.loadDraft = false;
    const bool canvas = scene_->kind() == sandcore::SceneKind::Canvas;
    if (pending.undo && canvas) {
        if (canvasInput_.undo(*scene_)) {
            // A snapshot holds the obstacles too; the hull only needs rebuilding when they differ
            // (the boxes themselves: clearing one obstacle and adding another keeps the count).
            if (!renderer_.hullShowsObstaclesOf(*scene_)) renderer_.setScene(*scene_, state_.render.cellSize);
            renderer_.sceneChanged();
            state_.statusLine = "undone";
        } else {
            state_.statusLine = "nothing to undo";
        }
    }
    pending.undo = false;
    if (pending.addObstacle && canvas) {
        const auto& lo = painting.obstacleMin;
        const auto& hi = painting.obstacleMax;
        if (lo[0] >= hi[0] || lo[1] >= hi[1] || lo[2] >= hi[2]) {
            state_.statusLine = "obstacle: each max must be larger than its min";
        } else {
            const std::int64_t removed = scene_->addObstacle(sandcore::GridLevel::Lower,
                                                             {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}});
            renderer_.setScene(*scene_, state_.render.cellSize); // the hull shows the new box
            state_.statusLine = "obstacle added (" + std::to_string(removed) + " grains inside removed)";
        }
    }
    pending.addObstacle = false;
    if (pending.clearObstacles && canvas) {
        scene_->clearObstacles(sandcore::GridLevel::Lower);
        renderer_.setScene(*scene_, state_.render.cellSize);
        state_.statusLine = "obstacles removed";
    }
    pending.clearObstacles = false;
    painting.undoSteps = canvasInput_.painter().undoDepth();
    painting.undoBytes = canvasInput_.painter().undoBytes();
}

void Application::updateDraftPlacement() {
    const bool canvas = scene_->kind() == sandcore::SceneKind::Canvas;
    DraftPlacement placement;
    placement.visible = canvas && state_.painting.showDraft && canvasInput_.draft() != nullptr;
    const PaintTarget target = state_.painting.pickAtTarget ? PaintTarget::Bottom : PaintTarget::Top;
    if (canvas) placement.surface = canvasSurface(*scene_, target, state_.render.cellSize);
    // Thesis §3.5: half-transparent over the release row, so the sand below stays visible.
    placement.opacity = target == PaintTarget::Top ? 0.5f : 1.0f;
    renderer_.setDraftPlacement(placement);
}

} // namespace sandglass
