// SPDX-License-Identifier: MIT
#pragma once
// Runs the sandglass executable as a user would, capturing its output and exit code: the one
// helper every CLI test uses. No shell and no temporary files: arguments go to the program as a
// vector (process/child_process.hpp), stdout and stderr come back through pipes, so tests
// running at once share nothing.

#include "process/child_process.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <csignal>
#include <initializer_list>
#include <string>
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
    sandglass::ChildCommand command;
    command.arguments = {program};
    command.arguments.insert(command.arguments.end(), args.begin(), args.end());
    command.output = sandglass::ChildStream::Pipe;
    command.errors = sandglass::ChildStream::Pipe;
    sandglass::ChildProcess child(command);
    if (!child.started()) {
        result.exitCode = 127; // as a shell says of a program it cannot run
        result.err = child.error();
        return result;
    }
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(timeoutSeconds));
    if (!child.readUntilClosed(deadline, &result.out, &result.err)) {
        result.timedOut = true;
        child.sendSignal(SIGKILL);
    }
    const sandglass::ChildExit exit = child.wait();
    result.exitCode = exit.signal != 0 ? 128 + exit.signal : exit.code;
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

/// Each command line is refused: a non-zero exit, one line on stderr that starts with
/// "sandglass: ", nothing on stdout.
inline void requireOneLineRefusals(std::initializer_list<const char*> commandLines) {
    for (const char* args : commandLines) {
        CAPTURE(args);
        const ProcessResult r = runSandglass(args);
        CHECK(r.exitCode != 0);
        CHECK(lineCount(r.err) == 1);
        CHECK(r.err.rfind("sandglass: ", 0) == 0);
        CHECK(r.out.empty());
    }
}

} // namespace cli
