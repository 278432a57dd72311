// SPDX-License-Identifier: MIT
#pragma once
// The versions of the libraries the scene layer is built on, for `sandglass --version`.

#include <string>

namespace sandglass {

/// e.g. "assimp 5.2.5"; the version the program runs with, not the one it was compiled against.
std::string sceneLibraryVersions();

} // namespace sandglass
