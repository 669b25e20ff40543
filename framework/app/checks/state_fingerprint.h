#pragma once
// A fingerprint of a run's state for the rewind check and determinism tests: the step count, the
// simulated time, a hash of everything the scene draws (positions, sizes, orientations and colours of
// every primitive, bit for bit; text labels are left out, since they may print timings) and the scene's
// metrics without their timings. Two states agree when their fingerprints are equal.
#include <cstdint>

#include <nlohmann/json.hpp>

#include "app/runner/scene_runner.h"

namespace pba::app {

/// FNV-1a 64 over the bytes of every primitive `scene` draws.
std::uint64_t drawHash(const Scene& scene);

/// {"steps", "sim_time_s", "draw_hash" (16 hex digits), "metrics"}.
nlohmann::json stateFingerprint(const SceneRunner& runner);

}  // namespace pba::app
