// SPDX-License-Identifier: MIT
#include "scene/library_versions.hpp"

#include <assimp/version.h>

namespace sandglass {

std::string sceneLibraryVersions() {
    return "assimp " + std::to_string(aiGetVersionMajor()) + "." + std::to_string(aiGetVersionMinor()) + "." +
           std::to_string(aiGetVersionPatch());
}

} // namespace sandglass
