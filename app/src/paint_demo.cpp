// SPDX-License-Identifier: MIT
#include "app/paint_demo.hpp"

#include <cstdlib>

namespace sandglass {

namespace {
bool isBackground(std::uint32_t rgba, std::uint32_t background) {
    int difference = 0;
    for (int shift = 0; shift < 24; shift += 8)
        difference += std::abs(int((rgba >> shift) & 255u) - int((background >> shift) & 255u));
    return difference < 60;
}
} // namespace

std::int64_t paintDraftDemo(Application& app, int passes) {
    const DraftImage* draft = app.canvas().draft();
    if (!draft || app.host().kind() != sandcore::SceneKind::Canvas) return 0;
    PaintingSettings& painting = app.state().painting;
    painting.erase = false;
    painting.pickAtTarget = false;
    painting.thinLines = true; // one grain per column per pass: the layers build the heaps
    painting.brushRadius = 0;
    painting.colorFromDraft = true;
    const std::uint32_t background = draft->colorAt(0.0, 0.0);
    const CanvasView view = app.canvasView();
    const CanvasSurface surface = canvasSurface(app.scene(), PaintTarget::Top, view.cellSize);
    const std::int64_t before = app.scene().grainCount();
    auto press = [&](CanvasColumn column, bool down) {
        if (const auto cursor = cursorOverColumn(view, surface, column))
            app.handleCanvasPointer({cursor->x, cursor->y, down, false, false});
    };
    for (int pass = 0; pass < passes; ++pass) {
        for (int z = 0; z < surface.columnsZ; ++z) {
            int x = 0;
            while (x < surface.columnsX) {
                auto inDrawing = [&](int column) {
                    return !isBackground(draft->colorAt((column + 0.5) / surface.columnsX, (z + 0.5) / surface.columnsZ),
                                         background);
                };
                if (!inDrawing(x)) {
                    ++x;
                    continue;
                }
                const int start = x;
                while (x + 1 < surface.columnsX && inDrawing(x + 1)) ++x;
                press({start, z}, true); // a stroke along the span: down, drag to its end, up
                press({x, z}, true);
                press({x, z}, false);
                ++x;
            }
        }
        app.runSteps(1); // the new grains move, so "settled" means this layer came to rest
        for (int step = 0; step < 1000 && !app.scene().settled(); ++step) app.runSteps(1);
    }
    painting.showDraft = false;
    return app.scene().grainCount() - before;
}

} // namespace sandglass
