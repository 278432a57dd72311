#pragma once
// Runs the sandglass executable as a user would, capturing its output and exit code.

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace cli {

struct ProcessResult {
    int exitCode = -1;
    std::string out; ///< standard output
    std::string err; ///< standard error
};

/// A fresh file name in the temporary directory.
inline std::string temporaryPath() {
    char path[] = "/tmp/sandglass-test-XXXXXX";
    const int fd = mkstemp(path);
    if (fd >= 0) close(fd);
    return path;
}

/// Runs `sandglass ARGS` (ARGS as typed in a shell) and captures stdout, stderr and the exit code.
inline ProcessResult runSandglass(const std::string& args) {
    const std::string errFile = temporaryPath();
    const std::string command = std::string(SANDGLASS_EXECUTABLE) + " " + args + " 2>" + errFile + " </dev/null";
    ProcessResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) result.out.append(buffer.data(), n);
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    if (FILE* err = std::fopen(errFile.c_str(), "r")) {
        while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), err)) result.err.append(buffer.data(), n);
        std::fclose(err);
    }
    std::remove(errFile.c_str());
    return result;
}

/// Number of lines in a text (a final line without newline counts).
inline int lineCount(const std::string& text) {
    int lines = 0;
    for (char c : text) lines += c == '\n';
    return lines + (!text.empty() && text.back() != '\n');
}

} // namespace cli
