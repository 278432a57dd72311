// SPDX-License-Identifier: MIT
#pragma once
// Runs the sandglass executable as a user would, capturing its output and exit code: the one
// helper every CLI test uses. No shell and no temporary files: arguments go to execv as a
// vector, stdout and stderr come back through pipes, so tests running at once share nothing.

#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <poll.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace cli {

struct ProcessResult {
    int exitCode = -1; ///< exit status, or 128 + signal number when a signal ended it
    std::string out;   ///< standard output
    std::string err;   ///< standard error
    bool timedOut = false; ///< killed after the time limit
};

/// Runs `program ARGS` with stdin from /dev/null; kills it after timeoutSeconds.
inline ProcessResult runProgram(const std::string& program, const std::vector<std::string>& args,
                                double timeoutSeconds = 300.0) {
    ProcessResult result;
    int out[2], err[2];
    if (::pipe2(out, O_CLOEXEC) != 0) return result;
    if (::pipe2(err, O_CLOEXEC) != 0) {
        ::close(out[0]), ::close(out[1]);
        return result;
    }
    // Prepared before the fork: the child calls only async-signal-safe functions.
    std::vector<std::string> storage{program};
    storage.insert(storage.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& s : storage) argv.push_back(s.data());
    argv.push_back(nullptr);
    const pid_t child = ::fork();
    if (child == 0) {
        const int devNull = ::open("/dev/null", O_RDONLY);
        if (devNull >= 0) ::dup2(devNull, STDIN_FILENO);
        ::dup2(out[1], STDOUT_FILENO);
        ::dup2(err[1], STDERR_FILENO);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    ::close(out[1]);
    ::close(err[1]);
    if (child < 0) {
        ::close(out[0]), ::close(err[0]);
        return result;
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
    std::array<pollfd, 2> watch{pollfd{out[0], POLLIN, 0}, pollfd{err[0], POLLIN, 0}};
    std::string* sinks[2] = {&result.out, &result.err};
    int open = 2;
    char buffer[8192];
    while (open > 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            result.timedOut = true;
            ::kill(child, SIGKILL);
            break;
        }
        const int ready = ::poll(watch.data(), watch.size(), int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno != EINTR) break;
        for (std::size_t i = 0; i < watch.size(); ++i) {
            if (watch[i].fd < 0 || (watch[i].revents & (POLLIN | POLLHUP | POLLERR)) == 0) continue;
            const ssize_t n = ::read(watch[i].fd, buffer, sizeof buffer);
            if (n > 0) {
                sinks[i]->append(buffer, std::size_t(n));
            } else if (n == 0 || errno != EINTR) {
                ::close(watch[i].fd);
                watch[i].fd = -1;
                --open;
            }
        }
    }
    for (const pollfd& p : watch)
        if (p.fd >= 0) ::close(p.fd);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

/// Runs `sandglass ARGS`, one argument per element (no shell: spaces and quotes are literal).
inline ProcessResult runSandglassArgs(const std::vector<std::string>& args, double timeoutSeconds = 300.0) {
    return runProgram(SANDGLASS_EXECUTABLE, args, timeoutSeconds);
}

/// Runs `sandglass ARGS` with ARGS written as on a command line: split at spaces, and a part in
/// single quotes kept whole (only that much of a shell's syntax; nothing is expanded).
inline ProcessResult runSandglass(const std::string& commandLine) {
    std::vector<std::string> args;
    std::string current;
    bool quoted = false, any = false;
    for (char c : commandLine) {
        if (c == '\'') {
            quoted = !quoted;
            any = true;
        } else if (c == ' ' && !quoted) {
            if (any) args.push_back(current);
            current.clear();
            any = false;
        } else {
            current += c;
            any = true;
        }
    }
    if (any) args.push_back(current);
    return runSandglassArgs(args);
}

/// Number of lines in a text (a final line without newline counts).
inline int lineCount(const std::string& text) {
    int lines = 0;
    for (char c : text) lines += c == '\n';
    return lines + (!text.empty() && text.back() != '\n');
}

} // namespace cli
