#pragma once
// Drives one lab window for the UI checks (tests/ui): starts the lab with PBA_UI_STATUS set, sends
// real X input with xdotool (keys, mouse moves, buttons, wheel), and waits on conditions of the status
// file the window rewrites every frame. Never sleeps to synchronise: every wait polls the status for
// a condition (a frame counter, a mode, a value) under a deadline and fails with what it waited for.
#include <sys/types.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace pba::uitest {

using nlohmann::json;

/// A failed check: the message says what was expected and what the status showed.
struct CheckFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A rectangle [pixels, y down].
struct Rect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  double area() const { return width() > 0 && height() > 0 ? width() * height() : 0.0; }
  bool contains(double x, double y, double margin = 0) const {
    return x >= x0 - margin && x <= x1 + margin && y >= y0 - margin && y <= y1 + margin;
  }
  Rect intersect(const Rect& o) const;
  static Rect fromJson(const json& j);  ///< [x0, y0, x1, y1]
};

class LabWindow {
 public:
  /// Starts `exe args...` in `workDir` (its screenshots land there) with its settings in
  /// workDir/config and its status in workDir/status.json; waits for the first frames and the window.
  LabWindow(std::string exe, std::vector<std::string> args, std::string workDir);
  ~LabWindow();  ///< kills the lab if it is still running
  LabWindow(const LabWindow&) = delete;
  LabWindow& operator=(const LabWindow&) = delete;

  /// The latest status (waits for a readable one).
  json status();
  /// Waits until `ready(status)` holds; fails after `seconds` or when the lab exits.
  json waitFor(const std::function<bool(const json&)>& ready, const std::string& what, double seconds = kWaitSeconds);
  /// Waits until `n` more frames have been displayed (the effect of input sent before is then in).
  json frames(int n = 2);

  void key(const std::string& name);  ///< xdotool key names: space, bracketright, F1, ctrl+a, …
  void type(const std::string& text);
  void move(double x, double y);  ///< cursor to window pixel (x, y)
  void press(int button);         ///< 1 left, 2 middle, 3 right
  void release(int button);
  void wheel(int steps);           ///< > 0 up (zoom in), < 0 down
  void click(double x, double y);  ///< left click at window pixel (x, y), a frame between each event
  /// Moves to `from`, presses `button`, moves to `to` in `steps` equal moves (a frame apart), releases.
  void drag(int button, double fromX, double fromY, double toX, double toY, int steps = 4);
  /// Clicks the named widget of the status ("load_button", ...), scrolling the panel until it shows.
  void clickWidget(const std::string& name, const std::string& headerToOpen);

  /// Asks the lab to close (SIGTERM: it saves its settings) and returns its exit code (fails on a crash).
  int close();
  bool running();
  const std::string& workDir() const { return work_; }

  static constexpr double kWaitSeconds = 60.0;  // [s] generous: llvmpipe on two shared cores, 1080p

 private:
  void xdotool(const std::string& arguments);
  std::string exe_, work_, statusPath_, window_;
  pid_t pid_ = -1;
  int exitCode_ = -1;
  json last_;
};

/// The lab's scene names in order (`exe --list-scenes`).
std::vector<std::string> listScenes(const std::string& exe);
/// The panels and other ImGui windows of a status, by name.
std::vector<std::pair<std::string, Rect>> windows(const json& status);
/// A point of the window no panel covers, as near the centre of the free area as the grid finds.
std::pair<double, double> freePoint(const json& status);
/// True when (x, y) is inside the window and at least `margin` pixels from every panel and edge.
bool isFree(const json& status, double x, double y, double margin);
void expect(bool condition, const std::string& message);
/// The X display's size [px] (xdotool getdisplaygeometry; 1280×720 when it cannot tell).
std::pair<int, int> displaySize();

}  // namespace pba::uitest
