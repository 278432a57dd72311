// SPDX-License-Identifier: MIT
// The digger tool: a blade, box or ball dragged through the canvas's sand with the mouse or
// driven with the arrow keys (sandcore's moving bodies push the sand out of its way).
#include "app/application.hpp"

#include "scene/canvas_surface.hpp"
#include "scene/digger.hpp"

#include "sandcore/scenes.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>

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

// The body's box of cells drawn as a shaded solid over the scene: its faces that look at the
// camera filled, lit from above, and outlined.
void Application::drawDigger() {
    if (scene().bodies().empty()) return;
    const std::vector<std::uint32_t> cells = scene().bodyCells(0);
    if (cells.empty()) return;
    const sandcore::CellGrid& grid = scene().grid(sandcore::GridLevel::Lower);
    sandcore::Int3 low = grid.coordinate(cells.front()), high = low;
    for (std::uint32_t n : cells) {
        const sandcore::Int3 c = grid.coordinate(n);
        low = {std::min(low.x, c.x), std::min(low.y, c.y), std::min(low.z, c.z)};
        high = {std::max(high.x, c.x), std::max(high.y, c.y), std::max(high.z, c.z)};
    }
    const CanvasView view = canvasView();
    const CanvasSurface floor = canvasSurface(scene(), PaintTarget::Bottom, view.cellSize);
    const float x0 = floor.originX + float(low.x) * floor.cellSize, x1 = floor.originX + float(high.x + 1) * floor.cellSize;
    const float y0 = floor.y + float(low.y) * floor.cellSize, y1 = floor.y + float(high.y + 1) * floor.cellSize;
    const float z0 = floor.originZ + float(low.z) * floor.cellSize, z1 = floor.originZ + float(high.z + 1) * floor.cellSize;
    const glm::mat4 toClip = view.projection * view.view;
    const float toWindowX = view.framebufferWidth > 0 ? float(view.windowWidth) / float(view.framebufferWidth) : 1.0f;
    const float toWindowY = view.framebufferHeight > 0 ? float(view.windowHeight) / float(view.framebufferHeight) : 1.0f;
    std::array<ImVec2, 8> corner;
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 clip = toClip * glm::vec4(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0, 1.0f);
        if (clip.w <= 0.0f) return;
        corner[std::size_t(i)] = ImVec2((clip.x / clip.w * 0.5f + 0.5f) * float(view.framebufferWidth) * toWindowX,
                                        (0.5f - clip.y / clip.w * 0.5f) * float(view.framebufferHeight) * toWindowY);
    }
    // Faces as corner indices, counter-clockwise seen from outside, with their shade.
    struct Face {
        int a, b, c, d;
        int shade;
    };
    const Face faces[] = {{2, 6, 7, 3, 235}, {0, 1, 5, 4, 90},  {0, 4, 6, 2, 150},
                          {1, 3, 7, 5, 170}, {0, 2, 3, 1, 130}, {4, 5, 7, 6, 200}};
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    for (const Face& f : faces) {
        const ImVec2 &a = corner[std::size_t(f.a)], &b = corner[std::size_t(f.b)], &c = corner[std::size_t(f.c)];
        const float turn = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (turn >= 0.0f) continue; // faces away (screen y points down)
        const int s = f.shade;
        draw->AddQuadFilled(a, b, c, corner[std::size_t(f.d)], IM_COL32(s * 40 / 100, s * 55 / 100, s * 75 / 100, 235));
        draw->AddQuad(a, b, c, corner[std::size_t(f.d)], IM_COL32(20, 30, 45, 255), 1.5f);
    }
}

} // namespace sandglass
