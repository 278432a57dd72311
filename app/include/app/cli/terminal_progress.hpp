// SPDX-License-Identifier: MIT
#pragma once
// SPEC U4: long command-line work shows where it stands on an interactive terminal: a bar with
// the rate and the time left when the end is known, the count, rate and time so far when it is
// not. Only on stderr and only when stderr is a terminal, so --json, pipes and logs get nothing
// extra.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <ostream>
#include <streambuf>
#include <string>
#include <thread>

namespace sandglass {

/// True when stderr is an interactive terminal.
bool stderrIsTerminal();

/// The progress line for `done` of `total` units (total 0: unknown) after `seconds`, e.g.
/// "simulate [########............]  40%  1234 steps/s  0:12 left" or
/// "simulate  12345 steps  1234 steps/s  0:10". Pure, for tests.
std::string progressLine(const std::string& what, double done, double total, const std::string& unit, double seconds);

/// A progress line redrawn in place on stderr at most twice a second, from the second second on
/// (short work shows nothing); nothing at all when disabled.
class TerminalProgress {
public:
    explicit TerminalProgress(std::string what, std::string unit, bool enabled = stderrIsTerminal(),
                              std::FILE* out = stderr, std::chrono::milliseconds firstDrawAfter = std::chrono::seconds(1));
    ~TerminalProgress() { finish(); }
    TerminalProgress(const TerminalProgress&) = delete;
    TerminalProgress& operator=(const TerminalProgress&) = delete;

    /// Cheap when nothing is due: one clock read.
    void update(double done, double total = 0.0);
    /// Clears the line (the result that follows starts on a clean line).
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    std::string what_, unit_;
    bool enabled_ = false, shown_ = false;
    std::FILE* out_;
    Clock::time_point start_, nextDraw_;
};

/// For work with no count to report (one model voxelized, a report of many stages): the elapsed
/// time, redrawn every half second by a thread, under the lines the work itself writes to
/// `log`. While it runs, write log lines through stream(): each clears the ticker's line first.
class ElapsedTicker {
public:
    ElapsedTicker(std::string what, std::ostream& log, bool enabled = stderrIsTerminal());
    ~ElapsedTicker();
    ElapsedTicker(const ElapsedTicker&) = delete;
    ElapsedTicker& operator=(const ElapsedTicker&) = delete;

    std::ostream& stream() { return stream_; } ///< `log`, with the ticker's line cleared before each write

private:
    class ClearingBuffer : public std::streambuf {
    public:
        ClearingBuffer(ElapsedTicker& owner, std::streambuf* target) : owner_(owner), target_(target) {}

    protected:
        int overflow(int c) override;
        std::streamsize xsputn(const char* text, std::streamsize count) override;
        int sync() override { return target_->pubsync(); }

    private:
        ElapsedTicker& owner_;
        std::streambuf* target_;
    };
    void clearLine(); // with mutex_ held
    void run();

    std::string what_;
    std::ostream& log_;
    bool enabled_;
    ClearingBuffer buffer_;
    std::ostream stream_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false, shown_ = false, atLineStart_ = true;
    std::chrono::steady_clock::time_point start_;
    std::thread thread_;
};

} // namespace sandglass
