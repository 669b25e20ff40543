#pragma once
// Exercise stubs (docs/architecture.md §5). In the student release every solution block is replaced by a stub
// that calls notImplemented("TAG", safeDefault): it records the tag, so the lab can show a banner,
// and returns a safe default so that every lab still runs.
//
// The record is process-wide on purpose: it is instrumentation read by the lab runner, never solver
// state, and it is the one exception to the library's "no globals" rule (docs/architecture.md).
#include <atomic>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pba::exercises {

/// Records that exercise `tag` (e.g. "HELLO-1") ran as a stub. Thread-safe.
void markNotImplemented(std::string_view tag);
/// Tags recorded so far, sorted, without repeats.
std::vector<std::string> notImplementedTags();
/// The tags of those stubs that ran outside the start-up probes (runProbes): the computation in hand
/// needed them. The test main reports a failing test whose code path ran one as skipped ("needs TAG").
std::vector<std::string> notImplementedTagsUsed();
/// Whether notImplementedTagsUsed() is not empty: one lock-free load, safe in a signal handler (the test
/// main's, when a stub's safe default leads to a floating-point trap).
bool anyNotImplementedUsed();
/// Forgets every record (tests use it).
void clearNotImplemented();

/// Records `tag` and hands back `safeDefault`: the one line a stub consists of. The exercise's other
/// inputs may be passed after it (ignored), so that the stub compiles without unused-parameter warnings:
///   return exercises::notImplemented("HELLO-1", state, acceleration, h);
template <typename T, typename... Inputs>
T notImplemented(std::string_view tag, T safeDefault, const Inputs&... /*inputsTheSolutionUses*/) {
  markNotImplemented(tag);
  return safeDefault;
}

/// The run-time switch of the isolation build (`tools/student_release.sh --switchable`, used by
/// tools/check_exercise_isolation.py). That tool rewrites every solution block as
///   static const ExerciseSwitch pbaExerciseSwitch("TAG");
///   if (pbaExerciseSwitch.stub()) { <the stub lines>; return; }
///   <the solution>
/// so that one build can run any set of exercises as stubs, chosen per process by the environment:
///   PBA_STUB_EXERCISES=IK-3,PART-2   (or "all")  these tags run their stubs, every other its solution
///   PBA_EXERCISE_TRACE=FILE          each tag whose code runs (outside start-up probes) is appended to
///                                    FILE once per process, one tag a line
/// Neither variable has any effect on the ordinary build, which never constructs a switch.
class ExerciseSwitch {
 public:
  explicit ExerciseSwitch(std::string_view tag);
  /// True when this process runs the exercise's stub. Cheap: one relaxed atomic load after the first call.
  bool stub() const {
    if (!traced_.load(std::memory_order_relaxed)) noteFirstRun();
    return stub_;
  }

 private:
  void noteFirstRun() const;
  std::string tag_;
  bool stub_ = false;
  mutable std::atomic<bool> traced_{false};
};

/// A probe calls an exercise once on a harmless input so that a lab can tell at start-up which
/// exercises are still stubs (a stub records its tag when it runs). Registered next to the
/// exercise with PBA_EXERCISE_PROBE; never inside a solution block.
bool registerProbe(void (*probe)());
/// Runs every registered probe; afterwards notImplementedTags() names every stubbed exercise.
void runProbes();

}  // namespace pba::exercises

#define PBA_EXERCISE_PROBE_CONCAT_INNER(a, b) a##b
#define PBA_EXERCISE_PROBE_CONCAT(a, b) PBA_EXERCISE_PROBE_CONCAT_INNER(a, b)
/// PBA_EXERCISE_PROBE(eulerStep(BallState{}, Vec3(0.0), 0.01)); at namespace scope.
#define PBA_EXERCISE_PROBE(call)                                             \
  static const bool PBA_EXERCISE_PROBE_CONCAT(pbaExerciseProbe_, __LINE__) = \
      ::pba::exercises::registerProbe([] { static_cast<void>(call); })
