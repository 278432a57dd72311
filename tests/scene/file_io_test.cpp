// SPDX-License-Identifier: MIT
#include "scene/file_io.hpp"

#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>
#include <sys/stat.h>
#include <unistd.h>

using namespace sandglass;

namespace {
std::string contentOf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
std::string errorOf(auto&& action) {
    try {
        action();
    } catch (const FileError& error) {
        return error.what();
    }
    return {};
}
} // namespace

TEST_CASE("inputs must be regular files: missing, folder, FIFO and link loop each get their own cause") {
    TemporaryFolder folder;
    const auto fifo = folder.path() / "pipe.obj";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    CHECK(errorOf([&] { requireReadableRegularFile(fifo); }).find("FIFO") != std::string::npos);
    CHECK(errorOf([&] { readFileBytes(fifo); }).find("FIFO") != std::string::npos);
    CHECK(errorOf([&] { requireReadableRegularFile(folder.path()); }).find("is a folder") != std::string::npos);
    CHECK(errorOf([&] { requireReadableRegularFile(folder.path() / "missing.obj"); }).find("no such file") != std::string::npos);
    const auto loop = folder.path() / "loop.obj";
    std::filesystem::create_symlink(loop, loop);
    CHECK(errorOf([&] { requireReadableRegularFile(loop); }).find("loop") != std::string::npos);
    const auto file = folder.path() / "model.obj";
    std::ofstream(file) << "v 0 0 0\n";
    CHECK(errorOf([&] { requireReadableRegularFile(file); }).empty());
    CHECK(readFileBytes(file).size() == 8);
    CHECK(errorOf([&] { readFileBytes(file, 4); }).find("too large") != std::string::npos);
}

TEST_CASE("an atomic write replaces the file whole, and a failed one leaves the old file and no temporary") {
    TemporaryFolder folder;
    const auto file = folder.path() / "out.txt";
    writeFileAtomically(file, std::string("first"));
    CHECK(contentOf(file) == "first");
    writeFileAtomically(file, std::string("second"));
    CHECK(contentOf(file) == "second");
    CHECK(std::distance(std::filesystem::directory_iterator(folder.path()), {}) == 1);

    CHECK(errorOf([&] { writeFileAtomically(folder.path() / "missing" / "x.txt", std::string("x")); })
              .find("does not exist") != std::string::npos);
    CHECK(errorOf([&] { writeFileAtomically(folder.path(), std::string("x")); }).find("folder") != std::string::npos);
    // /dev/full accepts opening but fails every write: no temporary can be made beside it.
    CHECK_FALSE(errorOf([&] { writeFileAtomically("/dev/full", std::string("x")); }).empty());
    if (::geteuid() != 0) { // root writes into read-only folders anyway
        const auto readOnly = folder.path() / "read-only";
        std::filesystem::create_directory(readOnly);
        std::filesystem::permissions(readOnly, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
        CHECK(errorOf([&] { writeFileAtomically(readOnly / "x.txt", std::string("x")); }).find("not writable") !=
              std::string::npos);
        std::filesystem::permissions(readOnly, std::filesystem::perms::owner_all);
    }
    CHECK(contentOf(file) == "second");
}

TEST_CASE("numbered files: the first free number is taken and no existing file is ever replaced") {
    TemporaryFolder folder;
    const std::vector<std::uint8_t> first{1, 2, 3}, second{4, 5}, third{6};
    CHECK(writeNewNumberedFile(folder.path(), "shot", ".png", first) == folder / "shot-1.png");
    CHECK(writeNewNumberedFile(folder.path(), "shot", ".png", second) == folder / "shot-2.png");
    // A file another program made, and one of an earlier run, stay as they are.
    std::ofstream(folder / "shot-3.png") << "someone else's";
    CHECK(writeNewNumberedFile(folder.path(), "shot", ".png", third, 2) == folder / "shot-4.png");
    CHECK(contentOf(folder / "shot-1.png") == std::string("\1\2\3"));
    CHECK(contentOf(folder / "shot-2.png") == std::string("\4\5"));
    CHECK(contentOf(folder / "shot-3.png") == "someone else's");
    CHECK(contentOf(folder / "shot-4.png") == std::string("\6"));
    // Nothing but the four files: no temporary file is left behind.
    CHECK(std::distance(std::filesystem::directory_iterator(folder.path()), std::filesystem::directory_iterator()) == 4);
}

TEST_CASE("numbered files: a missing folder is one line naming it, and nothing is written") {
    TemporaryFolder folder;
    const std::string message =
        errorOf([&] { writeNewNumberedFile(folder / "missing", "shot", ".png", std::vector<std::uint8_t>{1}); });
    CHECK(message.find((folder / "missing").string()) != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
    CHECK(std::filesystem::is_empty(folder.path()));
}

TEST_CASE("pictures folder: the desktop's user-dirs entry, else ~/Pictures, else the current folder") {
    TemporaryFolder home;
    ::setenv("HOME", home.path().c_str(), 1);
    ::unsetenv("XDG_PICTURES_DIR");
    ::unsetenv("XDG_CONFIG_HOME");
    CHECK(defaultPicturesFolder() == std::filesystem::current_path());
    std::filesystem::create_directory(home / "Pictures");
    CHECK(defaultPicturesFolder() == home / "Pictures");
    std::filesystem::create_directories(home / ".config");
    std::filesystem::create_directory(home / "Bilder");
    std::ofstream(home / ".config" / "user-dirs.dirs") << "# written by xdg-user-dirs-update\n"
                                                          "XDG_DESKTOP_DIR=\"$HOME/Desktop\"\n"
                                                          "XDG_PICTURES_DIR=\"$HOME/Bilder\"\n";
    CHECK(defaultPicturesFolder() == home / "Bilder");
    ::setenv("XDG_PICTURES_DIR", home.path().c_str(), 1);
    CHECK(defaultPicturesFolder() == home.path());
}
