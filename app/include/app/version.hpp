// SPDX-License-Identifier: MIT
#pragma once
// What `sandglass --version` prints: the version, the commit it was built from, and the
// libraries it runs with.

#include <string>

namespace sandglass {

/// Two lines: "sandglass 0.2.0 (commit 1a2b3c4)" and the libraries with their versions.
std::string versionText();

} // namespace sandglass
