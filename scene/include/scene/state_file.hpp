// SPDX-License-Identifier: MIT
#pragma once
// SPEC E1: the whole state of a scene in one `.sand` file, so a user can stop and go on later.
//
// Layout (little-endian): a 48-byte header, then one zstd frame.
//   0  8 bytes  signature 0x89 'S' 'A' 'N' 'D' '\r' '\n' 0x1a (caught by text-mode transfers, like PNG's)
//   8  u32      format version (kStateFileVersion)
//  12  u32      flags, 0
//  16  u64      payload bytes once decompressed
//  24  u64      compressed bytes that follow the header
//  32  u64      checksum (stateChecksum) over header bytes 0..31 and the compressed bytes
//  40  u64      0, reserved
// The payload holds the scene kind, step settings, the scene request as named text fields, both
// layouts, the fill list and a SceneSnapshot (both live grids, every grain record, obstacles,
// counters). Loading checks the signature, the version, the sizes against the file and the
// memory limit, the checksum, and only then decompresses and parses; the parsed state is
// checked for consistency before a Scene is built from it.

#include "scene/scene_request.hpp"

#include "sandcore/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace sandglass {

/// The format version this program writes. Version 2 stores the model relative to the .sand
/// file ("model") with its absolute path as a fallback ("model_absolute"), so a state moved
/// together with its model keeps it; version 1 stored the path as typed. Both are read.
inline constexpr std::uint32_t kStateFileVersion = 2;
/// The oldest format version this program still reads.
inline constexpr std::uint32_t kOldestStateFileVersion = 1;
/// Bytes of the header before the compressed payload.
inline constexpr std::size_t kStateHeaderBytes = 48;

/// A scene read back from a state file, with the settings it was built from.
struct LoadedState {
    sandcore::Scene scene;  ///< the scene exactly as saved: the same hash and the same future steps
    SceneSettings settings; ///< how it was built (model path and options) and how it steps, for the panel to show
};

/// What loading may use.
struct StateLoadLimits {
    std::uint64_t maxFileBytes = std::uint64_t{1} << 34; ///< largest file accepted, bytes (16 GiB)
    std::uint64_t memoryLimit = 0; ///< most bytes the decompressed state may take; 0 = the memory available now
};

/// The 64-bit checksum state files carry: a multiply-rotate hash over 8-byte words, in which any
/// change of a single word (so any single flipped bit) always changes the result.
std::uint64_t stateChecksum(std::span<const std::uint8_t> bytes, std::uint64_t seed = 0);

/// The uncompressed payload for a scene and its request. With `savedAt` (the .sand file it goes
/// to) the model is stored relative to that file's folder, its absolute path beside it.
/// Throws std::invalid_argument when the scene is not of the shape request.kind builds (sceneShapeOf).
std::vector<std::uint8_t> encodeStatePayload(const sandcore::Scene& scene, const SceneRequest& request,
                                             const std::filesystem::path& savedAt = {});
/// Header, checksum and zstd around a payload: the bytes of a `.sand` file.
std::vector<std::uint8_t> sealStateFile(std::span<const std::uint8_t> payload);
/// The bytes of a whole `.sand` file for a scene (sealStateFile of encodeStatePayload).
std::vector<std::uint8_t> encodeStateFile(const sandcore::Scene& scene, const SceneRequest& request,
                                          const std::filesystem::path& savedAt = {});

/// The format version in a state file's header (0 when the bytes are too short to hold one).
std::uint32_t stateFileVersion(std::span<const std::uint8_t> bytes);
/// Checks a file's header, sizes and checksum and returns its decompressed payload. Throws
/// FileError "FILE: cause" for anything else than an intact file of a version this program reads.
std::vector<std::uint8_t> openStateFile(std::span<const std::uint8_t> bytes, const std::filesystem::path& file,
                                        const StateLoadLimits& limits = {});
/// Rebuilds the scene from a payload of format `version`; throws FileError "FILE: cause" for a
/// damaged or inconsistent one. From version 2 on, the model path is resolved against `file`'s
/// folder, else the stored absolute path is used when that file exists.
LoadedState decodeStatePayload(std::span<const std::uint8_t> payload, const std::filesystem::path& file,
                               std::uint32_t version = kStateFileVersion);

/// Writes the scene's whole state to `file` (through a temporary file renamed into place).
/// Throws FileError when it cannot be written; an existing file is then left as it was.
void saveState(const std::filesystem::path& file, const sandcore::Scene& scene, const SceneRequest& request);
/// Reads a state file. Throws FileError with one line "FILE: cause" for a missing, truncated,
/// corrupted, foreign or wrong-version file; nothing else is touched, so a running scene stays.
LoadedState loadState(const std::filesystem::path& file, const StateLoadLimits& limits = {});

} // namespace sandglass
