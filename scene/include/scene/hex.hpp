// SPDX-License-Identifier: MIT
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>

namespace sandglass {

/// A 64-bit value as 16 lower-case hex digits (the state hash's printed form).
inline std::string toHex16(std::uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

} // namespace sandglass
