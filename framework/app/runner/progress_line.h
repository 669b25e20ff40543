#pragma once
// The progress of a long job on the terminal, one line: "[label] [#######       ] 40/120 frames, 3 s
// elapsed, ~6 s left". On a terminal the line redraws in place (at most 5 times a second); piped (logs,
// CI) it prints only at every tenth of the way when `piped` is set, and nothing otherwise, so the one-line
// errors of a piped run stay one line. Recordings and long headless runs use it; the bash and Python
// drivers print the same line (tools/progress.sh, tools/sweep.py).
#include <chrono>
#include <cstdio>
#include <string>

namespace pba::app {

class ProgressLine {
 public:
  ProgressLine(std::string label, long total, std::string unit, bool piped);
  /// Reports `done` of the total; the last call (done == total) ends the line.
  void update(long done);
  double elapsedSeconds() const;

 private:
  std::string label_, unit_;
  long total_;
  bool tty_, piped_;
  long lastTenth_ = -1;
  std::chrono::steady_clock::time_point started_, lastDrawn_;
};

/// The text of one progress line (tested without a terminal).
std::string progressText(const std::string& label, long done, long total, const std::string& unit, double elapsed);

}  // namespace pba::app
