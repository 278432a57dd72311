// SPDX-License-Identifier: MIT
#include "scene/file_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sandglass {

namespace {

std::string systemCause(int error) { return std::strerror(error); }

// The kind of a file that stat() found, in words.
std::string nonRegularKind(mode_t mode) {
    if (S_ISDIR(mode)) return "is a folder, not a file";
    if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
    if (S_ISSOCK(mode)) return "is a socket, not a regular file";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
    return "is not a regular file";
}

// Closes a file descriptor when it goes out of scope.
struct Descriptor {
    int fd = -1;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

} // namespace

void requireReadableRegularFile(const std::filesystem::path& file) {
    struct stat info {};
    if (::stat(file.c_str(), &info) != 0) {
        const int error = errno;
        if (error == ENOENT) throw FileError(file, "no such file");
        if (error == ELOOP) throw FileError(file, "symbolic links loop (too many levels of links)");
        throw FileError(file, systemCause(error));
    }
    if (!S_ISREG(info.st_mode)) throw FileError(file, nonRegularKind(info.st_mode));
    if (::access(file.c_str(), R_OK) != 0) throw FileError(file, "cannot be read (" + systemCause(errno) + ")");
}

std::vector<std::uint8_t> readFileBytes(const std::filesystem::path& file, std::uint64_t maxBytes) {
    requireReadableRegularFile(file);
    Descriptor in;
    // O_NONBLOCK: should the file have been swapped for a FIFO since the check, open() does not wait.
    in.fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (in.fd < 0) throw FileError(file, "cannot be opened (" + systemCause(errno) + ")");
    struct stat info {};
    if (::fstat(in.fd, &info) != 0 || !S_ISREG(info.st_mode)) throw FileError(file, "is not a regular file");
    if (std::uint64_t(info.st_size) > maxBytes)
        throw FileError(file, "is too large (" + std::to_string(info.st_size) + " bytes, at most " +
                                  std::to_string(maxBytes) + ")");
    std::vector<std::uint8_t> bytes(std::size_t(info.st_size));
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t got = ::read(in.fd, bytes.data() + done, bytes.size() - done);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) throw FileError(file, "read failed (" + systemCause(errno) + ")");
        if (got == 0) break; // shrank while reading: keep what is there
        done += std::size_t(got);
    }
    bytes.resize(done);
    return bytes;
}

namespace {

// Throws FileError naming `file` unless `folder` exists, is a folder and can be written.
void requireWritableFolder(const std::filesystem::path& folder, const std::filesystem::path& file) {
    struct stat info {};
    if (::stat(folder.c_str(), &info) != 0) {
        const int error = errno;
        if (error == ENOENT) throw FileError(file, "the folder " + folder.string() + " does not exist");
        throw FileError(file, "the folder " + folder.string() + ": " + systemCause(error));
    }
    if (!S_ISDIR(info.st_mode)) throw FileError(file, folder.string() + " is not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw FileError(file, "the folder " + folder.string() + " is not writable (" + systemCause(errno) + ")");
}

// Writes every byte to fd; false (errno set) on failure.
bool writeAll(int fd, std::span<const std::uint8_t> bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t wrote = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (wrote < 0 && errno == EINTR) continue;
        if (wrote <= 0) return false;
        done += std::size_t(wrote);
    }
    return true;
}

} // namespace

