// SPDX-License-Identifier: MIT
#pragma once
// The loaders read files, so each input is written to a private temporary file first.

#include <cstdint>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace fuzzing {

/// A temporary file holding one input, removed when it goes out of scope.
class InputFile {
public:
    InputFile(const std::uint8_t* data, std::size_t size, const std::string& extension) {
        const char* folder = std::getenv("TMPDIR");
        path_ = std::string(folder && *folder ? folder : "/tmp") + "/sandglass-fuzz-XXXXXX" + extension;
        const int fd = ::mkstemps(path_.data(), int(extension.size()));
        if (fd < 0) std::abort();
        std::size_t done = 0;
        while (done < size) {
            const ssize_t n = ::write(fd, data + done, size - done);
            if (n <= 0) std::abort();
            done += std::size_t(n);
        }
        ::close(fd);
    }
    ~InputFile() { ::unlink(path_.c_str()); }
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

} // namespace fuzzing
