// SPDX-License-Identifier: MIT
#include "view/render/gpu_frame_timer.hpp"

namespace sandglass {

GpuFrameTimer::~GpuFrameTimer() {
    if (queries_[0] != 0) glDeleteQueries(kRing, queries_.data());
}

void GpuFrameTimer::begin() {
    if (queries_[0] == 0) glGenQueries(kRing, queries_.data());
    if (running_) end();
    if (pending_[next_]) collect(next_);
    glBeginQuery(GL_TIME_ELAPSED, queries_[next_]);
    running_ = true;
}

void GpuFrameTimer::end() {
    if (!running_) return;
    glEndQuery(GL_TIME_ELAPSED);
    pending_[next_] = true;
    next_ = (next_ + 1) % kRing;
    running_ = false;
}

GpuTime GpuFrameTimer::take() {
    end();
    // Oldest first, though the order does not change the sum.
    for (int i = 0; i < kRing; ++i) {
        const int slot = (next_ + i) % kRing;
        if (pending_[slot]) collect(slot);
    }
    const GpuTime taken = total_;
    total_ = {};
    return taken;
}

void GpuFrameTimer::collect(int slot) {
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(queries_[slot], GL_QUERY_RESULT, &nanoseconds); // waits if not ready
    pending_[slot] = false;
    total_.frames += 1;
    total_.milliseconds += double(nanoseconds) / 1.0e6;
}

} // namespace sandglass
