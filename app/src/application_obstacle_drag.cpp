// SPDX-License-Identifier: MIT
// Obstacles placed with the mouse: after "Place with the mouse" the next left drag on the
// canvas floor outlines a box, and letting go adds it, with the height of the typed form.
#include "app/application.hpp"

#include "scene/canvas_surface.hpp"

#include <imgui.h>

#include <algorithm>

namespace sandglass {

void Application::handleObstacleDrag(double x, double y, bool leftDown, const InputCapture& capture) {
    ObstacleDrag& drag = state_.obstacleDrag;
    PaintingSettings onFloor = state_.painting;
    onFloor.pickAtTarget = true; // obstacles stand on the lower grid's floor
    const std::optional<CanvasColumn> column = canvas_.columnUnderCursor(host_, x, y, canvasView(), onFloor);
    if (!drag.dragging) {
        if (!leftDown || capture.mouse || !column) return;
        drag.dragging = true;
        drag.startX = drag.endX = column->x;
        drag.startZ = drag.endZ = column->z;
        return;
    }
    if (column) {
        drag.endX = column->x;
        drag.endZ = column->z;
    }
    if (leftDown) return;
    drag.dragging = false;
    drag.armed = false;
    PaintingSettings& painting = state_.painting;
    painting.obstacleMin[0] = std::min(drag.startX, drag.endX);
    painting.obstacleMin[2] = std::min(drag.startZ, drag.endZ);
    painting.obstacleMax[0] = std::max(drag.startX, drag.endX) + 1;
    painting.obstacleMax[2] = std::max(drag.startZ, drag.endZ) + 1;
    state_.commands.push(Command::AddObstacle);
}

void Application::drawObstacleBox() {
    const ObstacleDrag& drag = state_.obstacleDrag;
    if (!drag.dragging) return;
    const CanvasView view = canvasView();
    const CanvasSurface floor = canvasSurface(scene(), PaintTarget::Bottom, view.cellSize);
    const float x0 = floor.originX + float(std::min(drag.startX, drag.endX)) * floor.cellSize;
    const float x1 = floor.originX + float(std::max(drag.startX, drag.endX) + 1) * floor.cellSize;
    const float z0 = floor.originZ + float(std::min(drag.startZ, drag.endZ)) * floor.cellSize;
    const float z1 = floor.originZ + float(std::max(drag.startZ, drag.endZ) + 1) * floor.cellSize;
    const glm::mat4 toClip = view.projection * view.view;
    const float toWindowX = view.framebufferWidth > 0 ? float(view.windowWidth) / float(view.framebufferWidth) : 1.0f;
    const float toWindowY = view.framebufferHeight > 0 ? float(view.windowHeight) / float(view.framebufferHeight) : 1.0f;
    const float corners[4][2] = {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}};
    ImVec2 points[4];
    for (int i = 0; i < 4; ++i) {
        const glm::vec4 clip = toClip * glm::vec4(corners[i][0], floor.y, corners[i][1], 1.0f);
        if (clip.w <= 0.0f) return;
        points[i] = ImVec2((clip.x / clip.w * 0.5f + 0.5f) * float(view.framebufferWidth) * toWindowX,
                           (0.5f - clip.y / clip.w * 0.5f) * float(view.framebufferHeight) * toWindowY);
    }
    ImGui::GetForegroundDrawList()->AddPolyline(points, 4, IM_COL32(30, 90, 220, 255), ImDrawFlags_Closed, 3.0f);
}

} // namespace sandglass
