#pragma once
// Soak test (docs/decisions/2026-12-02-soak-runs-with-a-scripted-user.md): the hidden lab option `--soak SECONDS
// [--seed N]` drives a lab's LabSession, the object behind the window's keys and mouse, headless for SECONDS of wall
// time with a scripted user: drags through each scene's pick()/drag() interface, nudges, parameter changes within
// their declared ranges, presets, resets, pauses, single steps, rewinds and scene switches, all drawn from one random
// stream seeded by --seed. Every lab, including one added later, is covered without code of its own. It fails on
//   - an instability in a passive scene (untouched since its last reset): any guard pause at the defaults,
//     a non-finite state under a preset (a preset may show a blow-up on purpose, "symplectic: boom": the
//     guard must pause it while the state is still finite; such presets are listed). After a parameter
//     change, a drag or a nudge the guard's pause is its job (counted, then the scene's defaults again);
//   - an exception or a crash (the process dies; ./pba soak reports the exit status);
//   - a stalled frame: one frame or action taking longer than kSoakStallSeconds of wall time (a real hang is
//     caught by the time limit of ./pba soak and of the ctest);
//   - memory growing after warm-up by more than 1 % of the resident size: each time a scene has just been
//     loaded at its defaults (the previous scene, its rewind history and plots gone) the bytes held through
//     malloc (mallinfo2) and the resident set size (after malloc_trim) are read; the peak of the first after
//     warm-up (the first visit of every scene and at least the first quarter of the run) may exceed its
//     peak during warm-up by at most 1 % of the resident size then. The growth is measured on the heap, not
//     on the resident size itself, because pages of code and relocated data that a late first call touches
//     grow the resident size of a small process by about 1 % in the first minutes without any leak; a leak
//     grows both. Not judged in sanitizer builds (their allocator keeps freed memory in quarantine) or when
//     the run is too short to load a scene after warm-up.
// The sequence of actions depends on the seed alone (how far it gets, on the machine's speed), so a
// failure is reproduced by the same seed; the message lists the last actions before it.
#include <cstdint>
#include <iosfwd>
#include <string>

namespace pba::app {

inline constexpr double kSoakStallSeconds = 30.0;    ///< [s] wall time of one frame or action that counts as a hang
inline constexpr double kSoakMemoryGrowth = 0.01;    ///< growth allowed after warm-up, a fraction of resident memory
inline constexpr double kSoakWarmupFraction = 0.25;  ///< of the run's duration, at least

/// For `--soak`, before anything else runs: execs the program again with glibc's per-thread malloc cache
/// off (GLIBC_TUNABLES), whose freed chunks mallinfo2 would count as memory in use. Returns when the cache
/// is already off, in sanitizer builds, or when exec fails (the soak then measures with the cache on).
void restartWithoutThreadCache(const char* const* argv);
/// The cache is off in this process (the soak's report says which).
bool threadCacheOff();

struct SoakOptions {
  double seconds = 60.0;  ///< [s] wall time
  std::uint64_t seed = 1;
};

/// Runs the soak; prints a summary to `out` and each failure to `err`. Returns the process exit code
/// (0 passed, 1 failed).
int runSoak(const std::string& lab, const SoakOptions& options, std::ostream& out, std::ostream& err);

}  // namespace pba::app
