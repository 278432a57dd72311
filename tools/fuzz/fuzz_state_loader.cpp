// SPDX-License-Identifier: MIT
// libFuzzer target of the state-file loader (SPEC H4). Two ways in, picked by the first byte:
// the whole file (header, checksum and zstd frame checked by openStateFile), and the payload
// behind a valid seal, so the fuzzer reaches the decoder's bounds and consistency checks
// instead of stopping at the checksum. Each must load a scene that steps, or throw one line.

#include "scene/file_io.hpp"
#include "scene/state_file.hpp"

#include <cstdlib>
#include <span>
#include <string>

namespace {
void requireOneLine(const std::string& message) {
    if (message.rfind("fuzz.sand: ", 0) != 0 || message.find('\n') != std::string::npos) std::abort();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::span<const std::uint8_t> rest(data + 1, size - 1);
    sandglass::StateLoadLimits limits;
    limits.memoryLimit = std::uint64_t(64) << 20; // keep each run small
    try {
        const std::vector<std::uint8_t> payload =
            data[0] & 1 ? sandglass::openStateFile(rest, "fuzz.sand", limits)
                        : sandglass::openStateFile(sandglass::sealStateFile(rest), "fuzz.sand", limits);
        sandglass::LoadedState loaded = sandglass::decodeStatePayload(payload, "fuzz.sand");
        for (int i = 0; i < 3; ++i) loaded.scene.step(); // a scene that loaded must also run
    } catch (const sandglass::FileError& e) {
        requireOneLine(e.what());
    }
    return 0;
}
