// SPDX-License-Identifier: MIT
#pragma once
// SPEC I2: where the program finds its data (shaders, bundled models and drafts) and the model
// importer's helper, relative to its own executable, so an installed copy can be moved and a
// build tree works without an install.
//
//   installed:  PREFIX/bin/sandglass, PREFIX/share/sandglass/{shaders,models},
//               PREFIX/libexec/sandglass/sandglass-import
//   build tree: the source folder the build was configured from, and the helper built next to
//               the scene layer; used only when the installed layout is not beside the executable.

#include <filesystem>

namespace sandglass {

/// The folder of the running executable (/proc/self/exe); empty when it cannot be read.
std::filesystem::path executableFolder();

/// The folder holding shaders/ and models/: $SANDGLASS_DATA_DIR when set (development), else
/// EXE/../share/sandglass when it exists (an installed copy, wherever it was moved), else the
/// source folder of the build.
std::filesystem::path dataFolder();

/// The bundled models and draft images: dataFolder()/models.
std::filesystem::path modelsFolder();

/// The GLSL files: $SANDGLASS_SHADER_DIR when set (edit shaders without rebuilding), else
/// dataFolder()/shaders.
std::filesystem::path shaderFolder();

/// The model importer's executable: EXE/../libexec/sandglass/sandglass-import when it exists,
/// else the one the build made; empty when neither is there (no model can be loaded then).
std::filesystem::path importHelperPath();

} // namespace sandglass
