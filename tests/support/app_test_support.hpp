// SPDX-License-Identifier: MIT
#pragma once
// What the window tests share: opening an offscreen Application (or saying why not), canvas
// options, and reading pixels of a captured frame.

#include "support/display_guard.hpp"

#include "app/application.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace sandglass::testing {

/// A pixel of a square frame, x to the right, y down.
struct ScreenPoint {
    int x, y;
};

/// Where the world point lands on the application's square frame of `size` pixels.
inline ScreenPoint projectToFrame(Application& app, glm::vec3 world, int size) {
    const glm::mat4 viewProjection = app.camera().projection(1.0f) * app.camera().view();
    const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
    return {int((clip.x / clip.w * 0.5f + 0.5f) * float(size)), int((0.5f - clip.y / clip.w * 0.5f) * float(size))};
}

/// An Application with these options, or nothing when no OpenGL 3.3 context can be made
/// (reported through cannotDraw: a failure in CI); `what` names what then goes unchecked.
inline std::optional<Application> openApplication(ApplicationOptions options, std::string_view what) {
    try {
        return std::optional<Application>(std::in_place, std::move(options));
    } catch (const WindowError& error) {
        cannotDraw("no OpenGL 3.3 context (" + std::string(error.what()) + "): " + std::string(what) + " not checked");
        return std::nullopt;
    }
}

/// As openApplication, into an existing optional (an Application cannot be moved); false when
/// no context could be made.
inline bool openApplicationInto(std::optional<Application>& app, ApplicationOptions options, std::string_view what) {
    try {
        app.emplace(std::move(options));
        return true;
    } catch (const WindowError& error) {
        cannotDraw("no OpenGL 3.3 context (" + std::string(error.what()) + "): " + std::string(what) + " not checked");
        return false;
    }
}

/// A hidden, offscreen window of width x height pixels, panels off, on a scene of this kind and
/// resolution built without a model file.
inline ApplicationOptions hiddenWindowOptions(int width, int height, sandcore::SceneKind kind, int resolution,
                                              const char* title) {
    ApplicationOptions options;
    options.window = {width, height, false, false, title};
    options.offscreen = true;
    options.initial.showGui = false;
    options.initial.scene.request.kind = kind;
    options.initial.scene.request.modelPath.clear();
    options.initial.scene.request.resolution = resolution;
    return options;
}

/// A hidden, offscreen window of width x height pixels on an empty canvas, panels off.
inline ApplicationOptions canvasOptions(int width, int height, int resolution, const char* title) {
    return hiddenWindowOptions(width, height, sandcore::SceneKind::Canvas, resolution, title);
}

/// A hidden, offscreen window of width x height pixels on the procedural hourglass (no model
/// file), panels off.
inline ApplicationOptions proceduralHourglassOptions(int width, int height, int resolution, const char* title) {
    ApplicationOptions options = hiddenWindowOptions(width, height, sandcore::SceneKind::Hourglass, resolution, title);
    options.initial.scene.request.shape = "hourglass";
    return options;
}

/// One pixel of a captured frame, 0..255 per channel.
struct Pixel {
    int r, g, b;
};

/// The pixel at (x, y) of a frame, y from the top row.
inline Pixel pixelAt(const RgbImage& image, int x, int y) {
    const std::size_t i = (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 3;
    return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

/// The channel values in which two frames differ; frames of different sizes differ in all of them.
inline std::size_t differentPixels(const RgbImage& a, const RgbImage& b) {
    if (a.pixels.size() != b.pixels.size()) return std::max(a.pixels.size(), b.pixels.size());
    std::size_t different = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) different += a.pixels[i] != b.pixels[i] ? 1 : 0;
    return different;
}

} // namespace sandglass::testing
