// SPDX-License-Identifier: MIT
#pragma once
// An offscreen colour + depth target (hidden-window rendering for `sandglass render`, tests and
// the benchmark), and reading any bound framebuffer back as an RGB image for PNG screenshots.

#include "view/render/gl_objects.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sandglass {

/// Pixels in rows from the top, 3 bytes (RGB) per pixel.
struct RgbImage {
    int width = 0;                    ///< pixels
    int height = 0;                   ///< pixels
    std::vector<std::uint8_t> pixels; ///< width * height * 3 bytes, top row first
};

class OffscreenTarget {
public:
    /// A width x height RGBA8 + depth24 framebuffer; throws std::runtime_error if incomplete.
    OffscreenTarget(int width, int height);
    void bind() const; ///< draw into it (and read from it)
    int width() const { return width_; }   ///< pixels
    int height() const { return height_; } ///< pixels

private:
    int width_, height_;
    GlFramebuffer framebuffer_;
    GlRenderbuffer color_, depth_;
};

/// Reads the bound read framebuffer's lower-left width x height pixels, top row first.
RgbImage readPixels(int width, int height);
/// Writes a PNG; throws std::runtime_error with one line naming the file on failure.
void writePng(const std::filesystem::path& file, const RgbImage& image);
/// The image as PNG file content; throws std::runtime_error for an empty image.
std::vector<std::uint8_t> encodePng(const RgbImage& image);

} // namespace sandglass
