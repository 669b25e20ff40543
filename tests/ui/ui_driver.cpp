#include "ui_driver.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace pba::uitest {
namespace {

using Clock = std::chrono::steady_clock;
// How often a wait looks at the status file. Polling, not synchronisation: every wait ends on its
// condition (or its deadline), never on the passing of time.
constexpr std::chrono::milliseconds kPollInterval{5};

std::string run(const std::string& command) {
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    std::array<char, 256> buffer{};
    while (fgets(buffer.data(), buffer.size(), pipe)) out += buffer.data();
    pclose(pipe);
  }
  return out;
}

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string brief(const json& status) {
  if (!status.is_object()) return "(no status yet)";
  json b = json::object();
  for (const char* k :
       {"frame", "scene", "steps", "sim_time_s", "paused", "lecture", "ui_hidden", "help_shown", "message", "notice"})
    if (status.contains(k)) b[k] = status[k];
  return b.dump();
}

}  // namespace

Rect Rect::intersect(const Rect& o) const {
  Rect r{std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
  if (r.x1 < r.x0) r.x1 = r.x0;
  if (r.y1 < r.y0) r.y1 = r.y0;
  return r;
}

Rect Rect::fromJson(const json& j) {
  return Rect{j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>(), j.at(3).get<double>()};
}

std::pair<int, int> displaySize() {
  int w = 1280, h = 720;
  std::istringstream(run("xdotool getdisplaygeometry 2>/dev/null")) >> w >> h;
  return {w, h};
}

void expect(bool condition, const std::string& message) {
  if (!condition) throw CheckFailed(message);
}

LabWindow::LabWindow(std::string exe, std::vector<std::string> args, std::string workDir)
    : exe_(std::move(exe)), work_(std::move(workDir)), statusPath_(work_ + "/status.json") {
  // The window fills the display (1280×720 or 1920×1080): settings of a fresh lab name its size.
  const std::string lab = std::filesystem::path(exe_).filename().string().substr(4);  // pba-<lab>
  const std::filesystem::path settings = std::filesystem::path(work_) / "config" / "pba-labs" / lab / "settings.json";
  std::filesystem::create_directories(settings.parent_path());
  if (!std::filesystem::exists(settings)) {
    const auto [w, h] = displaySize();
    std::ofstream(settings) << json{{"window_width", w}, {"window_height", h}}.dump() << '\n';
  }
  std::filesystem::remove(statusPath_);
  pid_ = fork();
  if (pid_ == 0) {
    if (chdir(work_.c_str()) != 0) _exit(127);
    setenv("PBA_UI_STATUS", statusPath_.c_str(), 1);
    setenv("XDG_CONFIG_HOME", (work_ + "/config").c_str(), 1);
    const std::string log = work_ + "/lab-stderr.txt";
    if (FILE* f = freopen(log.c_str(), "a", stderr); !f) _exit(127);
    std::vector<char*> argv{const_cast<char*>(exe_.c_str())};
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(exe_.c_str(), argv.data());
    _exit(127);
  }
  expect(pid_ > 0, "cannot start " + exe_);
  waitFor([](const json& s) { return s.value("frame", 0) >= 2; }, "the first frames");
  // The lab's only window on this display; its id is what xdotool moves the pointer in.
  for (int attempt = 0; attempt < 200 && window_.empty(); ++attempt) {
    std::istringstream ids(run("xdotool search --pid " + std::to_string(pid_) + " 2>/dev/null"));
    std::string id;
    while (ids >> id) window_ = id;  // the last one is the top-level window
    if (window_.empty()) frames(1);
  }
  expect(!window_.empty(), "xdotool finds no window of pid " + std::to_string(pid_));
  xdotool("windowfocus " + window_);
  const auto [x, y] = freePoint(status());
  move(x, y);  // the keyboard follows the pointer on a display without a window manager
  frames(1);
}

LabWindow::~LabWindow() {
  if (running()) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
}

bool LabWindow::running() {
  if (exitCode_ >= 0 || pid_ <= 0) return false;
  int wstatus = 0;
  if (waitpid(pid_, &wstatus, WNOHANG) == pid_) {
    exitCode_ = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
    return false;
  }
  return true;
}

json LabWindow::status() {
  std::ifstream in(statusPath_);
  if (in) {
    try {
      last_ = json::parse(in);
    } catch (const json::exception&) {
      // written through a rename, so this is only a file that is not there yet: keep the last one
    }
  }
  return last_;
}

json LabWindow::waitFor(const std::function<bool(const json&)>& ready, const std::string& what, double seconds) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  while (true) {
    const json s = status();
    if (s.is_object() && ready(s)) return s;
    // A hand-out's stubbed exercises can blow a scene up: once the guard has paused it, waiting on is
    // futile (a minute per wait); the check ends here and reports itself skipped (ui_check.cpp's main).
    if (s.is_object() && !s.value("stubbed_exercises", json::array()).empty() && !s.value("guard", "").empty())
      throw CheckFailed("the guard paused the scene while waiting for " + what + ": " + s["guard"].get<std::string>());
    if (!running()) {
      std::ifstream log(work_ + "/lab-stderr.txt");
      std::stringstream text;
      text << log.rdbuf();
      throw CheckFailed("the lab exited with code " + std::to_string(exitCode_) + " while waiting for " + what +
                        "; its stderr: " + text.str());
    }
    if (Clock::now() > deadline)
      throw CheckFailed("timed out after " + std::to_string(seconds) + " s waiting for " + what + "; last status " +
                        brief(s));
    std::this_thread::sleep_for(kPollInterval);
  }
}

