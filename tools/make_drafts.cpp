// SPDX-License-Identifier: MIT
// Writes the bundled draft images for the canvas (models/draft_*.png|jpg): simple, bold
// pictures that read well when drawn in sand. The images are committed; developers rerun this
// after changing a picture:
//   cmake --build --preset release --target make_drafts && build/release/tools/make_drafts models
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace {

struct Rgb {
    std::uint8_t r, g, b;
};

using Painter = std::function<Rgb(double u, double v)>; // u right, v down, both in [0, 1)

std::vector<std::uint8_t> render(int size, const Painter& paint) {
    std::vector<std::uint8_t> pixels(std::size_t(size) * std::size_t(size) * 3);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const Rgb c = paint((x + 0.5) / size, (y + 0.5) / size);
            std::uint8_t* p = &pixels[(std::size_t(y) * std::size_t(size) + std::size_t(x)) * 3];
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
        }
    return pixels;
}

// A sun over hills and the sea, with a red heart in the sky.
Rgb sunAndSea(double u, double v) {
    const double sunDistance = std::hypot(u - 0.28, v - 0.27);
    const double angle = std::atan2(v - 0.27, u - 0.28);
    if (sunDistance < 0.13) return {250, 200, 40};
    if (sunDistance < 0.2 && std::cos(12 * angle) > 0.55) return {240, 130, 30};
    // Heart: the classic implicit curve (x^2 + y^2 - 1)^3 - x^2 y^3 <= 0.
    const double hx = (u - 0.72) / 0.13, hy = -(v - 0.3) / 0.13;
    if (std::pow(hx * hx + hy * hy - 1.0, 3.0) - hx * hx * hy * hy * hy <= 0.0) return {210, 40, 60};
    const double hill = 0.62 - 0.08 * std::sin(u * 7.0 + 0.5);
    const double sea = 0.8 + 0.025 * std::sin(u * 25.0);
    if (v > sea) return {30, 90, 190};
    if (v > hill) return {60, 150, 70};
    return {235, 228, 205}; // pale sky: reads as plain sand
}

// Concentric rainbow bands.
Rgb rainbow(double u, double v) {
    const double r = std::hypot(u - 0.5, v - 0.95);
    const Rgb bands[] = {{200, 40, 40}, {235, 140, 30}, {240, 215, 50}, {60, 160, 70}, {40, 100, 200}, {120, 60, 170}};
    const int band = int((0.8 - r) / 0.07);
    if (r < 0.8 && r > 0.38 && band >= 0 && band < 6) return bands[band];
    return {235, 228, 205};
}

} // namespace

int main(int argc, char** argv) {
    const std::string folder = argc > 1 ? argv[1] : "models";
    const int size = 256;
    const auto sun = render(size, sunAndSea);
    const auto bow = render(size, rainbow);
    const std::string png = folder + "/draft_sun.png", jpg = folder + "/draft_rainbow.jpg";
    if (!stbi_write_png(png.c_str(), size, size, 3, sun.data(), size * 3) ||
        !stbi_write_jpg(jpg.c_str(), size, size, 3, bow.data(), 90)) {
        std::fprintf(stderr, "make_drafts: cannot write into %s\n", folder.c_str());
        return 1;
    }
    std::printf("%s\n%s\n", png.c_str(), jpg.c_str());
    return 0;
}
