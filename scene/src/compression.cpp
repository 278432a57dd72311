#include "compression.hpp"

#include "byte_codec.hpp"

#include <zstd.h>

#include <string>

namespace sandglass {

std::vector<std::uint8_t> compressBytes(std::span<const std::uint8_t> bytes, int level) {
    std::vector<std::uint8_t> frame(ZSTD_compressBound(bytes.size()));
    const std::size_t written = ZSTD_compress(frame.data(), frame.size(), bytes.data(), bytes.size(), level);
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
