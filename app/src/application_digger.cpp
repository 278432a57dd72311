// SPDX-License-Identifier: MIT
// The digger tool: a blade, box, ball or voxelized model dragged through the canvas's sand with the mouse or
// driven with the arrow keys (sandcore's moving bodies push the sand out of its way).
#include "app/application.hpp"

#include "scene/canvas_surface.hpp"
#include "scene/digger.hpp"

#include "sandcore/scenes.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

namespace sandglass {

namespace {

// Unit moves a frame while dragging: the body follows the cursor without stalling the frame.
constexpr int kDiggerCellsPerFrame = 4;

const char* const kDiggerBodies[] = {"blade", "box", "ball"};
constexpr int kModelBody = 3; // DiggerSettings::body for the model file

bool sameCells(const sandcore::InsideMask& a, const sandcore::InsideMask& b) {
    return a.size == b.size && a.inside == b.inside;
}

} // namespace

bool Application::loadDiggerBody(const std::string& path) {
    DiggerSettings& digger = state_.digger;
    try {
        const int width = scene().grid(sandcore::GridLevel::Lower).size().x;
        sandcore::InsideMask shape = digBodyFromModel(path, width);
        state_.statusLine = "digger body " + path + ": " + std::to_string(shape.size.x) + " x " +
                            std::to_string(shape.size.y) + " x " + std::to_string(shape.size.z) +
                            " cells, placed at the next drag";
        diggerModel_ = std::move(shape);
        digger.loadedModel = path;
        digger.modelPath = path;
        digger.body = kModelBody;
        return true;
    } catch (const std::exception& error) {
        state_.statusLine = std::string("digger body: ") + error.what(); // the body chosen before stays
        return false;
    }
}

std::optional<sandcore::InsideMask> Application::chosenDiggerShape() {
    const DiggerSettings& digger = state_.digger;
    if (digger.body == kModelBody) {
        if (!diggerModel_) state_.statusLine = "choose a model file for the digger's body first";
        return diggerModel_;
    }
    const int width = scene().grid(sandcore::GridLevel::Lower).size().x;
    const int bed = sandcore::defaultSandboxBedDepth(sandcore::canvasSettingsForWidth(width));
    return makeDigBodyShape(kDiggerBodies[std::clamp(digger.body, 0, 2)], width, bed);
}

void Application::keepDiggerAsSet() {
    DiggerSettings& digger = state_.digger;
    if (scene().bodies().empty()) return;
    const sandcore::MovingBody& body = scene().bodies().front();
    if (body.quarterTurns != (digger.heading & 3)) host_.editLayout().turnBody(0, digger.heading);
    const sandcore::Int3 at = scene().bodies().front().position;
    if (at.y != digger.depth) host_.editLayout().moveBody(0, {at.x, digger.depth, at.z}, kDiggerCellsPerFrame);
}

void Application::handleDiggerDrag(double x, double y, bool leftDown, const InputCapture& capture) {
    DiggerSettings& digger = state_.digger;
    PaintingSettings onFloor = state_.painting;
    onFloor.pickAtTarget = true; // the body moves over the lower grid's floor
    const std::optional<CanvasColumn> column = canvas_.columnUnderCursor(host_, x, y, canvasView(), onFloor);
    if (!digger.dragging) {
        keepDiggerAsSet();
        if (!leftDown || capture.mouse || !column) return;
        digger.dragging = true;
        canvas_.rememberForUndo(host_); // the whole drag is one undo step
        ++state_.files.unsavedEdits;
        // A body of another shape than the panel's gives way to the panel's, placed here.
        std::optional<sandcore::InsideMask> shape = chosenDiggerShape();
        const bool otherShape = shape && !scene().bodies().empty() && !sameCells(scene().bodies().front().shape, *shape);
        if (otherShape) host_.editLayout().removeBody(0);
        if (shape && scene().bodies().empty() &&
            host_.editLayout().addBody({std::move(*shape), {column->x, digger.depth, column->z}, digger.heading & 3}) < 0)
            state_.statusLine = "the digger does not fit there";
        canvas_.publishUndoState(state_.painting);
        return;
    }
    if (!leftDown) {
        digger.dragging = false;
        return;
    }
    if (column && !scene().bodies().empty())
        host_.editLayout().moveBody(0, {column->x, digger.depth, column->z}, kDiggerCellsPerFrame);
}

bool Application::driveDiggerByKey(KeyCommand command) {
    if (!state_.digger.active || host_.kind() != sandcore::SceneKind::Canvas || scene().bodies().empty()) return false;
    sandcore::Int3 to = scene().bodies().front().position;
    switch (command) {
    case KeyCommand::RotateLeft: --to.x; break;
    case KeyCommand::RotateRight: ++to.x; break;
    case KeyCommand::RotateUp: --to.z; break;
    case KeyCommand::RotateDown: ++to.z; break;
    default: return false;
    }
    host_.editLayout().moveBody(0, to, 1);
    ++state_.files.unsavedEdits;
    return true;
}

} // namespace sandglass
