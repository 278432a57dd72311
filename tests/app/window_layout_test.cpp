// SPDX-License-Identifier: MIT
// SPEC U1, U2: the help lists every control, the panel keeps a sensible width, and a panel
// put somewhere stays on screen when the window shrinks and comes back when it grows.
#include "support/app_test_support.hpp"

#include "gui/help_window.hpp"
#include "gui/panels.hpp"
#include "view/input_routing.hpp"

#include <GLFW/glfw3.h>
#include <doctest/doctest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <string>

using namespace sandglass;

namespace {

bool helpMentions(const std::string& input) {
    for (const ControlHelp& control : controlHelp())
        if (std::string(control.input).find(input) != std::string::npos) return true;
    return false;
}

} // namespace

TEST_CASE("help: every key the window answers is in the help") {
    for (const char* input : {"F1", "?", "Space", "Esc", "Left drag", "Middle drag", "Right drag", "Mouse wheel", "Alt",
                              "Arrow keys", "+ / -", "1 / 2 / 3", "T", "Ctrl+Z", "Ctrl+Y", "Ctrl+Shift+Z", "Ctrl+S",
                              "Ctrl+O", "P", "B", "F", "#"}) {
        CAPTURE(input);
        CHECK(helpMentions(input));
    }
    CHECK(keyCommand({}, GLFW_KEY_F1) == KeyCommand::Help);
    CHECK(characterCommand({}, '?') == KeyCommand::Help);
    CHECK(keyCommand({false, true}, GLFW_KEY_F1) == KeyCommand::None); // typing into a field
}

TEST_CASE("panel placement: after a resize to 1x1 and back the panel is where it was") {
    const WindowPlacement chosen{10.0f, 10.0f};
    const WindowPlacement tiny = placeOnScreen(chosen, 300.0f, 700.0f, 1.0f, 1.0f);
    CHECK(tiny.x == 0.0f);
    CHECK(tiny.y == 0.0f);
    const WindowPlacement back = placeOnScreen(chosen, 300.0f, 700.0f, 1280.0f, 800.0f);
    CHECK(back.x == 10.0f);
    CHECK(back.y == 10.0f);
    // A panel put near the right edge moves in just enough to show whole.
    const WindowPlacement right = placeOnScreen({1200.0f, 50.0f}, 300.0f, 400.0f, 1280.0f, 800.0f);
    CHECK(right.x == 980.0f);
    CHECK(right.y == 50.0f);
}

TEST_CASE("panel width: about a third of small windows, at most 25 text heights on large ones") {
    CHECK(panelWidth(1280.0f, 15.0f) == doctest::Approx(375.0f));
    CHECK(panelWidth(800.0f, 15.0f) == doctest::Approx(288.0f));
    CHECK(panelWidth(640.0f, 15.0f) == doctest::Approx(270.0f));
    CHECK(panelWidth(100.0f, 15.0f) == doctest::Approx(100.0f));
}

TEST_CASE("window: F1 opens the help window, the text size grows, and a resize to 1x1 and back leaves the panel in place") {
    if (!testing::requireDisplay("the help window")) return;
    ApplicationOptions options;
    options.window = {640, 480, false, false, "window layout test"};
    options.offscreen = true;
    options.initial.scene.request.resolution = 20;
    std::optional<Application> app = testing::openApplication(std::move(options), "the help window");
    if (!app) return;
    GLFWwindow* handle = app->window().handle();
    // The key as GLFW delivers it, through the application's own callback.
    const GLFWkeyfun keyCallback = glfwSetKeyCallback(handle, nullptr);
    glfwSetKeyCallback(handle, keyCallback);
    REQUIRE(bool(keyCallback));
    keyCallback(handle, GLFW_KEY_F1, 0, GLFW_PRESS, 0);
    app->renderFrame(0.0);
    CHECK(app->state().showHelp);
    const ImGuiWindow* help = ImGui::FindWindowByName("Keys and mouse");
    REQUIRE(help != nullptr);
    CHECK(help->Active);
    keyCallback(handle, GLFW_KEY_F1, 0, GLFW_PRESS, 0);
    app->renderFrame(0.0);
    CHECK_FALSE(app->state().showHelp);

    // The text size setting: larger text at once, kept within its range.
    const float fontBefore = ImGui::GetFontSize();
    app->state().uiScale = 1.5f;
    app->renderFrame(0.0);
    CHECK(ImGui::GetFontSize() == doctest::Approx(1.5f * fontBefore).epsilon(0.05));
    app->state().uiScale = 9.0f;
    app->renderFrame(0.0);
    CHECK(app->state().uiScale == ImGuiLayer::kMaxUiScale);
    app->state().uiScale = 1.0f;
    app->renderFrame(0.0);
    CHECK(ImGui::GetFontSize() == doctest::Approx(fontBefore));

    const ImGuiWindow* panel = ImGui::FindWindowByName("sandglass");
    REQUIRE(panel != nullptr);
    const ImVec2 before = panel->Pos;
    glfwSetWindowSize(handle, 1, 1);
    for (int i = 0; i < 3; ++i) app->renderFrame(0.0);
    CHECK(panel->Pos.x >= 0.0f);
    CHECK(panel->Pos.y >= 0.0f);
    glfwSetWindowSize(handle, 640, 480);
    for (int i = 0; i < 3; ++i) app->renderFrame(0.0);
    CHECK(panel->Pos.x == before.x);
    CHECK(panel->Pos.y == before.y);
}
