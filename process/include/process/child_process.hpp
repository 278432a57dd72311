// SPDX-License-Identifier: MIT
#pragma once
// Another program as a child process, started with posix_spawn: no shell (the arguments go as
// they are), standard input from /dev/null, and no descriptor of the parent but the pipes asked
// for (not the display's socket, not a GPU file). posix_spawn does not run code of ours between
// fork and exec, so it is safe in a process with threads, where a lock another thread holds at
// a fork would stay locked in the child.

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sandglass {

/// Where a child's standard output or standard error goes.
enum class ChildStream {
    Null, ///< /dev/null
    Pipe, ///< a pipe the parent reads
};

/// A program to run and how.
struct ChildCommand {
    /// The program, then its arguments. A program name without '/' is looked up in PATH.
    std::vector<std::string> arguments;
    std::filesystem::path folder;            ///< the folder it runs in (a relative program path too); empty: the parent's
    ChildStream output = ChildStream::Null;  ///< its standard output
    ChildStream errors = ChildStream::Null;  ///< its standard error
    bool ownProcessGroup = false;            ///< a process group of its own: a signal reaches what it starts too
};

/// How a child ended.
struct ChildExit {
    int code = -1;   ///< its exit status when it exited, else -1
    int signal = 0;  ///< the signal that ended it, else 0
    bool succeeded() const { return code == 0; } ///< exited with status 0
};

/// A started child process. Destroying it while the child runs kills it (SIGKILL, to its group
/// when it has one) and waits for it, so no child outlives its owner or stays a zombie.
class ChildProcess {
public:
    /// Starts the command; on failure started() is false and error() says why.
    explicit ChildProcess(const ChildCommand& command);
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    bool started() const { return id_ > 0; }             ///< the program runs (or ran)
    const std::string& error() const { return error_; }  ///< why it did not start; empty when it did
    pid_t id() const { return id_; }                     ///< its process id; -1 when it did not start

    /// Reads the pipes into `output` and `errors` (either may be null for a stream that is not a
    /// pipe) until the child closes them or `deadline` passes; false when the deadline passed.
    bool readUntilClosed(std::chrono::steady_clock::time_point deadline, std::string* output, std::string* errors);
    /// Appends what the output pipe holds now to `output`, without waiting.
    void readAvailableOutput(std::string& output);

    /// Sends `signal` to the child, or to its process group when it has its own; nothing once it has been waited for.
    void sendSignal(int signal);
    /// Waits until the child ends; how it ended (code -1 for a child that did not start).
    ChildExit wait();
    /// How the child ended, once it has; nothing while it runs. Its pipes stay open, so what
    /// it wrote last can still be read.
    std::optional<ChildExit> exited();

private:
    void closePipes();

    pid_t id_ = -1;
    bool ownGroup_ = false;
    bool waited_ = false;
    ChildExit exit_;
    int output_ = -1; // read ends of the pipes, or -1
    int errors_ = -1;
    std::string error_;
};

} // namespace sandglass
