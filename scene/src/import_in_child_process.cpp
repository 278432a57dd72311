// SPDX-License-Identifier: MIT
// Why another process: assimp (Debian's 5.x) crashes with SIGSEGV, aborts in ai_assert and loops
// forever on truncated or byte-flipped PLY and OFF files. aiProcess_ValidateDataStructure turns
// some of these into errors, not all, and no check of ours can know every reader's bugs. So the
// import runs in a child process, the small executable sandglass-import
// (scene/src/import_helper_main.cpp); the parent waits with a time limit and reads a plain
// triangle list from a pipe, checking every count and index (decodeImport). The GUI builds
// scenes on a worker thread; posix_spawn (process/child_process.hpp) starts the child safely
// from a process with threads. The child keeps nothing of the parent: its output goes to the
// pipe, its errors (assert messages, sanitizer reports) to /dev/null, and the parent prints one line.

#include "isolated_import.hpp"

#include "process/child_process.hpp"
#include "scene/data_paths.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>

namespace sandglass {

ImportedTriangles importInChildProcess(const std::string& path, double timeLimitSeconds) {
    ImportedTriangles failed;
    // Beside an installed executable or in the build tree (data_paths.hpp).
    const std::string helper = importHelperPath().string();
    if (helper.empty()) {
        failed.error = "cannot start the model importer: sandglass-import is neither beside the program nor in its build tree";
        return failed;
    }
    ChildCommand command;
    command.arguments = {helper, path};
    command.output = ChildStream::Pipe;
    ChildProcess child(command);
    if (!child.started()) {
        failed.error = "cannot start the model importer " + helper + " (" + child.error() + ")";
        return failed;
    }
    const auto limit = std::chrono::duration<double>(timeLimitSeconds);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(limit);
    std::string reply;
    const bool finished = child.readUntilClosed(deadline, &reply, nullptr);
    if (!finished) child.sendSignal(SIGKILL);
    const ChildExit exit = child.wait();
    if (!finished) {
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", timeLimitSeconds);
        failed.error = std::string("the model importer did not finish within ") + seconds +
                       " s (the file is probably corrupt)";
        return failed;
    }
    if (exit.signal != 0) {
        const char* name = sigabbrev_np(exit.signal);
        failed.error = "the model importer crashed on this file (signal " + std::to_string(exit.signal) +
                       (name ? std::string(", SIG") + name : std::string()) + "); the file is probably corrupt";
        return failed;
    }
    if (!exit.succeeded()) {
        failed.error = "the model importer failed (exit status " + std::to_string(exit.code) + ")";
        return failed;
    }
    return decodeImport({reinterpret_cast<const std::uint8_t*>(reply.data()), reply.size()});
}

} // namespace sandglass
