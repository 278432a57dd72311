// SPDX-License-Identifier: MIT
#pragma once
// Holds a scene build at one phase until the test lets it go, so the test acts while the build
// surely runs (SPEC I5). Declare it after the SceneHost or Application: it opens when destroyed,
// so a failed check never leaves the build thread waiting on it.

#include "scene/build_progress.hpp"

#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>

namespace sandglass::testing {

class PhaseGate {
public:
    explicit PhaseGate(BuildPhase at) : shared_(std::make_shared<Shared>()) { shared_->at = at; }
    ~PhaseGate() { open(); }
    PhaseGate(const PhaseGate&) = delete;
    PhaseGate& operator=(const PhaseGate&) = delete;

    /// For SceneHost::setBuildPhaseListener: a build that reaches the phase waits there until open().
    std::function<void(BuildPhase)> listener() const {
        return [shared = shared_](BuildPhase phase) {
            if (phase != shared->at) return;
            std::unique_lock lock(shared->mutex);
            shared->reached = true;
            shared->changed.notify_all();
            shared->changed.wait(lock, [&] { return shared->opened; });
        };
    }
    /// Waits until a build has reached the phase; false when none did within a minute.
    bool waitUntilReached() const {
        std::unique_lock lock(shared_->mutex);
        return shared_->changed.wait_for(lock, std::chrono::minutes(1), [&] { return shared_->reached; });
    }
    /// Lets every build waiting at the phase go on, and later ones pass.
    void open() {
        std::lock_guard lock(shared_->mutex);
        shared_->opened = true;
        shared_->changed.notify_all();
    }

private:
    struct Shared {
        BuildPhase at = BuildPhase::Done;
        std::mutex mutex;
        std::condition_variable changed;
        bool reached = false;
        bool opened = false;
    };
    std::shared_ptr<Shared> shared_;
};

} // namespace sandglass::testing
