#include "scene/file_io.hpp"

#include <cerrno>
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

void requireWritableFileTarget(const std::filesystem::path& file) {
    if (file.empty()) throw FileError(file, "no file name given");
    const std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    struct stat info {};
    if (::stat(folder.c_str(), &info) != 0) {
        const int error = errno;
        if (error == ENOENT) throw FileError(file, "the folder " + folder.string() + " does not exist");
        throw FileError(file, "the folder " + folder.string() + ": " + systemCause(error));
    }
    if (!S_ISDIR(info.st_mode)) throw FileError(file, folder.string() + " is not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw FileError(file, "the folder " + folder.string() + " is not writable (" + systemCause(errno) + ")");
    if (::stat(file.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) throw FileError(file, nonRegularKind(info.st_mode));
}

void writeFileAtomically(const std::filesystem::path& file, std::span<const std::uint8_t> bytes) {
    requireWritableFileTarget(file);
    std::string temporary = file.string() + ".XXXXXX";
    Descriptor out;
    out.fd = ::mkstemp(temporary.data());
    if (out.fd < 0) throw FileError(file, "cannot create a temporary file beside it (" + systemCause(errno) + ")");
    auto fail = [&](const std::string& cause) {
        ::unlink(temporary.c_str());
        throw FileError(file, cause);
    };
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t wrote = ::write(out.fd, bytes.data() + done, bytes.size() - done);
        if (wrote < 0 && errno == EINTR) continue;
        if (wrote <= 0) fail("write failed (" + systemCause(errno) + "); the file was not changed");
        done += std::size_t(wrote);
    }
    // Files made by mkstemp are private (0600); give the new file the usual permissions.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(out.fd, 0666 & ~mask);
    if (::fsync(out.fd) != 0) fail("write failed (" + systemCause(errno) + "); the file was not changed");
    const int fd = out.fd;
    out.fd = -1;
    if (::close(fd) != 0) fail("write failed (" + systemCause(errno) + "); the file was not changed");
    if (::rename(temporary.c_str(), file.c_str()) != 0) fail("cannot be replaced (" + systemCause(errno) + ")");
}

void writeFileAtomically(const std::filesystem::path& file, const std::string& text) {
    writeFileAtomically(file, std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

} // namespace sandglass
