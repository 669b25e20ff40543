#include "app/runner/progress_line.h"

#include <algorithm>

#include "app/runner/host_system.h"

namespace pba::app {

std::string progressText(const std::string& label, long done, long total, const std::string& unit, double elapsed) {
  constexpr int kWidth = 30;
  const long shown = std::clamp(done, 0L, std::max(total, 1L));
  const int filled = total > 0 ? static_cast<int>(kWidth * shown / total) : 0;
  char tail[128];
  if (done > 0 && done < total)
    std::snprintf(tail, sizeof tail, "%ld/%ld %s, %.0f s elapsed, ~%.0f s left", done, total, unit.c_str(), elapsed,
                  elapsed / static_cast<double>(done) * static_cast<double>(total - done));
  else
    std::snprintf(tail, sizeof tail, "%ld/%ld %s, %.0f s elapsed", done, total, unit.c_str(), elapsed);
  return "[" + label + "] [" + std::string(static_cast<std::size_t>(filled), '#') +
         std::string(static_cast<std::size_t>(kWidth - filled), ' ') + "] " + tail;
}

ProgressLine::ProgressLine(std::string label, long total, std::string unit, bool piped)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      tty_(standardErrorIsTerminal()),
      piped_(piped),
      started_(std::chrono::steady_clock::now()),
      lastDrawn_(started_) {}

double ProgressLine::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

void ProgressLine::update(long done) {
  if (total_ <= 0) return;
  const bool last = done >= total_;
  const auto now = std::chrono::steady_clock::now();
  if (tty_) {
    if (!last && now - lastDrawn_ < std::chrono::milliseconds(200)) return;
    lastDrawn_ = now;
    std::fprintf(stderr, "\r%s%s", progressText(label_, done, total_, unit_, elapsedSeconds()).c_str(),
                 last ? "\n" : "");
    std::fflush(stderr);
    return;
  }
  const long tenth = 10 * done / total_;
  if (!piped_ || tenth == lastTenth_) return;
  lastTenth_ = tenth;
  std::fprintf(stderr, "%s\n", progressText(label_, done, total_, unit_, elapsedSeconds()).c_str());
}

}  // namespace pba::app
