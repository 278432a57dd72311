// SPDX-License-Identifier: MIT
// libFuzzer target of the draft-image loader (SPEC H4): DraftImage::load must return an image
// whose pixels match its size or throw with one line naming the file. stb_image runs in this
// process, so ASan sees every read it makes.

#include "scene/draft_image.hpp"

#include "fuzz_file.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const fuzzing::InputFile file(data, size, size > 0 && data[0] == 0xff ? ".jpg" : ".png");
    try {
        const sandglass::DraftImage image = sandglass::DraftImage::load(file.path());
        if (image.rgba().size() != std::size_t(image.width()) * std::size_t(image.height()) * 4) std::abort();
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        if (message.rfind(file.path() + ": ", 0) != 0 || message.find('\n') != std::string::npos) std::abort();
    }
    return 0;
}
