// SPDX-License-Identifier: MIT
#include "scene/build_progress.hpp"

namespace sandglass {

const char* buildPhaseName(BuildPhase phase) {
    switch (phase) {
    case BuildPhase::Loading: return "loading the model";
    case BuildPhase::Voxelizing: return "voxelizing";
    case BuildPhase::FindingSandSpace: return "finding the sand space";
    case BuildPhase::Filling: return "filling";
    case BuildPhase::Done: return "done";
    }
    return "building";
}

float buildShareAtStart(BuildPhase phase) {
    // The hourglass's search for its bulbs and neck takes most of a model build; loading and
    // voxelizing are quick unless the file is huge.
    switch (phase) {
    case BuildPhase::Loading: return 0.0f;
    case BuildPhase::Voxelizing: return 0.1f;
    case BuildPhase::FindingSandSpace: return 0.2f;
    case BuildPhase::Filling: return 0.8f;
    case BuildPhase::Done: return 1.0f;
    }
    return 0.0f;
}

void BuildProgress::checkpoint(BuildPhase phase) {
    phase_ = phase;
    if (onPhase_) onPhase_(phase);
    if (cancelled_) throw BuildCancelled();
}

} // namespace sandglass
