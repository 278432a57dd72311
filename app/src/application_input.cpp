// SPDX-License-Identifier: MIT
// The application's input: GLFW's callbacks (keys, characters, scroll, buttons, drops, closing)
// routed past ImGui, the mouse each frame (camera drags, the canvas's strokes, obstacle
// placement) and the keys' commands.
#include "app/application.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <cstdio>
#include <utility>

namespace sandglass {

// GLFW calls plain functions; they find the application through the window's user pointer and
// forward every event to ImGui before routing it (ImGui's capture flags decide).
struct ApplicationCallbacks {
    static Application& of(GLFWwindow* window) { return *static_cast<Application*>(glfwGetWindowUserPointer(window)); }
    static InputCapture capture() {
        const ImGuiIO& io = ImGui::GetIO();
        return {io.WantCaptureMouse, io.WantCaptureKeyboard};
    }
    static void key(GLFWwindow* window, int key, int scancode, int action, int mods) {
        ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
        if (action == GLFW_RELEASE) return;
        const KeyCommand command = keyCommand(capture(), key, mods);
        if (of(window).driveDiggerByKey(command)) return; // the arrows drive the digger while it is on
        const bool cameraKey = applyCameraCommand(command, of(window).camera_);
        if (!cameraKey && action == GLFW_PRESS) of(window).handleKey(command);
    }
    static void character(GLFWwindow* window, unsigned codepoint) {
        ImGui_ImplGlfw_CharCallback(window, codepoint);
        const KeyCommand command = characterCommand(capture(), codepoint);
        if (!applyCameraCommand(command, of(window).camera_)) of(window).handleKey(command);
    }
    static void scroll(GLFWwindow* window, double x, double y) {
        ImGui_ImplGlfw_ScrollCallback(window, x, y);
        applyScroll(capture(), float(y), of(window).camera_);
    }
    static void mouseButton(GLFWwindow* window, int button, int action, int mods) {
        ImGui_ImplGlfw_MouseButtonCallback(window, button, action, mods);
        // Every press and release is kept, so clicks between two slow frames all count.
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window, &x, &y);
        of(window).queueMouseButton(button, action == GLFW_PRESS, x, y);
    }
    static void close(GLFWwindow* window) {
        // The window's close button asks first too, when there are unsaved edits (U5).
        if (of(window).state_.files.unsavedEdits == 0) return;
        glfwSetWindowShouldClose(window, GLFW_FALSE);
        of(window).state_.files.confirmQuit = true; // a second click keeps the question up
    }
    static void focus(GLFWwindow* window, int focused) { ImGui_ImplGlfw_WindowFocusCallback(window, focused); }
    static void enter(GLFWwindow* window, int entered) { ImGui_ImplGlfw_CursorEnterCallback(window, entered); }
    static void drop(GLFWwindow* window, int count, const char** paths) {
        if (count < 1) return;
        of(window).openFile(paths[0]);
    }
};

void Application::installInputCallbacks() {
    GLFWwindow* handle = window_.handle();
    glfwSetWindowUserPointer(handle, this);
    glfwSetKeyCallback(handle, ApplicationCallbacks::key);
    glfwSetCharCallback(handle, ApplicationCallbacks::character);
    glfwSetScrollCallback(handle, ApplicationCallbacks::scroll);
    glfwSetMouseButtonCallback(handle, ApplicationCallbacks::mouseButton);
    glfwSetWindowFocusCallback(handle, ApplicationCallbacks::focus);
    glfwSetCursorEnterCallback(handle, ApplicationCallbacks::enter);
    glfwSetDropCallback(handle, ApplicationCallbacks::drop);
    glfwSetWindowCloseCallback(handle, ApplicationCallbacks::close);
}

void Application::queueMouseButton(int button, bool pressed, double x, double y) {
    imgui_.queueMouseTransition({button, pressed, x, y});
}

