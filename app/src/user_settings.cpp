// SPDX-License-Identifier: MIT
#include "app/user_settings.hpp"

#include "scene/file_io.hpp"
#include "scene/scene_request.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <system_error>

namespace sandglass {

namespace {

using Json = nlohmann::json;

// Reads one value when it is there; a value of the wrong kind or out of range keeps the
// default and leaves its name in `bad` (the first one is reported).
class FieldReader {
public:
    FieldReader(const Json& object, std::string& bad) : object_(object), bad_(bad) {}

    void integer(const char* key, int& value, int min, int max) {
        const Json* found = find(key);
        if (!found) return;
        if (found->is_number_integer() && found->get<long long>() >= min && found->get<long long>() <= max)
            value = found->get<int>();
        else
            reject(key);
    }
    void number(const char* key, float& value, float min, float max) {
        const Json* found = find(key);
        if (!found) return;
        if (found->is_number() && std::isfinite(found->get<double>()) && found->get<double>() >= min &&
            found->get<double>() <= max)
            value = found->get<float>();
        else
            reject(key);
    }
    void flag(const char* key, bool& value) {
        const Json* found = find(key);
        if (!found) return;
        if (found->is_boolean())
            value = found->get<bool>();
        else
            reject(key);
    }
    void text(const char* key, std::string& value) {
        const Json* found = find(key);
        if (!found) return;
        if (found->is_string())
            value = found->get<std::string>();
        else
            reject(key);
    }
    // A name one of the parse functions knows (mode, palette, scene).
    template <class Parse, class T> void named(const char* key, T& value, Parse parse) {
        std::string name;
        const Json* found = find(key);
        if (!found) return;
        if (!found->is_string()) return reject(key);
        if (const auto parsed = parse(found->get<std::string>()))
            value = *parsed;
        else
            reject(key);
    }
    void list(const char* key, std::vector<std::string>& value) {
        const Json* found = find(key);
        if (!found) return;
        if (!found->is_array()) return reject(key);
        for (const Json& item : *found) {
            if (!item.is_string()) return reject(key);
            if (value.size() < kMaxRecentFiles) value.push_back(item.get<std::string>());
        }
    }

private:
    const Json* find(const char* key) {
        const auto it = object_.find(key);
        return it == object_.end() ? nullptr : &*it;
    }
    void reject(const char* key) {
        if (bad_.empty()) bad_ = key;
    }

    const Json& object_;
    std::string& bad_;
};

std::optional<sandcore::SceneKind> sceneKindNamed(const std::string& name) {
    try {
        return parseSceneKind(name);
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

} // namespace

std::filesystem::path settingsFolder() {
    const char* config = std::getenv("XDG_CONFIG_HOME");
    // The XDG base directory spec: a relative XDG_CONFIG_HOME is invalid and is ignored.
    if (config != nullptr && std::filesystem::path(config).is_absolute()) return std::filesystem::path(config) / "sandglass";
    const char* home = std::getenv("HOME");
    if (home != nullptr && *home != '\0') return std::filesystem::path(home) / ".config" / "sandglass";
    return {};
}

UserSettings readUserSettings(const std::filesystem::path& file, std::string& problem) {
    problem.clear();
    UserSettings settings;
    std::error_code error;
    if (!std::filesystem::exists(file, error)) return settings;
    Json object;
    try {
        const std::vector<std::uint8_t> bytes = readFileBytes(file, 1 << 20);
        object = Json::parse(bytes.begin(), bytes.end());
    } catch (const FileError& e) {
        problem = std::string(e.what()) + "; starting from the default settings";
        return settings;
    } catch (const Json::exception&) {
        problem = file.string() + ": is not a settings file (not JSON); starting from the default settings";
        return settings;
    }
    if (!object.is_object()) {
        problem = file.string() + ": is not a settings file (not a JSON object); starting from the default settings";
        return settings;
    }
    std::string bad;
    FieldReader read(object, bad);
    read.integer("window_width", settings.windowWidth, 160, 8192);
    read.integer("window_height", settings.windowHeight, 120, 8192);
    if (object.contains("window_x") && object.contains("window_y")) {
        int x = 0, y = 0;
        read.integer("window_x", x, -65536, 65536);
        read.integer("window_y", y, -65536, 65536);
        if (bad.empty()) {
            settings.windowPlaced = true;
            settings.windowX = x;
            settings.windowY = y;
        }
    }
    read.number("ui_scale", settings.uiScale, 0.5f, 4.0f);
    read.named("render_mode", settings.mode, parseRenderMode);
    read.named("palette", settings.palette, parseSandPalette);
    read.flag("lighting", settings.lighting);
    read.named("scene", settings.scene, sceneKindNamed);
    read.text("model", settings.model);
    read.text("screenshot_folder", settings.screenshotFolder);
    read.list("recent_files", settings.recentFiles);
    if (!bad.empty()) problem = file.string() + ": the value of '" + bad + "' is not valid; its default is used";
    return settings;
}

std::string userSettingsJson(const UserSettings& settings) {
    nlohmann::ordered_json out;
    out["window_width"] = settings.windowWidth;
    out["window_height"] = settings.windowHeight;
    if (settings.windowPlaced) {
        out["window_x"] = settings.windowX;
        out["window_y"] = settings.windowY;
    }
    out["ui_scale"] = settings.uiScale;
    out["render_mode"] = renderModeName(settings.mode);
    out["palette"] = sandPaletteName(settings.palette);
    out["lighting"] = settings.lighting;
    out["scene"] = sceneKindName(settings.scene);
    out["model"] = settings.model;
    out["screenshot_folder"] = settings.screenshotFolder;
    out["recent_files"] = settings.recentFiles;
    return out.dump(2) + "\n";
}

void writeUserSettings(const std::filesystem::path& file, const UserSettings& settings) {
    std::error_code error;
    std::filesystem::create_directories(file.parent_path(), error);
    if (error) throw FileError(file.parent_path(), "cannot be made (" + error.message() + ")");
    writeFileAtomically(file, userSettingsJson(settings));
}

void addRecentFile(std::vector<std::string>& recent, const std::string& path) {
    if (path.empty()) return;
    std::error_code error;
    std::string absolute = std::filesystem::absolute(path, error).lexically_normal().string();
    if (error) absolute = path;
    recent.erase(std::remove(recent.begin(), recent.end(), absolute), recent.end());
    recent.insert(recent.begin(), absolute);
    if (recent.size() > kMaxRecentFiles) recent.resize(kMaxRecentFiles);
}

} // namespace sandglass
