#pragma once
// What the UI checks share (tests/ui/ui_check.cpp and the files of its checks): the skip signal, tolerances,
// reading the status, and pausing the window.
#include <cmath>
#include <stdexcept>
#include <string>

#include "ui_driver.h"

namespace pba::uitest {

/// The lab offers nothing this check can look at: ctest shows the check as skipped (exit code 77,
/// SKIP_RETURN_CODE), never as passed.
struct NothingToCheck : std::runtime_error {
  using std::runtime_error::runtime_error;
};
constexpr int kSkipped = 77;

inline bool near(double a, double b, double tolerance) { return std::abs(a - b) <= tolerance; }
inline double vecAt(const json& v, int i) { return v.at(i).get<double>(); }

inline json pause(LabWindow& lab) {
  lab.key("space");
  return lab.waitFor([](const json& s) { return s["paused"] == true; }, "Space to pause");
}

/// The pointer checks (ui_check_pointer.cpp): pick and drag, throw again, orbit and zoom.
void checkDrag(const std::string& exe, const std::string& work);
void checkDragEveryScene(const std::string& exe, const std::string& work);
void checkThrowAgain(const std::string& exe, const std::string& work);
void checkOrbitAndZoom(const std::string& exe, const std::string& work);
/// Lecture mode's layout, measured from the rendered image (ui_check_lecture.cpp).
void checkLectureLayout(const std::string& exe, const std::string& work);

}  // namespace pba::uitest
