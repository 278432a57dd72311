// SPDX-License-Identifier: MIT
#include "compression.hpp"

#include "byte_codec.hpp"

#include <zstd.h>

#include <algorithm>
#include <memory>
#include <string>
#include <thread>

namespace sandglass {

std::vector<std::uint8_t> compressBytes(std::span<const std::uint8_t> bytes, int level) {
    std::unique_ptr<ZSTD_CCtx, std::size_t (*)(ZSTD_CCtx*)> context(ZSTD_createCCtx(), ZSTD_freeCCtx);
    if (!context) throw FormatError("compression failed: out of memory");
    ZSTD_CCtx_setParameter(context.get(), ZSTD_c_compressionLevel, level);
    // Large states compress on several threads where the library was built with them (Debian's
    // is); the frame is the same format either way. Small ones are not worth starting threads.
    if (bytes.size() > (std::size_t(8) << 20)) {
        const int workers = int(std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
        ZSTD_CCtx_setParameter(context.get(), ZSTD_c_nbWorkers, workers); // ignored where unsupported
    }
    std::vector<std::uint8_t> frame(ZSTD_compressBound(bytes.size()));
    const std::size_t written = ZSTD_compress2(context.get(), frame.data(), frame.size(), bytes.data(), bytes.size());
    if (ZSTD_isError(written)) throw FormatError(std::string("compression failed: ") + ZSTD_getErrorName(written));
    frame.resize(written);
    frame.shrink_to_fit();
    return frame;
}

std::vector<std::uint8_t> decompressBytes(std::span<const std::uint8_t> frame, std::uint64_t expectedSize) {
    const unsigned long long declared = ZSTD_getFrameContentSize(frame.data(), frame.size());
    if (declared == ZSTD_CONTENTSIZE_ERROR) throw FormatError("the compressed data is damaged (no zstd frame)");
    if (declared != expectedSize)
        throw FormatError("the compressed data holds " +
                          (declared == ZSTD_CONTENTSIZE_UNKNOWN ? std::string("an unknown number of")
                                                                : std::to_string(declared)) +
                          " bytes where the header says " + std::to_string(expectedSize));
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(expectedSize));
    const std::size_t got = ZSTD_decompress(bytes.data(), bytes.size(), frame.data(), frame.size());
    if (ZSTD_isError(got)) throw FormatError(std::string("the compressed data is damaged (") + ZSTD_getErrorName(got) + ")");
    if (got != expectedSize) throw FormatError("the compressed data ends early");
    return bytes;
}

} // namespace sandglass