void Application::handleMouse() {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_.handle(), &x, &y);
    const float dx = float(x - lastCursorX_), dy = float(y - lastCursorY_);
    lastCursorX_ = x;
    lastCursorY_ = y;
    GLFWwindow* handle = window_.handle();
    const bool alt = glfwGetKey(handle, GLFW_KEY_LEFT_ALT) == GLFW_PRESS || glfwGetKey(handle, GLFW_KEY_RIGHT_ALT) == GLFW_PRESS;
    const InputCapture capture = ApplicationCallbacks::capture();
    int width = 0, height = 0;
    glfwGetWindowSize(handle, &width, &height);
    const std::pair<int, MouseButton> buttons[] = {{GLFW_MOUSE_BUTTON_LEFT, MouseButton::Left},
                                                   {GLFW_MOUSE_BUTTON_MIDDLE, MouseButton::Middle},
                                                   {GLFW_MOUSE_BUTTON_RIGHT, MouseButton::Right}};
    const bool leftPaints = host_.kind() == sandcore::SceneKind::Canvas;
    for (const auto& [glfwButton, button] : buttons)
        if (glfwGetMouseButton(handle, glfwButton) == GLFW_PRESS)
            applyMouseDrag(capture, button, alt, leftPaints, dx, dy, float(height), camera_);
    if (host_.kind() != sandcore::SceneKind::Canvas) return;
    const bool leftDown = glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    // While an obstacle is being placed, the left button drags its box instead of pouring sand;
    // while the digger is on, its body.
    if (state_.digger.active || state_.digger.dragging)
        handleDiggerDrag(x, y, leftDown && !alt, capture);
    else if (state_.obstacleDrag.armed || state_.obstacleDrag.dragging)
        handleObstacleDrag(x, y, leftDown && !alt, capture);
    else
        handleCanvasPointer({x, y, leftDown, alt, capture.mouse});
}

void Application::handleKey(KeyCommand command) {
    switch (command) {
    case KeyCommand::ToggleGui: state_.showGui = !state_.showGui; break;
    case KeyCommand::PrintFilledCells:
        std::printf("filled cells: %lld (upper %lld, lower %lld)\n", (long long)scene().grainCount(),
                    (long long)scene().counters().grainsUpper, (long long)scene().counters().grainsLower);
        break;
    case KeyCommand::PrintFrameRate:
        std::printf("%.1f frames per second, %.2f ms per frame\n", state_.stats.framesPerSecond,
                    state_.stats.millisecondsPerFrame);
        break;
    case KeyCommand::RunBenchmark:
        if (!benchmark_.running) state_.commands.push(Command::Benchmark);
        break;
    case KeyCommand::Quit:
        // Esc during the frame benchmark ends the benchmark, and during a build the build, not the program.
        if (benchmark_.running)
            benchmark_.cancelRequested = true;
        else if (state_.building && !state_.build.cancelling && !state_.files.confirmQuit)
            state_.commands.push(Command::CancelBuild);
        else
            state_.commands.push(Command::Quit);
        break;
    case KeyCommand::Help: state_.showHelp = !state_.showHelp; break;
    case KeyCommand::Screenshot: state_.commands.push(Command::Screenshot); break;
    case KeyCommand::Undo: state_.commands.push(Command::Undo); break;
    case KeyCommand::Flip: state_.commands.push(Command::Flip); break;
    case KeyCommand::Redo: state_.commands.push(Command::Redo); break;
    case KeyCommand::Save: state_.commands.push(Command::SaveState); break;
    case KeyCommand::Open: state_.commands.push(Command::LoadState); break;
    default: break;
    }
    std::fflush(stdout);
}

std::optional<CanvasColumn> Application::columnUnderCursor(double cursorX, double cursorY) {
    return canvas_.columnUnderCursor(host_, cursorX, cursorY, canvasView(), state_.painting);
}

bool Application::handleCanvasPointer(const PointerSample& sample) {
    const bool changed = canvas_.handlePointer(host_, sample, canvasView(), state_.painting);
    if (changed) ++state_.files.unsavedEdits;
    canvas_.publishUndoState(state_.painting);
    return changed;
}

} // namespace sandglass
