// SPDX-License-Identifier: MIT
#include "view/render/thread_cpu_clock.hpp"

#include <chrono>
#include <ctime>

namespace sandglass {

double threadCpuMilliseconds() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) * 1000.0 + double(now.tv_nsec) / 1.0e6;
#else
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
#endif
}

} // namespace sandglass
