// Fuzz target: the command-line parser (app/runner/command_line.h) with the particles lab's flags. The input
// is split at line breaks into arguments. Besides no sanitizer report: an error is one line (the lab
// prints it after "pba-LAB: "), and a parsed command line gives a frame count within the bounds.
#include <cstdint>
#include <string>
#include <vector>

#include "app/runner/command_line.h"
#include "fuzz_check.h"

using namespace pba;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> args{"pba-fuzz"};
  for (std::size_t start = 0; start <= text.size() && args.size() < 64;) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    args.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  const Result<app::LabOptions> o = app::parseCommandLine(static_cast<int>(argv.size()), argv.data());
  if (!o) {
    fuzz::require(o.error().find('\n') == std::string::npos, "an error is one line", o.error());
    return 0;
  }
  const long frames = o.value().frameCount();
  fuzz::require(frames >= 1 && frames <= app::kMaxFrames + 1, "the frame count is within its bounds",
                std::to_string(frames));
  for (const app::ParamOverride& p : o.value().overrides) (void)app::overrideError(p, p.param + ": bad");
  return 0;
}
