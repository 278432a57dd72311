// SPDX-License-Identifier: MIT
#pragma once
// P5: the draft image shown over the canvas and sampled for "colour from draft" (P6).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sandglass {

class DraftImage {
public:
    /// Loads a PNG or JPEG (anything stb_image reads) as RGBA8. Throws std::runtime_error with a
    /// one-line "FILE: cause" message for a missing, unreadable, broken or empty image.
    static DraftImage load(const std::string& path);
    /// An image from RGBA8 pixels, rows from the top; throws std::invalid_argument on a size mismatch.
    DraftImage(int width, int height, std::vector<std::uint8_t> rgba, std::string path = {});

    int width() const { return width_; }                        ///< pixels
    int height() const { return height_; }                      ///< pixels
    const std::vector<std::uint8_t>& rgba() const { return rgba_; } ///< RGBA8, rows from the top
    const std::string& path() const { return path_; }           ///< the file it came from

    /// Colour at (u, v) in [0, 1]^2 (u right, v down from the top row), nearest pixel, as RGBA8
    /// packed with R in the low byte and alpha forced to 255.
    std::uint32_t colorAt(double u, double v) const;

private:
    int width_;
    int height_;
    std::vector<std::uint8_t> rgba_;
    std::string path_;
};

/// True for a file name ending in .png, .jpg or .jpeg (any case): dropped on the canvas, it is a draft.
bool isDraftImageFile(const std::filesystem::path& file);
/// The draft images of a folder (files named draft_* that isDraftImageFile accepts), sorted.
std::vector<std::string> listDraftFiles(const std::filesystem::path& folder);

} // namespace sandglass
