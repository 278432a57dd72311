// SPDX-License-Identifier: MIT
// sandglass-import: the model importer as its own process. loadMesh starts it with posix_spawn
// (import_in_child_process.cpp), so nothing of the parent's state, no lock another thread held,
// reaches the process that runs assimp. It writes the encoded triangle list (or one line of
// error) to stdout and exits.

#include "isolated_import.hpp"

#include <cerrno>
#include <sys/resource.h>
#include <unistd.h>

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    const rlimit noCore{0, 0}; // a crash on a corrupt file is expected: no core file
    ::setrlimit(RLIMIT_CORE, &noCore);
    std::vector<std::uint8_t> reply;
    try {
        reply = sandglass::encodeImport(sandglass::importInThisProcess(argv[1]));
    } catch (...) {
        sandglass::ImportedTriangles failed;
        failed.error = "the importer ran out of memory or failed";
        reply = sandglass::encodeImport(failed);
    }
    std::size_t done = 0;
    while (done < reply.size()) {
        const ssize_t n = ::write(STDOUT_FILENO, reply.data() + done, reply.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return 3;
        done += std::size_t(n);
    }
    // _exit: nothing left to clean up, and a leak check at exit (ASan builds) must not turn a
    // finished import into a failure.
    ::_exit(0);
}
