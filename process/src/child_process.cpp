// SPDX-License-Identifier: MIT
#include "process/child_process.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace sandglass {

namespace {

// A pipe whose ends are closed on exec; the child gets its write end through a dup2, which
// clears that flag on the copy.
bool openPipe(int ends[2]) { return ::pipe2(ends, O_CLOEXEC) == 0; }

void closeIfOpen(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

ChildExit exitOf(int status) {
    ChildExit exit;
    if (WIFEXITED(status)) exit.code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) exit.signal = WTERMSIG(status);
    return exit;
}

// Reads what `fd` holds now into `sink`; false once the writer has closed it (or it failed).
bool readAvailable(int fd, std::string* sink) {
    char buffer[65536];
    for (;;) {
        const ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got > 0) {
            if (sink) sink->append(buffer, std::size_t(got));
            continue;
        }
        if (got < 0 && errno == EINTR) continue;
        return got < 0 && errno == EAGAIN; // nothing more yet
    }
}

} // namespace

ChildProcess::ChildProcess(const ChildCommand& command) {
    if (command.arguments.empty()) {
        error_ = "no program named";
        return;
    }
    int outputPipe[2] = {-1, -1}, errorPipe[2] = {-1, -1};
    if ((command.output == ChildStream::Pipe && !openPipe(outputPipe)) ||
        (command.errors == ChildStream::Pipe && !openPipe(errorPipe))) {
        error_ = std::string("no pipe (") + std::strerror(errno) + ")";
        for (int* fd : {&outputPipe[0], &outputPipe[1], &errorPipe[0], &errorPipe[1]}) closeIfOpen(*fd);
        return;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    const auto route = [&](int stream, int pipeEnd) {
        if (pipeEnd >= 0)
            posix_spawn_file_actions_adddup2(&actions, pipeEnd, stream);
        else
            posix_spawn_file_actions_addopen(&actions, stream, "/dev/null", O_WRONLY, 0);
    };
    route(STDOUT_FILENO, outputPipe[1]);
    route(STDERR_FILENO, errorPipe[1]);
    const std::string folder = command.folder.string();
    if (!folder.empty()) posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
    posix_spawn_file_actions_addclosefrom_np(&actions, 3);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    if (command.ownProcessGroup) {
        posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
        posix_spawnattr_setpgroup(&attributes, 0);
    }
    std::vector<char*> arguments;
    for (const std::string& argument : command.arguments) arguments.push_back(const_cast<char*>(argument.c_str()));
    arguments.push_back(nullptr);
    const char* program = arguments[0];
    pid_t child = -1;
    // Where exec fails (no such program, not executable, no such folder) posix_spawn says so
    // itself: glibc's child reports it before the call returns.
    const int failed = std::strchr(program, '/') != nullptr
                           ? ::posix_spawn(&child, program, &actions, &attributes, arguments.data(), environ)
                           : ::posix_spawnp(&child, program, &actions, &attributes, arguments.data(), environ);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    closeIfOpen(outputPipe[1]);
    closeIfOpen(errorPipe[1]);
    if (failed != 0) {
        error_ = std::strerror(failed);
        closeIfOpen(outputPipe[0]);
        closeIfOpen(errorPipe[0]);
        return;
    }
    id_ = child;
    ownGroup_ = command.ownProcessGroup;
    output_ = outputPipe[0];
    errors_ = errorPipe[0];
    for (int fd : {output_, errors_})
        if (fd >= 0) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
}

ChildProcess::~ChildProcess() {
    if (started() && !waited_) {
        sendSignal(SIGKILL);
        wait();
    }
    closePipes();
}

void ChildProcess::closePipes() {
    closeIfOpen(output_);
    closeIfOpen(errors_);
}

bool ChildProcess::readUntilClosed(std::chrono::steady_clock::time_point deadline, std::string* output, std::string* errors) {
    pollfd watch[2] = {{output_, POLLIN, 0}, {errors_, POLLIN, 0}};
    std::string* sinks[2] = {output, errors};
    int* ends[2] = {&output_, &errors_};
    for (;;) {
        if (output_ < 0 && errors_ < 0) return true;
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return false;
        for (int i = 0; i < 2; ++i) watch[i].fd = *ends[i];
        const int ready = ::poll(watch, 2, int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0) return true; // taken as closed pipes: what came is used as it is
        for (int i = 0; i < 2; ++i)
            if (*ends[i] >= 0 && (watch[i].revents & (POLLIN | POLLHUP | POLLERR)) != 0 && !readAvailable(*ends[i], sinks[i]))
                closeIfOpen(*ends[i]);
    }
}

void ChildProcess::readAvailableOutput(std::string& output) {
    if (output_ >= 0 && !readAvailable(output_, &output)) closeIfOpen(output_);
}

void ChildProcess::sendSignal(int signal) {
    if (!started() || waited_) return;
    ::kill(ownGroup_ ? -id_ : id_, signal);
}

ChildExit ChildProcess::wait() {
    if (!started() || waited_) return exit_;
    int status = 0;
    while (::waitpid(id_, &status, 0) < 0 && errno == EINTR) {
    }
    waited_ = true;
    exit_ = exitOf(status);
    return exit_;
}

std::optional<ChildExit> ChildProcess::exited() {
    if (!started()) return std::nullopt;
    if (waited_) return exit_;
    int status = 0;
    const pid_t done = ::waitpid(id_, &status, WNOHANG);
    if (done == 0 || (done < 0 && errno == EINTR)) return std::nullopt;
    // done < 0: it cannot be waited for (already reaped): ended, how is not known.
    waited_ = true;
    if (done < 0) return exit_;
    exit_ = exitOf(status);
    return exit_;
}

} // namespace sandglass
