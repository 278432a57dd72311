// SPDX-License-Identifier: MIT
#include "scene/draft_image.hpp"

#include "scene/file_io.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>

namespace sandglass {

DraftImage DraftImage::load(const std::string& path) {
    // Read through file_io: a FIFO is refused instead of blocking, and stb_image decodes from
    // memory, so it never touches the file system itself. 256 MiB is far beyond any draft.
    std::vector<std::uint8_t> bytes;
    try {
        bytes = readFileBytes(path, std::uint64_t{256} << 20);
    } catch (const FileError& e) {
        throw std::runtime_error(e.what());
    }
    if (bytes.empty()) throw std::runtime_error(path + ": the file is empty, not an image");
    if (bytes.size() > std::size_t(std::numeric_limits<int>::max()))
        throw std::runtime_error(path + ": the file is too large for an image");
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4), stbi_image_free);
    if (!pixels) {
        // stb's reason can quote bytes of the file (a corrupt PNG chunk name): keep it one printable line.
        std::string reason = stbi_failure_reason() ? stbi_failure_reason() : "unknown";
        for (char& c : reason)
            if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
        throw std::runtime_error(path + ": not a readable PNG or JPEG image (" + reason + ")");
    }
    if (width <= 0 || height <= 0) throw std::runtime_error(path + ": the image is empty");
    const std::size_t size = std::size_t(width) * std::size_t(height) * 4;
    return DraftImage(width, height, std::vector<std::uint8_t>(pixels.get(), pixels.get() + size), path);
}

DraftImage::DraftImage(int width, int height, std::vector<std::uint8_t> rgba, std::string path)
    : width_(width), height_(height), rgba_(std::move(rgba)), path_(std::move(path)) {
    if (width <= 0 || height <= 0 || rgba_.size() != std::size_t(width) * std::size_t(height) * 4)
        throw std::invalid_argument("draft image: pixel data does not match its size");
}

std::uint32_t DraftImage::colorAt(double u, double v) const {
    const int x = std::clamp(int(u * width_), 0, width_ - 1);
    const int y = std::clamp(int(v * height_), 0, height_ - 1);
    const std::uint8_t* p = rgba_.data() + (std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 4;
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | 0xff000000u;
}

bool isDraftImageFile(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".png" || extension == ".jpg" || extension == ".jpeg";
}

std::vector<std::string> listDraftFiles(const std::filesystem::path& folder) {
    std::vector<std::string> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (entry.path().filename().string().starts_with("draft_") && isDraftImageFile(entry.path()))
            files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace sandglass