json LabWindow::frames(int n) {
  const long target = status().value("frame", 0L) + n;
  return waitFor([target](const json& s) { return s.value("frame", 0L) >= target; },
                 std::to_string(n) + " more frames");
}

void LabWindow::xdotool(const std::string& arguments) {
  const std::string command = "xdotool " + arguments + " >/dev/null 2>&1";
  expect(std::system(command.c_str()) == 0, "xdotool failed: " + command);
}

void LabWindow::key(const std::string& name) { xdotool("key --clearmodifiers " + name); }
void LabWindow::type(const std::string& text) { xdotool("type --delay 1 " + quote(text)); }
void LabWindow::move(double x, double y) {
  xdotool("mousemove --window " + window_ + " " + std::to_string(std::lround(x)) + " " +
          std::to_string(std::lround(y)));
}
void LabWindow::press(int button) { xdotool("mousedown " + std::to_string(button)); }
void LabWindow::release(int button) { xdotool("mouseup " + std::to_string(button)); }
void LabWindow::wheel(int steps) {
  if (steps == 0) return;
  xdotool("click --repeat " + std::to_string(std::abs(steps)) + " --delay 1 " + (steps > 0 ? "4" : "5"));
}

void LabWindow::drag(int button, double fromX, double fromY, double toX, double toY, int steps) {
  move(fromX, fromY);
  frames(2);
  press(button);
  frames(2);
  for (int i = 1; i <= steps; ++i) {
    move(fromX + (toX - fromX) * i / steps, fromY + (toY - fromY) * i / steps);
    frames(2);
  }
  release(button);
  frames(2);
}

/// True when `r` lies wholly inside one of the status's windows, clear of its bottom edge (a widget cut
/// by the panel's edge is not safely clickable).
bool wholeInWindow(const json& s, const Rect& r) {
  for (const auto& [window, rect] : windows(s))
    if (rect.contains(r.x0, r.y0) && rect.contains(r.x1, r.y1) && r.y1 < rect.y1 - 4) return true;
  return false;
}

void LabWindow::click(double x, double y) {
  move(x, y);
  frames(2);
  press(1);
  frames(2);
  release(1);
  frames(2);
}

void LabWindow::clickWidget(const std::string& name, const std::string& headerToOpen) {
  bool headerClicked = headerToOpen.empty();
  for (int attempt = 0; attempt < 60; ++attempt) {
    const json s = frames(1);
    const json& widgets = s.at("widgets");
    if (widgets.contains(name) && wholeInWindow(s, Rect::fromJson(widgets[name]))) {
      const Rect r = Rect::fromJson(widgets[name]);
      click(r.x0 + std::min(0.5 * r.width(), 0.5 * r.height()),
            0.5 * (r.y0 + r.y1));  // a checkbox's box, a field's start
      return;
    }
    const std::string header = "header:" + headerToOpen;
    if (!headerClicked && !widgets.contains(name) && widgets.contains(header) &&
        wholeInWindow(s, Rect::fromJson(widgets[header]))) {
      const Rect h = Rect::fromJson(widgets[header]);
      click(h.x0 + 0.5 * h.height(), 0.5 * (h.y0 + h.y1));  // on the arrow
      headerClicked = true;
      continue;
    }
    // Not (wholly) on screen yet: scroll the control panel down with the wheel over it.
    for (const auto& [window, rect] : windows(s))
      if (window.find("###panel") != std::string::npos) move(0.5 * (rect.x0 + rect.x1), 0.5 * (rect.y0 + rect.y1));
    frames(1);
    wheel(-3);
  }
  throw CheckFailed("the widget '" + name + "' never showed on screen");
}

int LabWindow::close() {
  if (running()) kill(pid_, SIGTERM);
  const auto deadline = Clock::now() + std::chrono::duration<double>(kWaitSeconds);
  while (running() && Clock::now() < deadline) std::this_thread::sleep_for(kPollInterval);
  expect(!running(), "the lab did not close after SIGTERM");
  return exitCode_;
}

std::vector<std::string> listScenes(const std::string& exe) {
  std::vector<std::string> names;
  std::istringstream lines(run(quote(exe) + " --list-scenes"));
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string name;
    if (words >> name) names.push_back(name);
  }
  return names;
}

std::vector<std::pair<std::string, Rect>> windows(const json& status) {
  std::vector<std::pair<std::string, Rect>> out;
  for (const json& w : status.at("windows"))
    out.emplace_back(w.at("name").get<std::string>(), Rect::fromJson(w.at("rect")));
  return out;
}

bool isFree(const json& status, double x, double y, double margin) {
  const double w = status.at("viewport").at(0).get<double>(), h = status.at("viewport").at(1).get<double>();
  if (x < margin || y < margin || x > w - margin || y > h - margin) return false;
  for (const auto& [name, r] : windows(status))
    if (r.contains(x, y, margin)) return false;
  return true;
}

std::pair<double, double> freePoint(const json& status) {
  const double w = status.at("viewport").at(0).get<double>(), h = status.at("viewport").at(1).get<double>();
  std::pair<double, double> best{0.5 * w, 0.5 * h};
  double bestDistance = 1e30;
  for (double y = 0; y < h; y += 16)
    for (double x = 0; x < w; x += 16) {
      if (!isFree(status, x, y, 40)) continue;
      const double d = std::hypot(x - 0.6 * w, y - 0.5 * h);
      if (d < bestDistance) {
        bestDistance = d;
        best = {x, y};
      }
    }
  return best;
}

}  // namespace pba::uitest
