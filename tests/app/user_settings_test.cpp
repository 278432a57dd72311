// SPDX-License-Identifier: MIT
// SPEC I4: the settings file, read and written; a damaged one never stops the program.
#include "app/user_settings.hpp"

#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

using namespace sandglass;

namespace {

void writeText(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

// Sets an environment variable for one scope and puts the old value back.
class ScopedEnvironment {
public:
    ScopedEnvironment(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        value ? ::setenv(name, value, 1) : ::unsetenv(name);
    }
    ~ScopedEnvironment() { old_.empty() ? ::unsetenv(name_) : ::setenv(name_, old_.c_str(), 1); }

private:
    const char* name_;
    std::string old_;
};

void checkDefaults(const UserSettings& s) {
    const UserSettings defaults;
    CHECK(s.windowWidth == defaults.windowWidth);
    CHECK(s.windowHeight == defaults.windowHeight);
    CHECK_FALSE(s.windowPlaced);
    CHECK(s.uiScale == defaults.uiScale);
    CHECK(s.mode == defaults.mode);
    CHECK(s.palette == defaults.palette);
    CHECK(s.lighting == defaults.lighting);
    CHECK(s.scene == defaults.scene);
    CHECK(s.model.empty());
    CHECK(s.recentFiles.empty());
}

} // namespace

TEST_CASE("settings: a missing file gives the defaults without a word") {
    TemporaryFolder folder;
    std::string problem = "x";
    checkDefaults(readUserSettings(folder / "settings.json", problem));
    CHECK(problem.empty());
}

TEST_CASE("settings: what is written is read back") {
    TemporaryFolder folder;
    UserSettings s;
    s.windowWidth = 900;
    s.windowHeight = 640;
    s.windowPlaced = true;
    s.windowX = 33;
    s.windowY = -20;
    s.uiScale = 1.5f;
    s.mode = RenderMode::PseudoBillboards;
    s.palette = SandPalette::Volcanic;
    s.lighting = true;
    s.scene = sandcore::SceneKind::Sculpture;
    s.model = "/models/vase.obj";
    s.screenshotFolder = "/pictures";
    s.recentFiles = {"/a.sand", "/b.obj"};
    writeUserSettings(folder / "deeper/settings.json", s); // the folder is made
    std::string problem;
    const UserSettings r = readUserSettings(folder / "deeper/settings.json", problem);
    CHECK(problem.empty());
    CHECK(r.windowWidth == 900);
    CHECK(r.windowHeight == 640);
    CHECK(r.windowPlaced);
    CHECK(r.windowX == 33);
    CHECK(r.windowY == -20);
    CHECK(r.uiScale == 1.5f);
    CHECK(r.mode == RenderMode::PseudoBillboards);
    CHECK(r.palette == SandPalette::Volcanic);
    CHECK(r.lighting);
    CHECK(r.scene == sandcore::SceneKind::Sculpture);
    CHECK(r.model == "/models/vase.obj");
    CHECK(r.screenshotFolder == "/pictures");
    CHECK(r.recentFiles == std::vector<std::string>{"/a.sand", "/b.obj"});
}

TEST_CASE("settings: a garbage file gives one line naming it and the defaults") {
    TemporaryFolder folder;
    for (const std::string& garbage : {std::string("{\"window_width\": 900, "), std::string("\x89PNG\r\n\x1a\n\0\0", 10),
                                      std::string("[1, 2, 3]"), std::string("")}) {
        writeText(folder / "settings.json", garbage);
        std::string problem;
        const UserSettings s = readUserSettings(folder / "settings.json", problem);
        CAPTURE(problem);
        CHECK(problem.rfind((folder / "settings.json").string() + ": ", 0) == 0);
        CHECK(problem.find('\n') == std::string::npos);
        CHECK(problem.find("default") != std::string::npos);
        checkDefaults(s);
    }
    // A folder where the file should be cannot be read: the same.
    std::filesystem::remove(folder / "settings.json");
    std::filesystem::create_directory(folder / "settings.json");
    std::string problem;
    checkDefaults(readUserSettings(folder / "settings.json", problem));
    CHECK(problem.rfind((folder / "settings.json").string() + ": ", 0) == 0);
}

TEST_CASE("settings: a value of the wrong kind keeps its default and the others are read") {
    TemporaryFolder folder;
    writeText(folder / "settings.json",
              R"({"window_width": "wide", "ui_scale": 1.25, "render_mode": "voxels", "palette": "beach",
                  "lighting": 1, "recent_files": ["/x.sand", 7], "scene": "canvas", "future_option": true})");
    std::string problem;
    const UserSettings s = readUserSettings(folder / "settings.json", problem);
    CHECK(problem.find("'window_width'") != std::string::npos); // the first one named, one line
    CHECK(problem.find('\n') == std::string::npos);
    CHECK(s.windowWidth == UserSettings{}.windowWidth);
    CHECK(s.uiScale == 1.25f);
    CHECK(s.mode == RenderMode::PseudoBillboards); // the default
    CHECK(s.palette == SandPalette::Beach);
    CHECK(s.lighting); // the default
    CHECK(s.scene == sandcore::SceneKind::Canvas);
}

TEST_CASE("settings: the folder is $XDG_CONFIG_HOME/sandglass, else ~/.config/sandglass") {
    {
        ScopedEnvironment config("XDG_CONFIG_HOME", "/somewhere/config");
        CHECK(settingsFolder() == std::filesystem::path("/somewhere/config/sandglass"));
    }
    ScopedEnvironment home("HOME", "/home/someone");
    {
        ScopedEnvironment unset("XDG_CONFIG_HOME", nullptr);
        CHECK(settingsFolder() == std::filesystem::path("/home/someone/.config/sandglass"));
    }
    ScopedEnvironment relative("XDG_CONFIG_HOME", "relative/config"); // invalid by the XDG spec: ignored
    CHECK(settingsFolder() == std::filesystem::path("/home/someone/.config/sandglass"));
}

TEST_CASE("settings: recent files are absolute, newest first, each once, at most ten") {
    std::vector<std::string> recent;
    for (int i = 0; i < 14; ++i) addRecentFile(recent, "/files/" + std::to_string(i) + ".sand");
    addRecentFile(recent, "/files/7.sand");
    addRecentFile(recent, "");
    REQUIRE(recent.size() == kMaxRecentFiles);
    CHECK(recent[0] == "/files/7.sand");
    CHECK(recent[1] == "/files/13.sand");
    CHECK(std::count(recent.begin(), recent.end(), "/files/7.sand") == 1);
    addRecentFile(recent, "relative.obj");
    CHECK(std::filesystem::path(recent[0]).is_absolute());
}
