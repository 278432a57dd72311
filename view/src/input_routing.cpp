// SPDX-License-Identifier: MIT
#include "view/input_routing.hpp"

#include <GLFW/glfw3.h>

#include <cmath>

namespace sandglass {

bool applyMouseDrag(const InputCapture& capture, MouseButton button, bool altHeld, bool leftPaints, float dxPixels,
                    float dyPixels, float viewportHeightPixels, OrbitCamera& camera) {
    if (capture.mouse || (leftPaints && !altHeld) || (dxPixels == 0.0f && dyPixels == 0.0f)) return false;
    switch (button) {
    case MouseButton::Left: camera.rotate(-dxPixels * kRadiansPerPixel, dyPixels * kRadiansPerPixel); return true;
    case MouseButton::Middle: {
        const float height = viewportHeightPixels > 1.0f ? viewportHeightPixels : 1.0f;
        camera.pan(-dxPixels / height, dyPixels / height);
        return true;
    }
    case MouseButton::Right: camera.zoom(std::exp(dyPixels * 0.005f)); return true;
    }
    return false;
}

bool applyScroll(const InputCapture& capture, float wheelSteps, OrbitCamera& camera) {
    if (capture.mouse || wheelSteps == 0.0f) return false;
    camera.zoom(std::pow(0.9f, wheelSteps));
    return true;
}

KeyCommand keyCommand(const InputCapture& capture, int glfwKey, int glfwModifiers) {
    if (capture.keyboard) return KeyCommand::None;
    if (glfwModifiers & GLFW_MOD_CONTROL) {
        if (glfwKey == GLFW_KEY_Z) return (glfwModifiers & GLFW_MOD_SHIFT) ? KeyCommand::Redo : KeyCommand::Undo;
        if (glfwKey == GLFW_KEY_Y) return KeyCommand::Redo;
        if (glfwKey == GLFW_KEY_S) return KeyCommand::Save;
        if (glfwKey == GLFW_KEY_O) return KeyCommand::Open;
    }
    switch (glfwKey) {
    case GLFW_KEY_SPACE: return KeyCommand::ToggleGui;
    case GLFW_KEY_F1: return KeyCommand::Help;
    case GLFW_KEY_F: return KeyCommand::PrintFrameRate;
    case GLFW_KEY_B: return KeyCommand::RunBenchmark;
    case GLFW_KEY_ESCAPE: return KeyCommand::Quit;
    case GLFW_KEY_P: return KeyCommand::Screenshot;
    case GLFW_KEY_T: return KeyCommand::Flip;
    case GLFW_KEY_LEFT: return KeyCommand::RotateLeft;
    case GLFW_KEY_RIGHT: return KeyCommand::RotateRight;
    case GLFW_KEY_UP: return KeyCommand::RotateUp;
    case GLFW_KEY_DOWN: return KeyCommand::RotateDown;
    case GLFW_KEY_1: case GLFW_KEY_KP_1: return KeyCommand::ViewPerspective;
    case GLFW_KEY_2: case GLFW_KEY_KP_2: return KeyCommand::ViewFront;
    case GLFW_KEY_3: case GLFW_KEY_KP_3: return KeyCommand::ViewTop;
    default: return KeyCommand::None;
    }
}

KeyCommand characterCommand(const InputCapture& capture, unsigned codepoint) {
    // '#', '+', '-' and '?' sit on different keys per keyboard layout, so they come as characters.
    if (capture.keyboard) return KeyCommand::None;
    switch (codepoint) {
    case '#': return KeyCommand::PrintFilledCells;
    case '+': return KeyCommand::ZoomIn;
    case '-': return KeyCommand::ZoomOut;
    case '?': return KeyCommand::Help;
    default: return KeyCommand::None;
    }
}

bool applyCameraCommand(KeyCommand command, OrbitCamera& camera) {
    constexpr float step = 0.08f; // radians per key press or repeat
    switch (command) {
    case KeyCommand::RotateLeft: camera.rotate(-step, 0.0f); return true;
    case KeyCommand::RotateRight: camera.rotate(step, 0.0f); return true;
    case KeyCommand::RotateUp: camera.rotate(0.0f, step); return true;
    case KeyCommand::RotateDown: camera.rotate(0.0f, -step); return true;
    case KeyCommand::ZoomIn: camera.zoom(0.9f); return true;
    case KeyCommand::ZoomOut: camera.zoom(1.0f / 0.9f); return true;
    case KeyCommand::ViewPerspective: camera.setView(CameraView::Perspective); return true;
    case KeyCommand::ViewFront: camera.setView(CameraView::Front); return true;
    case KeyCommand::ViewTop: camera.setView(CameraView::Top); return true;
    default: return false;
    }
}

} // namespace sandglass
