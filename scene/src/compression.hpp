// SPDX-License-Identifier: MIT
#pragma once
// zstd for the state file (E1) and the undo history (E3), behind two calls.

#include <cstdint>
#include <span>
#include <vector>

namespace sandglass {

/// zstd level for saving and for undo snapshots: fast, and grids of mostly EMPTY cells shrink
/// a hundredfold even at low levels.
inline constexpr int kCompressionLevel = 3;

/// The bytes compressed as one zstd frame that records its content size.
std::vector<std::uint8_t> compressBytes(std::span<const std::uint8_t> bytes, int level = kCompressionLevel);

/// Decompresses one zstd frame that must hold exactly expectedSize bytes; throws FormatError
/// (before allocating) when the frame says otherwise, and when the data is damaged.
std::vector<std::uint8_t> decompressBytes(std::span<const std::uint8_t> frame, std::uint64_t expectedSize);

} // namespace sandglass