void requireWritableFileTarget(const std::filesystem::path& file) {
    if (file.empty()) throw FileError(file, "no file name given");
    const std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    requireWritableFolder(folder, file);
    struct stat info {};
    if (::stat(file.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) throw FileError(file, nonRegularKind(info.st_mode));
}

namespace {

// Writes bytes to a new temporary file beside `file` (named after it), flushed to disk, with the
// usual permissions; returns its path. On failure nothing is left behind and FileError names `file`.
std::string writeTemporaryBeside(const std::filesystem::path& file, std::span<const std::uint8_t> bytes) {
    std::string temporary = file.string() + ".XXXXXX";
    Descriptor out;
    out.fd = ::mkstemp(temporary.data());
    if (out.fd < 0) throw FileError(file, "cannot create a temporary file beside it (" + systemCause(errno) + ")");
    auto fail = [&](const std::string& cause) {
        ::unlink(temporary.c_str());
        throw FileError(file, cause);
    };
    if (!writeAll(out.fd, bytes)) fail("write failed (" + systemCause(errno) + "); the file was not changed");
    // Files made by mkstemp are private (0600); give the new file the usual permissions.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(out.fd, 0666 & ~mask);
    if (::fsync(out.fd) != 0) fail("write failed (" + systemCause(errno) + "); the file was not changed");
    const int fd = out.fd;
    out.fd = -1;
    if (::close(fd) != 0) fail("write failed (" + systemCause(errno) + "); the file was not changed");
    return temporary;
}

} // namespace

void writeFileAtomically(const std::filesystem::path& file, std::span<const std::uint8_t> bytes) {
    requireWritableFileTarget(file);
    const std::string temporary = writeTemporaryBeside(file, bytes);
    if (::rename(temporary.c_str(), file.c_str()) != 0) {
        const int error = errno;
        ::unlink(temporary.c_str());
        throw FileError(file, "cannot be replaced (" + systemCause(error) + ")");
    }
}

void writeFileAtomically(const std::filesystem::path& file, const std::string& text) {
    writeFileAtomically(file, std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

namespace {

// Creates `target` with O_EXCL (it fails on an existing name) and writes bytes to it; for
// folders without hard links. True when written; false when the name exists; throws otherwise.
bool writeExclusively(const std::filesystem::path& target, std::span<const std::uint8_t> bytes) {
    Descriptor out;
    out.fd = ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (out.fd < 0) {
        if (errno == EEXIST) return false;
        throw FileError(target, "cannot be written (" + systemCause(errno) + ")");
    }
    if (!writeAll(out.fd, bytes) || ::fsync(out.fd) != 0) {
        const int error = errno;
        ::unlink(target.c_str());
        throw FileError(target, "write failed (" + systemCause(error) + ")");
    }
    return true;
}

} // namespace

std::filesystem::path writeNewNumberedFile(const std::filesystem::path& folder, const std::string& stem,
                                           const std::string& extension, std::span<const std::uint8_t> bytes,
                                           int firstNumber) {
    auto numbered = [&](int number) { return folder / (stem + "-" + std::to_string(number) + extension); };
    firstNumber = std::max(1, firstNumber);
    requireWritableFolder(folder.empty() ? std::filesystem::path(".") : folder, numbered(firstNumber));
    std::string temporary = writeTemporaryBeside(numbered(firstNumber), bytes);
    // link() refuses a name that exists, so even a file made meanwhile by another program is
    // never replaced; the first free number wins. Folders without hard links (FAT, some network
    // shares) fall back to creating the name exclusively and writing it there.
    for (int number = firstNumber; number < kMaxNumberedFiles; ++number) {
        const std::filesystem::path target = numbered(number);
        if (!temporary.empty()) {
            if (::link(temporary.c_str(), target.c_str()) == 0) {
                ::unlink(temporary.c_str());
                return target;
            }
            const int error = errno;
            if (error == EEXIST) continue;
            ::unlink(temporary.c_str());
            temporary.clear();
            if (error != EPERM && error != EOPNOTSUPP && error != ENOSYS && error != EMLINK)
                throw FileError(target, "cannot be written (" + systemCause(error) + ")");
        }
        if (writeExclusively(target, bytes)) return target;
    }
    if (!temporary.empty()) ::unlink(temporary.c_str());
    throw FileError(folder, "has no free name " + stem + "-N" + extension + " for N from " + std::to_string(firstNumber) +
                                " to " + std::to_string(kMaxNumberedFiles - 1));
}

namespace {

// The value of KEY in the XDG user-dirs file ("KEY=\"$HOME/Pictures\""), with $HOME expanded;
// empty when the file or the key is missing.
std::string userDirFromConfig(const std::filesystem::path& config, const std::string& key, const std::string& home) {
    std::vector<std::uint8_t> bytes;
    try {
        bytes = readFileBytes(config, 1 << 20);
    } catch (const FileError&) {
        return {};
    }
    const std::string text(bytes.begin(), bytes.end());
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        start = end + 1;
        if (line.rfind(key + "=", 0) != 0) continue;
        std::string value = line.substr(key.size() + 1);
        if (value.size() >= 2 && value.front() == '"' && value.back() == '"') value = value.substr(1, value.size() - 2);
        if (value.rfind("$HOME", 0) == 0) value = home + value.substr(5);
        return value;
    }
    return {};
}

bool isFolder(const std::filesystem::path& path) {
    std::error_code error;
    return !path.empty() && std::filesystem::is_directory(path, error);
}

} // namespace

std::filesystem::path defaultPicturesFolder() {
    const char* home = std::getenv("HOME");
    const std::string homeFolder = home ? home : "";
    if (const char* fromEnvironment = std::getenv("XDG_PICTURES_DIR"); fromEnvironment && isFolder(fromEnvironment))
        return fromEnvironment;
    if (!homeFolder.empty()) {
        const char* configHome = std::getenv("XDG_CONFIG_HOME");
        const std::filesystem::path config = (configHome && *configHome ? std::filesystem::path(configHome)
                                                                        : std::filesystem::path(homeFolder) / ".config") /
                                             "user-dirs.dirs";
        const std::filesystem::path fromConfig = userDirFromConfig(config, "XDG_PICTURES_DIR", homeFolder);
        // user-dirs.dirs names the home folder itself when there is no pictures folder.
        if (isFolder(fromConfig) && fromConfig != std::filesystem::path(homeFolder)) return fromConfig;
        if (isFolder(std::filesystem::path(homeFolder) / "Pictures")) return std::filesystem::path(homeFolder) / "Pictures";
    }
    std::error_code error;
    const std::filesystem::path current = std::filesystem::current_path(error);
    return error ? std::filesystem::path(".") : current;
}

} // namespace sandglass
