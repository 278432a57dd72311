// SPDX-License-Identifier: MIT
// Issue: at a few frames per second, several clicks between two frames counted once, because
// ImGui 1.86 sees one button state per frame. The layer replays each press and release in a
// frame of its own; these tests click a "+" button several times within one slow frame.
#include "support/display_guard.hpp"

#include "app/imgui_layer.hpp"
#include "view/window.hpp"

#include <doctest/doctest.h>
#include <imgui.h>

#include <optional>

using namespace sandglass;

namespace {

// A window with one "+" button at a fixed place; counts its presses and remembers its centre.
struct PlusButton {
    int count = 0;
    ImVec2 centre{0.0f, 0.0f};
    void build() {
        ImGui::SetNextWindowPos(ImVec2(20.0f, 20.0f), ImGuiCond_Always);
        ImGui::Begin("clicks", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        if (ImGui::Button(" + ")) ++count;
        const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
        centre = ImVec2(0.5f * (min.x + max.x), 0.5f * (min.y + max.y));
        ImGui::End();
    }
};

// One frame as the application makes it: replayed transitions, then the real build.
void frame(ImGuiLayer& layer, PlusButton& button) {
    layer.newFrame([&] { button.build(); });
    button.build();
    layer.render(false);
}

std::optional<Window> openHiddenWindow() {
    try {
        return std::optional<Window>(std::in_place, WindowOptions{320, 240, false, false, "mouse clicks test"});
    } catch (const WindowError& error) {
        testing::cannotDraw(std::string("no OpenGL 3.3 context (") + error.what() + "): clicks not checked");
        return std::nullopt;
    }
}

} // namespace

TEST_CASE("mouse clicks: five clicks within one slow frame all reach the button") {
    if (!testing::requireDisplay("mouse clicks")) return;
    std::optional<Window> window = openHiddenWindow();
    if (!window) return;
    ImGuiLayer layer(window->handle(), 1.0f);
    PlusButton plus;
    frame(layer, plus); // lays the button out
    frame(layer, plus);
    REQUIRE(plus.centre.x > 20.0f);
    for (int click = 0; click < 5; ++click) {
        layer.queueMouseTransition({0, true, plus.centre.x, plus.centre.y});
        layer.queueMouseTransition({0, false, plus.centre.x, plus.centre.y});
    }
    frame(layer, plus); // the one slow frame that finds all ten transitions
    CHECK(plus.count == 5);
    frame(layer, plus);
    CHECK(plus.count == 5); // nothing counted twice
}

TEST_CASE("mouse clicks: a press in one frame and its release in the next count once, as ever") {
    if (!testing::requireDisplay("mouse clicks")) return;
    std::optional<Window> window = openHiddenWindow();
    if (!window) return;
    ImGuiLayer layer(window->handle(), 1.0f);
    PlusButton plus;
    frame(layer, plus);
    frame(layer, plus);
    layer.queueMouseTransition({0, true, plus.centre.x, plus.centre.y});
    frame(layer, plus);
    CHECK(plus.count == 0); // a button fires on release
    layer.queueMouseTransition({0, false, plus.centre.x, plus.centre.y});
    frame(layer, plus);
    CHECK(plus.count == 1);
    // A click off the button counts nothing.
    layer.queueMouseTransition({0, true, 300.0, 230.0});
    layer.queueMouseTransition({0, false, 300.0, 230.0});
    frame(layer, plus);
    CHECK(plus.count == 1);
}
