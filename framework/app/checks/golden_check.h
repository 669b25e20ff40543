#pragma once
// Golden trajectories (docs/decisions/2026-12-02-golden-trajectories-bit-for-bit-or-within-tolerance.md): every
// registered scene of a lab is run headless from its defaults for a fixed number of frames and seed, and its state
// fingerprint (state_fingerprint.h: step count, clock, hash of everything drawn, metrics without timings) is compared
// with the one recorded in tests/golden/<lab>.json. The hidden lab options
//   --check-golden FILE    compare (exit 0 when every scene agrees, 1 when one differs, 2 for a bad file)
//   --update-golden FILE   rewrite FILE from this build (./pba golden --update does it for every lab)
// loop over the registry in one process, so a new scene is covered once its entry is regenerated.
#include <iosfwd>
#include <string>

namespace pba::app {

/// Display frames (1/60 s) each scene runs before its fingerprint is taken, unless --frames says otherwise.
inline constexpr long kDefaultGoldenFrames = 60;

struct GoldenOptions {
  std::string file;  ///< the golden file (tests/golden/<lab>.json)
  bool update = false;
  long frames = kDefaultGoldenFrames;  ///< used when writing; a check uses the file's own count
};

/// Checks (or rewrites) the golden file of lab `lab`; prints one line per scene to `out` and errors to
/// `err`. Returns the process exit code.
int runGoldenCheck(const std::string& lab, const GoldenOptions& options, std::ostream& out, std::ostream& err);

}  // namespace pba::app
