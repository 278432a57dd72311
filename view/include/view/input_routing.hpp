// SPDX-License-Identifier: MIT
#pragma once
// Where keyboard and mouse input goes (SPEC G3): to ImGui when it wants it, else to the camera
// or an application command. Pure functions of the input and ImGui's capture flags, so the
// rule "input ImGui wants never moves the camera" is tested without a window.

#include "view/camera.hpp"

namespace sandglass {

/// ImGui's wishes for this frame (io.WantCaptureMouse / io.WantCaptureKeyboard).
struct InputCapture {
    bool mouse = false;    ///< a panel is under the mouse or being dragged
    bool keyboard = false; ///< a text field or navigation has the keyboard
};

enum class MouseButton { Left, Middle, Right };

/// Thesis §3.6 keys, plus the screenshot key.
enum class KeyCommand {
    None,
    ToggleGui,         ///< Space
    PrintFilledCells,  ///< #
    PrintFrameRate,    ///< F
    RunBenchmark,      ///< B
    Quit,              ///< Esc
    Screenshot,        ///< P
    Undo,              ///< Ctrl+Z: take back the last stroke (P7)
    Flip,              ///< T: turn the hourglass over
    Redo,              ///< Ctrl+Y or Ctrl+Shift+Z: bring back the last undone stroke (E3)
    Save,              ///< Ctrl+S: save the state (E1)
    Open,              ///< Ctrl+O: open a saved state (E1)
    Help,              ///< F1 or ?: show or hide the keys and mouse controls
    RotateLeft, RotateRight, RotateUp, RotateDown, ///< arrow keys
    ZoomIn, ZoomOut,   ///< + and -
    ViewPerspective,   ///< 1
    ViewFront,         ///< 2
    ViewTop,           ///< 3
};

/// Rotation per pixel of Alt + left drag, radians.
inline constexpr float kRadiansPerPixel = 0.008f;

/// Applies a mouse move of (dx, dy) pixels with `button` held to the camera: left rotates,
/// middle pans, right zooms. Where the left button paints (the canvas) these need Alt held;
/// elsewhere a plain drag does it. Returns true when the camera moved; never when ImGui wants
/// the mouse.
bool applyMouseDrag(const InputCapture& capture, MouseButton button, bool altHeld, bool leftPaints, float dxPixels,
                    float dyPixels, float viewportHeightPixels, OrbitCamera& camera);
/// Mouse wheel zoom by `wheelSteps` notches (positive = closer); false when ImGui wants the mouse.
bool applyScroll(const InputCapture& capture, float wheelSteps, OrbitCamera& camera);
/// The command of a GLFW key press (GLFW_KEY_*, modifiers GLFW_MOD_*); None when ImGui wants the keyboard.
KeyCommand keyCommand(const InputCapture& capture, int glfwKey, int glfwModifiers = 0);
/// The command of a typed character ('#', '+', '-'); None when ImGui wants the keyboard.
KeyCommand characterCommand(const InputCapture& capture, unsigned codepoint);
/// Applies a camera command (arrows, zoom, views); returns false for any other command.
bool applyCameraCommand(KeyCommand command, OrbitCamera& camera);

} // namespace sandglass
