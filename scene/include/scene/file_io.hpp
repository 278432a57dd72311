// SPDX-License-Identifier: MIT
#pragma once
// Reading inputs and writing outputs safely. Inputs must be regular files (a FIFO would block
// a reader forever, a folder is no model); outputs are written to a temporary file beside the
// target and renamed into place, so a failed or partial write never destroys an existing file.

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace sandglass {

/// A file that cannot be read or written; what() is one line, "FILE: cause".
class FileError : public std::runtime_error {
public:
    FileError(const std::filesystem::path& file, const std::string& cause)
        : std::runtime_error(file.string() + ": " + cause) {}
};

/// Throws FileError unless `file` names an existing, readable regular file (after following
/// symbolic links): missing files, folders, FIFOs, devices, sockets and link loops each get
/// their own one-line cause.
void requireReadableRegularFile(const std::filesystem::path& file);

/// The whole content of a regular file, at most maxBytes long; throws FileError otherwise.
std::vector<std::uint8_t> readFileBytes(const std::filesystem::path& file,
                                        std::uint64_t maxBytes = std::uint64_t{1} << 32);

/// Throws FileError unless `file` can be written: its folder exists and is a folder, and the
/// file itself, if it exists, is a regular file. Checked before long work, so it fails early.
void requireWritableFileTarget(const std::filesystem::path& file);

/// Writes bytes to `file` through a temporary file in the same folder, flushed to disk and
/// renamed over the target. On any failure (full disk, read-only folder, missing folder) the
/// temporary file is removed, an existing `file` is left as it was, and FileError is thrown.
void writeFileAtomically(const std::filesystem::path& file, std::span<const std::uint8_t> bytes);
/// As above, for text.
void writeFileAtomically(const std::filesystem::path& file, const std::string& text);

/// Numbered files a folder may hold before writeNewNumberedFile gives up.
inline constexpr int kMaxNumberedFiles = 1'000'000;

/// Writes bytes to the first free FOLDER/STEM-N.EXTENSION with N >= firstNumber and returns the
/// path written. Never replaces a file, not even one another program makes at the same moment
/// (the complete file is linked into place, which fails on an existing name). Throws FileError
/// (folder missing or not writable, disk full), leaving nothing behind.
std::filesystem::path writeNewNumberedFile(const std::filesystem::path& folder, const std::string& stem,
                                           const std::string& extension, std::span<const std::uint8_t> bytes,
                                           int firstNumber = 1);

/// Where pictures go by default: the desktop's pictures folder (XDG_PICTURES_DIR, from the
/// environment or ~/.config/user-dirs.dirs), else ~/Pictures, when it exists; else the current folder.
std::filesystem::path defaultPicturesFolder();

} // namespace sandglass
