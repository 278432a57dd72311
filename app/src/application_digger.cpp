// SPDX-License-Identifier: MIT
// The digger tool: a blade, box or ball dragged through the canvas's sand with the mouse or
// driven with the arrow keys (sandcore's moving bodies push the sand out of its way).
#include "app/application.hpp"

#include "scene/canvas_surface.hpp"
#include "scene/digger.hpp"

#include "sandcore/scenes.hpp"

#include <algorithm>

namespace sandglass {

namespace {

// Unit moves a frame while dragging: the body follows the cursor without stalling the frame.
constexpr int kDiggerCellsPerFrame = 4;

const char* const kDiggerBodies[] = {"blade", "box", "ball"};

} // namespace

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
        if (scene().bodies().empty()) {
            const int width = scene().grid(sandcore::GridLevel::Lower).size().x;
            const int bed = sandcore::defaultSandboxBedDepth(sandcore::canvasSettingsForWidth(width));
            const sandcore::InsideMask shape = makeDigBodyShape(kDiggerBodies[std::clamp(digger.body, 0, 2)], width, bed);
            if (host_.editLayout().addBody({shape, {column->x, digger.depth, column->z}, digger.heading & 3}) < 0)
                state_.statusLine = "the digger does not fit there";
        }
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
    if (!state_.digger.active || scene().kind() != sandcore::SceneKind::Canvas || scene().bodies().empty()) return false;
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
