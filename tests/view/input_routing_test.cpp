// SPDX-License-Identifier: MIT
// SPEC G3: mouse input ImGui wants never moves the camera; keys typed into ImGui never act.
#include "view/input_routing.hpp"

#include <GLFW/glfw3.h>
#include <doctest/doctest.h>
#include <imgui.h>

#include <initializer_list>

using namespace sandglass;

namespace {

OrbitCamera framedCamera() {
    OrbitCamera camera;
    camera.frame({0, 0, 0}, {10, 20, 10});
    return camera;
}

bool sameView(const OrbitCamera& a, const OrbitCamera& b) {
    return a.yaw() == b.yaw() && a.pitch() == b.pitch() && a.distance() == b.distance() && a.target() == b.target();
}

// A real ImGui frame with a panel under the mouse: ImGui then sets WantCaptureMouse itself.
InputCapture captureWithPanelUnderMouse(bool mouseOverPanel) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(400, 300);
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    InputCapture capture;
    for (int frame = 0; frame < 3; ++frame) {
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = mouseOverPanel ? ImVec2(50, 50) : ImVec2(350, 250);
        io.MouseDown[0] = frame >= 1; // a press that started over the panel
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(10, 10));
        ImGui::SetNextWindowSize(ImVec2(150, 120));
        ImGui::Begin("panel");
        ImGui::TextUnformatted("controls");
        ImGui::End();
        ImGui::Render();
        capture = {io.WantCaptureMouse, io.WantCaptureKeyboard};
    }
    ImGui::DestroyContext();
    return capture;
}

} // namespace

TEST_CASE("input: a drag over an ImGui panel leaves the camera where it was") {
    const InputCapture overPanel = captureWithPanelUnderMouse(true);
    REQUIRE(overPanel.mouse);
    OrbitCamera camera = framedCamera();
    const OrbitCamera before = camera;
    for (MouseButton button : {MouseButton::Left, MouseButton::Middle, MouseButton::Right})
        CHECK_FALSE(applyMouseDrag(overPanel, button, true, true, 25.0f, -12.0f, 300.0f, camera));
    CHECK_FALSE(applyScroll(overPanel, 2.0f, camera));
    CHECK(sameView(camera, before));
}

TEST_CASE("input: the same Alt drag over the scene moves the camera") {
    const InputCapture overScene = captureWithPanelUnderMouse(false);
    REQUIRE_FALSE(overScene.mouse);
    OrbitCamera camera = framedCamera();
    const OrbitCamera before = camera;
    CHECK(applyMouseDrag(overScene, MouseButton::Left, true, true, 25.0f, -12.0f, 300.0f, camera));
    CHECK(camera.yaw() != before.yaw());
    OrbitCamera panned = before;
    CHECK(applyMouseDrag(overScene, MouseButton::Middle, true, true, 25.0f, 0.0f, 300.0f, panned));
    CHECK(panned.target() != before.target());
    OrbitCamera zoomed = before;
    CHECK(applyMouseDrag(overScene, MouseButton::Right, true, true, 0.0f, 40.0f, 300.0f, zoomed));
    CHECK(zoomed.distance() > before.distance());
    CHECK(applyScroll(overScene, 1.0f, zoomed));
}

TEST_CASE("input: where the left button paints, only Alt drags move the camera (thesis §3.6)") {
    OrbitCamera camera = framedCamera();
    const OrbitCamera before = camera;
    for (MouseButton button : {MouseButton::Left, MouseButton::Middle, MouseButton::Right})
        CHECK_FALSE(applyMouseDrag({}, button, false, true, 30.0f, 30.0f, 300.0f, camera));
    CHECK(sameView(camera, before));
}

TEST_CASE("input: where the left button does not paint, a plain drag rotates, pans and zooms") {
    const OrbitCamera before = framedCamera();
    OrbitCamera rotated = before, panned = before, zoomed = before;
    CHECK(applyMouseDrag({}, MouseButton::Left, false, false, 30.0f, 10.0f, 300.0f, rotated));
    CHECK(rotated.yaw() != before.yaw());
    CHECK(applyMouseDrag({}, MouseButton::Middle, false, false, 30.0f, 0.0f, 300.0f, panned));
    CHECK(panned.target() != before.target());
    CHECK(applyMouseDrag({}, MouseButton::Right, false, false, 0.0f, 40.0f, 300.0f, zoomed));
    CHECK(zoomed.distance() > before.distance());
    CHECK(keyCommand({}, GLFW_KEY_T) == KeyCommand::Flip);
}

TEST_CASE("input: keys act only when ImGui does not want the keyboard") {
    const InputCapture typing{false, true};
    CHECK(keyCommand(typing, GLFW_KEY_SPACE) == KeyCommand::None);
    CHECK(keyCommand(typing, GLFW_KEY_ESCAPE) == KeyCommand::None);
    CHECK(characterCommand(typing, '#') == KeyCommand::None);
    const InputCapture free{};
    CHECK(keyCommand(free, GLFW_KEY_SPACE) == KeyCommand::ToggleGui);
    CHECK(keyCommand(free, GLFW_KEY_F) == KeyCommand::PrintFrameRate);
    CHECK(keyCommand(free, GLFW_KEY_B) == KeyCommand::RunBenchmark);
    CHECK(keyCommand(free, GLFW_KEY_ESCAPE) == KeyCommand::Quit);
    CHECK(characterCommand(free, '#') == KeyCommand::PrintFilledCells);
    CHECK(characterCommand(free, '+') == KeyCommand::ZoomIn);
    CHECK(characterCommand(free, '-') == KeyCommand::ZoomOut);
    CHECK(keyCommand(free, GLFW_KEY_3) == KeyCommand::ViewTop);
}

TEST_CASE("camera: views 2 (front) and 3 (top) look along -z and straight down") {
    OrbitCamera camera = framedCamera();
    applyCameraCommand(KeyCommand::ViewFront, camera);
    const glm::vec3 front = glm::normalize(camera.target() - camera.position());
    CHECK(front.z == doctest::Approx(-1.0f));
    applyCameraCommand(KeyCommand::ViewTop, camera);
    const glm::vec3 down = glm::normalize(camera.target() - camera.position());
    CHECK(down.y < -0.999f);
    applyCameraCommand(KeyCommand::ViewPerspective, camera);
    CHECK(camera.pitch() > 0.0f);
}

TEST_CASE("files and redo keys: Ctrl+S saves, Ctrl+O opens, Ctrl+Y and Ctrl+Shift+Z redo, Ctrl+Z undoes") {
    const InputCapture free{};
    CHECK(keyCommand(free, GLFW_KEY_S, GLFW_MOD_CONTROL) == KeyCommand::Save);
    CHECK(keyCommand(free, GLFW_KEY_O, GLFW_MOD_CONTROL) == KeyCommand::Open);
    CHECK(keyCommand(free, GLFW_KEY_Y, GLFW_MOD_CONTROL) == KeyCommand::Redo);
    CHECK(keyCommand(free, GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT) == KeyCommand::Redo);
    CHECK(keyCommand(free, GLFW_KEY_Z, GLFW_MOD_CONTROL) == KeyCommand::Undo);
    CHECK(keyCommand(free, GLFW_KEY_S) == KeyCommand::None); // S alone does nothing
    const InputCapture typing{false, true};
    CHECK(keyCommand(typing, GLFW_KEY_S, GLFW_MOD_CONTROL) == KeyCommand::None);
}
