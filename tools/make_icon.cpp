// SPDX-License-Identifier: MIT
// Writes desktop/sandglass.svg, the program's icon: a framed hourglass, glass with its sand
// half run through, drawn on a 256 x 256 canvas. The committed file comes from here:
//   cmake --build --preset release --target make_icon && build/release/tools/make_icon desktop/sandglass.svg
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

constexpr double kCentre = 128.0;
constexpr double kTop = 40.0, kBottom = 216.0, kNeckY = 128.0;
constexpr double kBulbHalfWidth = 58.0, kNeckHalfWidth = 5.0;

// Half the glass's width at height y: a smooth bulb narrowing to the neck (the lathe profile
// of models/hourglass.obj, drawn in 2D).
double halfWidth(double y) {
    const double t = std::abs(y - kNeckY) / (kNeckY - kTop); // 0 at the neck, 1 at a plate
    const double bulb = std::sin(std::min(t, 1.0) * 3.14159265358979 * 0.62);
    return kNeckHalfWidth + (kBulbHalfWidth - kNeckHalfWidth) * std::pow(bulb, 0.8);
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

// The outline of the glass between heights from and to, down the right side and up the left.
std::string glassPath(double from, double to, double inset) {
    std::string right, left;
    constexpr int kSteps = 48;
    for (int i = 0; i <= kSteps; ++i) {
        const double y = from + (to - from) * i / kSteps;
        const double w = std::max(halfWidth(y) - inset, 0.5);
        right += (i == 0 ? "M" : " L") + number(kCentre + w) + "," + number(y);
        left = " L" + number(kCentre - w) + "," + number(y) + left;
    }
    return right + left + " Z";
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_icon OUT.svg\n");
        return 2;
    }
    FILE* out = std::fopen(argv[1], "w");
    if (!out) {
        std::perror(argv[1]);
        return 1;
    }
    const std::string glass = glassPath(kTop + 6, kBottom - 6, 0.0);
    // Sand: the upper bulb's lower part, the stream through the neck, a heap in the lower bulb.
    const std::string upperSand = glassPath(98.0, kNeckY, 4.0);
    std::string heap = "M" + number(kCentre - halfWidth(206) + 4) + ",206";
    for (int i = 0; i <= 24; ++i) {
        const double x = -1.0 + 2.0 * i / 24.0;
        const double y = 206.0 - 44.0 * (1.0 - std::abs(x)) - 8.0;
        const double w = halfWidth(y) - 4.0;
        heap += " L" + number(kCentre + std::clamp(x * 60.0, -w, w)) + "," + number(y);
    }
    heap += " L" + number(kCentre + halfWidth(206) - 4) + ",206 Z";
    std::fprintf(out,
                 "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                 "<!-- Made by tools/make_icon.cpp: a framed hourglass, sandglass's icon. -->\n"
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"256\" height=\"256\" viewBox=\"0 0 256 256\">\n"
                 "  <defs>\n"
                 "    <linearGradient id=\"sand\" x1=\"0\" y1=\"0\" x2=\"0\" y2=\"1\">\n"
                 "      <stop offset=\"0\" stop-color=\"#e8b56a\"/><stop offset=\"1\" stop-color=\"#c98a3f\"/>\n"
                 "    </linearGradient>\n"
                 "    <linearGradient id=\"wood\" x1=\"0\" y1=\"0\" x2=\"0\" y2=\"1\">\n"
                 "      <stop offset=\"0\" stop-color=\"#8a5a34\"/><stop offset=\"1\" stop-color=\"#5e3b20\"/>\n"
                 "    </linearGradient>\n"
                 "    <linearGradient id=\"glass\" x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\">\n"
                 "      <stop offset=\"0\" stop-color=\"#dff1ff\" stop-opacity=\"0.55\"/>\n"
                 "      <stop offset=\"0.35\" stop-color=\"#ffffff\" stop-opacity=\"0.15\"/>\n"
                 "      <stop offset=\"1\" stop-color=\"#bcdcf5\" stop-opacity=\"0.45\"/>\n"
                 "    </linearGradient>\n"
                 "  </defs>\n"
                 "  <path d=\"%s\" fill=\"url(#sand)\"/>\n"
                 "  <rect x=\"126\" y=\"124\" width=\"4\" height=\"76\" fill=\"#d9a158\"/>\n"
                 "  <path d=\"%s\" fill=\"url(#sand)\"/>\n"
                 "  <path d=\"%s\" fill=\"url(#glass)\" stroke=\"#7fa7c4\" stroke-width=\"3\"/>\n"
                 "  <rect x=\"58\" y=\"34\" width=\"140\" height=\"14\" rx=\"4\" fill=\"url(#wood)\"/>\n"
                 "  <rect x=\"58\" y=\"208\" width=\"140\" height=\"14\" rx=\"4\" fill=\"url(#wood)\"/>\n"
                 "  <rect x=\"64\" y=\"46\" width=\"7\" height=\"164\" fill=\"#6e4527\"/>\n"
                 "  <rect x=\"185\" y=\"46\" width=\"7\" height=\"164\" fill=\"#6e4527\"/>\n"
                 "</svg>\n",
                 upperSand.c_str(), heap.c_str(), glass.c_str());
    return std::fclose(out) == 0 ? 0 : 1;
}
