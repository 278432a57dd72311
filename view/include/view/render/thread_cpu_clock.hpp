// SPDX-License-Identifier: MIT
#pragma once
// The calling thread's CPU time: what a frame costs the CPU, apart from waiting. With a software
// GL (Mesa's llvmpipe) the driver runs its vertex processing on the caller's thread inside the
// draw calls, so the renderer also measures those calls on their own (RenderStats).

namespace sandglass {

/// CPU time of the calling thread, ms (wall time where the platform has no thread clock).
double threadCpuMilliseconds();

} // namespace sandglass
