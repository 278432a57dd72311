// SPDX-License-Identifier: MIT
#include "app/cli/terminal_progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sandglass {

namespace {

std::string clockText(double seconds) {
    const long whole = long(std::max(0.0, seconds) + 0.5);
    char text[32];
    if (whole >= 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", whole / 3600, whole / 60 % 60, whole % 60);
    else
        std::snprintf(text, sizeof text, "%ld:%02ld", whole / 60, whole % 60);
    return text;
}

constexpr const char* kClearLine = "\r\033[K";

} // namespace

bool stderrIsTerminal() { return isatty(STDERR_FILENO) == 1; }

std::string progressLine(const std::string& what, double done, double total, const std::string& unit, double seconds) {
    const double rate = seconds > 0.0 ? done / seconds : 0.0;
    char text[160];
    if (total > 0.0) {
        const double share = std::clamp(done / total, 0.0, 1.0);
        constexpr int kWidth = 20;
        std::string bar(std::size_t(kWidth), '.');
        std::fill_n(bar.begin(), int(share * kWidth), '#');
        const std::string left = rate > 0.0 ? clockText((total - done) / rate) + " left" : "";
        std::snprintf(text, sizeof text, "%s [%s] %3.0f%%  %.0f %s/s  %s", what.c_str(), bar.c_str(), share * 100.0,
                      rate, unit.c_str(), left.c_str());
    } else {
        std::snprintf(text, sizeof text, "%s  %.0f %s  %.0f %s/s  %s", what.c_str(), done, unit.c_str(), rate,
                      unit.c_str(), clockText(seconds).c_str());
    }
    return text;
}

TerminalProgress::TerminalProgress(std::string what, std::string unit, bool enabled, std::FILE* out,
                                   std::chrono::milliseconds firstDrawAfter)
    : what_(std::move(what)), unit_(std::move(unit)), enabled_(enabled), out_(out), start_(Clock::now()),
      nextDraw_(start_ + firstDrawAfter) {}

void TerminalProgress::update(double done, double total) {
    if (!enabled_) return;
    const Clock::time_point now = Clock::now();
    if (now < nextDraw_) return;
    nextDraw_ = now + std::chrono::milliseconds(500);
    const double seconds = std::chrono::duration<double>(now - start_).count();
    std::fprintf(out_, "%s%s", kClearLine, progressLine(what_, done, total, unit_, seconds).c_str());
    std::fflush(out_);
    shown_ = true;
}

void TerminalProgress::finish() {
    if (!shown_) return;
    std::fprintf(out_, "%s", kClearLine);
    std::fflush(out_);
    shown_ = false;
}

ElapsedTicker::ElapsedTicker(std::string what, std::ostream& log, bool enabled)
    : what_(std::move(what)), log_(log), enabled_(enabled), buffer_(*this, log.rdbuf()), stream_(&buffer_),
      start_(std::chrono::steady_clock::now()) {
    if (enabled_) thread_ = std::thread([this] { run(); });
}

ElapsedTicker::~ElapsedTicker() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
        clearLine();
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
    log_.flush();
}

void ElapsedTicker::clearLine() {
    if (!shown_) return;
    log_.rdbuf()->sputn(kClearLine, 4);
    log_.rdbuf()->pubsync();
    shown_ = false;
}

void ElapsedTicker::run() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(500), [this] { return stop_; })) {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        // Short work shows nothing, and a log line half written is never drawn over.
        if (seconds < 1.0 || !atLineStart_) continue;
        const std::string line = std::string(kClearLine) + what_ + "  " + clockText(seconds) + " so far";
        log_.rdbuf()->sputn(line.data(), std::streamsize(line.size()));
        log_.rdbuf()->pubsync();
        shown_ = true;
    }
}

int ElapsedTicker::ClearingBuffer::overflow(int c) {
    if (c == traits_type::eof()) return traits_type::not_eof(c);
    const char ch = char(c);
    return xsputn(&ch, 1) == 1 ? c : traits_type::eof();
}

std::streamsize ElapsedTicker::ClearingBuffer::xsputn(const char* text, std::streamsize count) {
    std::lock_guard<std::mutex> lock(owner_.mutex_);
    owner_.clearLine();
    if (count > 0) owner_.atLineStart_ = text[count - 1] == '\n';
    return target_->sputn(text, count);
}

} // namespace sandglass
