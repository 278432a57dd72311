// SPDX-License-Identifier: MIT
#pragma once
// GPU time of the frames drawn, read with timer queries. On a hardware GL the CPU's clock cannot
// see it: draw calls return at once and a driver waits for the GPU in the buffer swap, on some
// drivers spinning, so a GPU-bound frame looks like CPU work. The results come a few frames late;
// a small ring of queries keeps several frames in flight, and nothing is lost or counted twice.

#include <GL/glew.h>

#include <array>
#include <cstdint>

namespace sandglass {

/// Frames timed and their GPU time, ms.
struct GpuTime {
    std::int64_t frames = 0;   ///< frames whose time is in milliseconds
    double milliseconds = 0.0; ///< their GPU time, summed
    double perFrame() const { return frames > 0 ? milliseconds / double(frames) : 0.0; } ///< mean ms a frame
};

class GpuFrameTimer {
public:
    GpuFrameTimer() = default; ///< makes its queries at the first begin(): needs a current GL context then
    ~GpuFrameTimer();
    GpuFrameTimer(const GpuFrameTimer&) = delete;
    GpuFrameTimer& operator=(const GpuFrameTimer&) = delete;

    /// Starts timing a frame's GL commands; waits only when every query of the ring is still
    /// pending (a GPU several frames behind). One frame at a time: end() before the next begin().
    void begin();
    /// Ends the frame begun last.
    void end();
    /// Waits for the frames still pending and returns everything timed since the last take(),
    /// then starts counting afresh.
    GpuTime take();

private:
    void collect(int slot); // adds the slot's result (waiting for it) and frees the slot

    static constexpr int kRing = 4;
    std::array<GLuint, kRing> queries_{};
    std::array<bool, kRing> pending_{};
    int next_ = 0;
    bool running_ = false;
    GpuTime total_;
};

} // namespace sandglass
