// The pointer checks of pba_ui_check: a pick and drag follows the pinhole camera model, every rigid scene's
// bodies can be dragged, the tumble box can be thrown again, and right-drag and the wheel move the camera
// by its rotate speed and zoom factor.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ui_check_support.h"

namespace pba::uitest {
namespace {

/// The draggable objects of a status that are on screen, away from the panels by `margin` pixels.
std::vector<json> freeHandles(const json& s, double margin) {
  std::vector<json> out;
  for (const json& h : s["handles"])
    if (h["visible"] == true && isFree(s, vecAt(h["pixel"], 0), vecAt(h["pixel"], 1), margin)) out.push_back(h);
  return out;
}

/// Walks every scene with ] and returns to the one with the most draggable objects on screen (the
/// IK tree's goals, the rope's particles, the hello ball): a scene built around dragging. Returns the
/// first of those objects, away from the panels.
json sceneWithHandle(LabWindow& lab, const std::vector<std::string>& list, double margin) {
  std::string best;
  size_t most = 0;
  bool anyReported = false;
  for (size_t i = 0; i < list.size(); ++i) {
    const json s = lab.frames(3);
    anyReported = anyReported || !s["handles"].empty();
    const size_t n = freeHandles(s, margin).size();
    if (n > most) {
      most = n;
      best = s["scene"];
    }
    const std::string current = s["scene"];
    lab.key("bracketright");
    lab.waitFor([&](const json& st) { return st["scene"] != current; }, "] to switch scenes");
  }
  if (most == 0 && !anyReported)
    throw NothingToCheck("no scene of this lab reports its draggable objects (Scene::dragHandles)");
  expect(most > 0, "no scene of this lab shows a draggable object away from the panels");
  for (size_t i = 0; i < list.size() && lab.status()["scene"] != best; ++i) {
    const std::string current = lab.status()["scene"];
    lab.key("bracketright");
    lab.waitFor([&](const json& st) { return st["scene"] != current; }, "] to switch scenes");
  }
  const json s = lab.frames(3);
  const std::vector<json> handles = freeHandles(s, margin);
  expect(!handles.empty(), best + ": its draggable objects left the screen");
  // The one farthest on screen from every other object, so that a click there can only mean it (a far
  // rope's beads lie a few pixels apart, and the pick takes the nearest bead along the ray).
  auto separation = [&](const json& h) {
    double nearest = 1e30;
    for (const json& o : s["handles"])
      if (o["handle"] != h["handle"] && o["visible"] == true)
        nearest = std::min(nearest, std::hypot(vecAt(o["pixel"], 0) - vecAt(h["pixel"], 0),
                                               vecAt(o["pixel"], 1) - vecAt(h["pixel"], 1)));
    return nearest;
  };
  return *std::max_element(handles.begin(), handles.end(),
                           [&](const json& a, const json& b) { return separation(a) < separation(b); });
}

// A left drag moves the picked object `h` by the dragged distance: dx right and dy down on screen move it
// by (dx right − dy up) × (metres per pixel at its depth) = 2 d tan(fov/2) / height, in the plane
// facing the camera (the pinhole model, an independent route from the window's picking code).
void expectDragFollows(LabWindow& lab, const json& h) {
  const json s0 = lab.status();
  const double px = vecAt(h["pixel"], 0), py = vecAt(h["pixel"], 1);
  // 60 px across and 45 px up or down, toward the middle of the window (away from its edges).
  const double dx = px < 0.5 * vecAt(s0["viewport"], 0) ? 60 : -60, dy = py < 0.5 * vecAt(s0["viewport"], 1) ? 45 : -45;
  lab.move(px, py);
  lab.frames(2);
  lab.press(1);
  const int handle = h["handle"];
  // A fresh pick (the status keeps the last one dragged): the button holds this object now.
  lab.waitFor(
      [handle](const json& s) {
        return s.value("dragging", true) && !s["picked"].is_null() && s["picked"]["handle"] == handle;
      },
      "the pick");
  for (int i = 1; i <= 4; ++i) {
    lab.move(px + dx * i / 4, py + dy * i / 4);
    lab.frames(2);
  }
  const json s = lab.frames(2);
  lab.release(1);
  lab.frames(2);
  const json& cam = s0["camera"];
  // The cursor moves on the plane facing the camera through the picked surface point; the object keeps
  // its offset from it, so it moves by the displacement at that plane's depth (its own centre's depth
  // when the window does not report the plane).
  const json& plane = s["picked"].contains("drag_plane_point") ? s["picked"]["drag_plane_point"] : h["position"];
  double p0[3], p1[3], moved[3], want[3], depth = 0.0;
  for (int k = 0; k < 3; ++k) {
    p0[k] = vecAt(h["position"], k);
    p1[k] = vecAt(s["picked"]["position"], k);
    moved[k] = p1[k] - p0[k];
    depth += (vecAt(plane, k) - vecAt(cam["eye"], k)) * vecAt(cam["forward"], k);
  }
  const double metresPerPixel = 2.0 * depth * std::tan(0.5 * cam["fov_y"].get<double>()) / vecAt(s0["viewport"], 1);
  double error = 0.0, length = 0.0, along = 0.0;
  for (int k = 0; k < 3; ++k) {
    want[k] = (dx * vecAt(cam["right"], k) - dy * vecAt(cam["up"], k)) * metresPerPixel;
    error += (moved[k] - want[k]) * (moved[k] - want[k]);
    length += want[k] * want[k];
    along += moved[k] * vecAt(cam["forward"], k);
  }
  // 12 %: the slack of the cursor's whole pixels and of a running spring's lag (paused: none).
  std::printf("scene %s handle %d moved %.4f m, expected %.4f m, error %.4f m\n", s["scene"].get<std::string>().c_str(),
              handle, std::sqrt(moved[0] * moved[0] + moved[1] * moved[1] + moved[2] * moved[2]), std::sqrt(length),
              std::sqrt(error));
  expect(std::sqrt(error) <= 0.12 * std::sqrt(length), "the dragged object did not follow the cursor");
  expect(std::abs(along) <= 0.05 * std::sqrt(length), "the drag moved the object toward or away from the camera");
}

}  // namespace

// The scene built most around dragging (sceneWithHandle): its object follows a left drag.
void checkDrag(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  pause(lab);  // a paused scene: only the drag moves anything
  expectDragFollows(lab, sceneWithHandle(lab, listScenes(exe), 30));
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

// Every scene of the lab with a dynamic body at its start has one on screen, and it follows a left drag
// (the rigid lab: workbook §5 says "left-drag any body", the tumble box included).
void checkDragEveryScene(const std::string& exe, const std::string& work) {
  const std::vector<std::string> list = listScenes(exe);
  LabWindow lab(exe, {}, work);
  pause(lab);
  for (size_t index = 0; index < list.size(); ++index) {
    if (index > 0) {
      lab.key("bracketright");
      lab.waitFor([&](const json& s) { return s["scene"] == list[index]; }, "] to reach " + list[index]);
    }
    const json s = lab.frames(3);
    if (s["handles"].empty()) {  // e.g. bullet: static walls until its first shot is fired
      std::printf("scene %s: no dynamic body at its start, nothing to drag\n", list[index].c_str());
      continue;
    }
    const bool anyInView =
        std::any_of(s["handles"].begin(), s["handles"].end(), [](const json& h) { return h["visible"] == true; });
    if (!anyInView) {  // bench-boxes: the bodies it reports, its highest, start above the picture
      std::printf("scene %s: the bodies it reports are out of view at its start, not dragged\n", list[index].c_str());
      continue;
    }
    const std::vector<json> handles = freeHandles(s, 30);
    expect(!handles.empty(), list[index] + ": no draggable body on screen away from the panels");
    expectDragFollows(lab, handles.front());
  }
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

namespace {

double heightOf(const json& s) { return vecAt(s["handles"].at(0)["position"], 1); }
}  // namespace

// The default scene (rigid: tumble) can be thrown again: once the box has landed (its centre below the
// drop height's half), T lifts it back to the drop height and it falls and lands again, with no reset
// (the step count keeps growing) and no guard pause.
void checkThrowAgain(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  const json start = lab.frames(2);
  if (start["handles"].empty()) throw NothingToCheck("the default scene reports no draggable body");
  const double drop = start["params"]["height"];
  lab.waitFor([&](const json& s) { return heightOf(s) < 0.5 * drop; }, "the box to land");
  const long steps = lab.status()["steps"];
  lab.key("t");
  const json thrown = lab.waitFor([&](const json& s) { return heightOf(s) > 0.9 * drop; }, "T to throw the box again");
  expect(thrown["steps"].get<long>() >= steps, "T reset the scene's clock instead of throwing again");
  lab.waitFor([&](const json& s) { return heightOf(s) < 0.5 * drop; }, "the box to land again");
  expect(lab.status()["guard"].get<std::string>().empty(), "the guard paused the second throw");
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

// Right drag orbits by the camera's rotate speed per pixel; the wheel zooms by its zoom factor per step.
void checkOrbitAndZoom(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  const json s0 = lab.frames(2);
  const auto [x, y] = freePoint(s0);
  const double yaw0 = s0["camera"]["yaw"], pitch0 = s0["camera"]["pitch"];
  lab.drag(3, x, y, x + 100, y);
  const json s1 = lab.frames(1);
  const double turned = std::remainder(s1["camera"]["yaw"].get<double>() - yaw0, 2.0 * M_PI);
  const double speed = s1["camera"]["rotate_speed"];
  expect(near(turned, -100 * speed, 0.05 * 100 * speed),
         "a 100 px right drag turned the yaw by " + std::to_string(turned) + " rad");
  expect(near(s1["camera"]["pitch"], pitch0, 1e-6), "a horizontal right drag changed the pitch");
  const double d0 = s1["camera"]["distance"];
  lab.move(x, y);
  lab.frames(2);
  lab.wheel(3);
  const double factor = std::pow(s1["camera"]["zoom_factor"].get<double>(), 3);
  const json s2 = lab.waitFor(
      [&](const json& s) { return s["camera"]["distance"].get<double>() < d0 * (1.0 + factor) / 2.0; }, "the wheel");
  const json s3 = lab.frames(2);
  expect(near(s3["camera"]["distance"].get<double>() / d0, factor, 1e-4),
         "three wheel steps zoomed by " + std::to_string(s3["camera"]["distance"].get<double>() / d0));
  (void)s2;
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

}  // namespace pba::uitest
