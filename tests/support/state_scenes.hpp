// SPDX-License-Identifier: MIT
#pragma once
// The three scene kinds as the state file and export tests use them: small, with sand moving.

#include "scene/sand_painter.hpp"
#include "scene/scene_request.hpp"

#include "sandcore/scenes.hpp"

namespace support {

/// A procedural hourglass of height 32.
inline sandglass::SceneRequest hourglassRequest() {
    sandglass::SceneRequest request;
    request.kind = sandcore::SceneKind::Hourglass;
    request.shape = "hourglass";
    request.resolution = 32;
    return request;
}

/// A sphere sculpture 20 cells across.
inline sandglass::SceneRequest sculptureRequest() {
    sandglass::SceneRequest request;
    request.kind = sandcore::SceneKind::Sculpture;
    request.shape = "sphere";
    request.resolution = 20;
    return request;
}

/// A 24-wide canvas.
inline sandglass::SceneRequest canvasRequest() {
    sandglass::SceneRequest request;
    request.kind = sandcore::SceneKind::Canvas;
    request.resolution = 24;
    return request;
}

/// A canvas with two obstacles and strokes of red, draft-less default and blue sand, some of it
/// still falling.
inline sandcore::Scene paintedCanvas(std::uint64_t seed = 7) {
    sandcore::StepSettings step;
    step.seed = seed;
    sandcore::Scene scene = sandglass::buildScene({canvasRequest(), step});
    scene.addObstacle(sandcore::GridLevel::Lower, {{4, 0, 4}, {10, 6, 9}});
    scene.addObstacle(sandcore::GridLevel::Lower, {{14, 2, 12}, {20, 3, 22}});
    sandglass::SandPainter painter;
    sandglass::PaintSettings paint;
    paint.brushRadius = 2;
    const std::uint32_t colours[] = {0xff2020e0u, 0u, 0xffe03010u};
    for (int stroke = 0; stroke < 3; ++stroke) {
        paint.color = colours[stroke];
        painter.beginStroke(scene, {3 + 6 * stroke, 5}, paint);
        for (int i = 0; i < 12; ++i) {
            scene.step();
            painter.continueStroke(scene, {3 + 6 * stroke + i / 3, 5 + i}, paint);
        }
        painter.endStroke();
    }
    return scene;
}

} // namespace support

namespace support {
/// A scene built from a request and step settings.
inline sandcore::Scene build(const sandglass::SceneRequest& request, const sandcore::StepSettings& step = {}) {
    return sandglass::buildScene({request, step});
}
} // namespace support
