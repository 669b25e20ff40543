// UI checks of one lab window under Xvfb (issue 15), registered for every lab by tests/ui/CMakeLists.txt.
// Usage: pba_ui_check CHECK LAB_EXE WORK_DIR
// Each check drives the window with real X input (xdotool) and reads the effect from the status file
// the window writes every frame (PBA_UI_STATUS, framework/app/window/ui_status.h). Expected values come from
// the check itself: the preset's own values over the defaults the window reported on arrival, the
// pinhole camera model for a drag, the camera's rotate speed and zoom factor for orbit and wheel.
#include <sys/wait.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <thread>

#include "ui_check_support.h"
#include "ui_driver.h"

namespace pba::uitest {
namespace {

namespace fs = std::filesystem;
using Check = void (*)(const std::string& exe, const std::string& work);

/// The lab's exercises that ran as stubs, from the last status the window wrote ("RIGID-1, RIGID-2");
/// empty with the solutions or without a status.
std::string stubbedExercises(const std::string& work) {
  std::ifstream in(fs::path(work) / "status.json");
  const json s = json::parse(in, nullptr, false);
  std::string tags;
  if (s.is_object() && s.contains("stubbed_exercises"))
    for (const json& tag : s["stubbed_exercises"]) tags += (tags.empty() ? "" : ", ") + tag.get<std::string>();
  return tags;
}
bool hasWindow(const json& s, const std::string& part) {
  for (const auto& [name, rect] : windows(s))
    if (name.find(part) != std::string::npos) return true;
  return false;
}

// Space and P pause and resume; while paused the step count does not move.
void checkPause(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  const long s0 = lab.status()["steps"];
  lab.waitFor([s0](const json& s) { return s["steps"].get<long>() > s0; }, "the scene to run");
  pause(lab);
  const long held = lab.frames(3)["steps"];
  expect(lab.frames(10)["steps"] == held, "the step count moved while paused");
  lab.key("p");
  lab.waitFor([held](const json& s) { return s["paused"] == false && s["steps"].get<long>() > held; }, "P to resume");
  lab.key("p");
  lab.waitFor([](const json& s) { return s["paused"] == true; }, "P to pause");
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

// O advances exactly one step (and pauses), each time.
void checkStep(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  const long s0 = pause(lab)["steps"];
  const long held = lab.frames(3)["steps"];
  expect(held == s0, "the step count moved while paused");
  for (int k = 1; k <= 3; ++k) {
    lab.key("o");
    lab.waitFor([&](const json& s) { return s["steps"].get<long>() >= held + k; }, "O to step");
    expect(lab.frames(5)["steps"] == held + k, "O advanced more than one step");
  }
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

// R resets the clock and the step count to zero.
void checkReset(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  lab.waitFor([](const json& s) { return s["sim_time_s"].get<double>() > 0.1; }, "the clock to pass 0.1 s");
  pause(lab);
  lab.key("r");
  const json s = lab.waitFor([](const json& st) { return st["steps"] == 0; }, "R to reset");
  expect(s["sim_time_s"].get<double>() == 0.0, "R left t = " + s["sim_time_s"].dump());
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

// ] and [ walk the scene list in order, wrapping around.
void checkScenes(const std::string& exe, const std::string& work) {
  const std::vector<std::string> list = listScenes(exe);
  expect(!list.empty(), "--list-scenes lists nothing");
  LabWindow lab(exe, {}, work);
  expect(lab.status()["scene"] == list.front(), "the window did not start on the first scene");
  auto expectScene = [&](const std::string& key, const std::string& name) {
    lab.key(key);
    lab.waitFor([&](const json& s) { return s["scene"] == name; }, key + " to switch to " + name);
  };
  if (list.size() > 1) expectScene("bracketright", list[1]);
  expectScene("bracketleft", list.front());
  expectScene("bracketleft", list.back());
  expectScene("bracketright", list.front());
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

// Rewind: , steps one simulation step back and . one forward, Shift+, one second back, the history kept; the
// clock, the step count and the plots go back with the state (each plotted series ends at the metric of the
// state shown, one sample per frame up to it and one for a state between frames); dragging the timeline strip to its left end shows the state at reset; Space
// runs on from there and the later frames are discarded.
void checkRewind(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  lab.waitFor([](const json& s) { return s["history"]["frames"].get<long>() >= 30; }, "30 frames of history");
  pause(lab);
  const json held = lab.frames(2);
  const long frames = held["history"]["frames"], newest = held["history"]["cursor"];
  expect(newest == frames - 1, "paused, the timeline is not at the newest frame");
  // , and . move by one simulation step (a frame holds several), Shift by one second.
  const long s0 = held["steps"];
  for (long k = 1; k <= 3; ++k) {
    lab.key("comma");
    lab.waitFor([&](const json& s) { return s["steps"].get<long>() == s0 - k; },
                ", to step back to step " + std::to_string(s0 - k));
  }
  const json back = lab.frames(2);
  expect(back["sim_time_s"].get<double>() < held["sim_time_s"].get<double>(), "the clock did not go back");
  expect(back["history"]["frames"].get<long>() == frames, "stepping back changed the history's length");
  const long cursor = back["history"]["cursor"];
  for (const auto& [name, plot] : back["plots"].items()) {
    expect(plot["last"] == back["metrics"][name], "plot " + name + " ends at " + plot["last"].dump() +
                                                      ", the state shown has " + back["metrics"][name].dump());
    const long samples = plot["samples"];
    expect(samples == std::min<long>(cursor + 1, 600) || samples == std::min<long>(cursor + 2, 600),
           "plot " + name + " has " + std::to_string(samples) + " samples at frame " + std::to_string(cursor));
  }
  lab.key("period");
  lab.waitFor([&](const json& s) { return s["steps"].get<long>() == s0 - 2; }, ". to step forward one step");
  const double t1 = lab.frames(1)["sim_time_s"];
  lab.key("shift+comma");
  const json second = lab.waitFor([&](const json& s) { return s["steps"].get<long>() < s0 - 3; }, "Shift+, to go back");
  // round(1 s / dt) steps of dt: one second within a step (dt ≤ 20 ms in every scene).
  expect(std::abs(t1 - second["sim_time_s"].get<double>() - 1.0) < 0.02 || second["steps"] == 0,
         "Shift+, went back " + std::to_string(t1 - second["sim_time_s"].get<double>()) + " s, not one second");
  const Rect bar = Rect::fromJson(lab.frames(1)["widgets"]["timeline"]);
  const double y = 0.5 * (bar.y0 + bar.y1);
  lab.drag(1, bar.x1 - 4, y, bar.x0 - 40, y);
  const json start =
      lab.waitFor([](const json& s) { return s["history"]["cursor"] == 0; }, "the timeline dragged to its start");
  expect(start["steps"] == 0 && start["sim_time_s"].get<double>() == 0.0,
         "the first frame of the history is not the reset state: t = " + start["sim_time_s"].dump());
  lab.key("space");
  const json resumed = lab.waitFor([](const json& s) { return s["paused"] == false && s["steps"].get<long>() > 0; },
                                   "Space to run on from the start");
  expect(resumed["history"]["frames"].get<long>() < frames, "running on from the start kept the later frames");
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

// A demo script (--demo): the first step's scene and camera, no notes on screen until N; PageDown / PageUp
// (xdotool Next / Prior) move between this lab's steps; N hides the notes again; PageDown onto another lab's step closes
// the window with exit 0 and leaves that step's number in the --demo-next file for ./pba demo.
void checkDemo(const std::string& exe, const std::string& work) {
  const std::vector<std::string> list = listScenes(exe);
  fs::create_directories(work);
  const std::string lab = fs::path(exe).filename().string().substr(4);  // pba-<lab>
  const std::string other = lab == "hello" ? "ik" : "hello";
  const std::string second = list.size() > 1 ? list[1] : list[0];
  const std::string script = work + "/demo.json", next = work + "/next.txt";
  std::ofstream(script)
      << json{{"title", "UI check"},
              {"steps",
               {{{"lab", lab},
                 {"scene", list[0]},
                 {"title", "first"},
                 {"camera", {{"target", {0.5, 1.0, -0.5}}, {"distance", 7.5}, {"yaw_deg", 20}, {"pitch_deg", 25}}},
                 {"notes", "the first step"}},
                {{"lab", lab}, {"scene", second}, {"notes", "the second step"}},
                {{"lab", other}, {"scene", "any"}, {"notes", "another lab"}}}}}
             .dump(2);
  fs::remove(next);
  LabWindow w(exe, {"--demo", script, "--demo-next", next}, work);
  const json first = w.waitFor([&](const json& s) { return s["scene"] == list[0]; }, "step 1");
  // The speaker notes go to the terminal; on the projector only behind N.
  expect(!hasWindow(w.frames(2), "Step 1 of 3"), "the speaker notes are on screen before N");
  w.key("n");
  w.waitFor([&](const json& s) { return hasWindow(s, "Step 1 of 3"); }, "N to show the notes");
  expect(first["lecture"] == true, "a demo does not start in lecture mode");
  expect(near(first["camera"]["distance"].get<double>(), 7.5, 1e-4) &&
             near(vecAt(first["camera"]["target"], 1), 1.0, 1e-4),
         "step 1's camera was not applied: " + first["camera"].dump());
  w.key("Next");
  w.waitFor([&](const json& s) { return s["scene"] == second && hasWindow(s, "Step 2 of 3"); }, "PageDown to step 2");
  w.key("Prior");
  w.waitFor([&](const json& s) { return s["scene"] == list[0] && hasWindow(s, "Step 1 of 3"); }, "PageUp to step 1");
  w.key("n");
  w.waitFor([&](const json& s) { return !hasWindow(s, "Step 1 of 3"); }, "N to hide the notes");
  w.key("Next");
  w.waitFor([&](const json& s) { return hasWindow(s, "Step 2 of 3") || s["scene"] == second; }, "PageDown to step 2");
  w.key("Next");
  for (int i = 0; i < 600 && w.running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  expect(!w.running(), "PageDown onto another lab's step did not close the window");
  expect(w.close() == 0, "the lab did not exit cleanly when handing over");
  std::ifstream in(next);
  std::string step;
  in >> step;
  expect(step == "3", "the hand-off file says '" + step + "', expected 3");
}

/// Parameter values agree: numbers to 1e-9 relative (angles pass through radians), others exactly.
bool sameValue(const json& a, const json& b) {
  if (a.is_number() && b.is_number())
    return near(a.get<double>(), b.get<double>(), 1e-9 * std::max(1.0, std::abs(b.get<double>())));
  return a == b;
}

// 1-9 apply the scene's presets, and every parameter then equals the preset's value or, where the
// preset names none, the scene's default: the same setup whatever was pressed before. Every scene
// with presets is checked, its presets pressed from the last to the first.
void checkPresets(const std::string& exe, const std::string& work) {
  const std::vector<std::string> list = listScenes(exe);
  LabWindow lab(exe, {}, work);
  pause(lab);
  int checked = 0;
  for (size_t index = 0; index < list.size(); ++index) {
    if (index > 0) {
      lab.key("bracketright");
      lab.waitFor([&](const json& s) { return s["scene"] == list[index]; }, "] to reach " + list[index]);
    }
    const json arrival = lab.frames(1);
    const json defaults = arrival["params"];  // a scene fresh from the registry: its declared defaults
    const json& presets = arrival["presets"];
    for (int k = std::min<int>(static_cast<int>(presets.size()), 9); k >= 1; --k) {
      const json& preset = presets[static_cast<size_t>(k - 1)];
      lab.key(std::to_string(k));
      const std::string message = "Preset " + std::to_string(k) + ": " + preset["name"].get<std::string>();
      const json s = lab.waitFor([&](const json& st) { return st["message"] == message; },
                                 "key " + std::to_string(k) + " on " + list[index]);
      for (const auto& [name, value] : defaults.items()) {
        const json& want = preset["params"].contains(name) ? preset["params"][name] : value;
        expect(sameValue(s["params"][name], want), list[index] + " preset " + std::to_string(k) + ": parameter " +
                                                       name + " is " + s["params"][name].dump() + ", expected " +
                                                       want.dump());
      }
      ++checked;
    }
  }
  std::cout << "checked " << checked << " presets over " << list.size() << " scenes\n";
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

// F1 and H open and close the help overlay.
void checkHelp(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  const std::string title = "Keys and mouse";
  for (const char* key : {"F1", "h", "h", "F1"}) {
    const bool want = !lab.status()["help_shown"].get<bool>();
    lab.key(key);
    const json s = lab.waitFor([&](const json& st) { return st["help_shown"] == want && hasWindow(st, title) == want; },
                               std::string(key) + (want ? " to show" : " to hide") + " the help");
    (void)s;
  }
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

// F12 writes a PNG into the working folder and names it on screen for about two seconds.
void checkScreenshot(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  lab.key("F12");
  const json s =
      lab.waitFor([](const json& st) { return !st["last_screenshot"].get<std::string>().empty(); }, "F12 to save");
  const std::string file = s["last_screenshot"];
  const json shown = lab.waitFor(
      [&](const json& st) {
        return st["notice"].get<std::string>().find(file) != std::string::npos && hasWindow(st, "##notice");
      },
      "the notice naming " + file);
  std::ifstream png(fs::path(work) / file, std::ios::binary);
  char magic[8] = {};
  png.read(magic, 8);
  expect(png && std::string(magic + 1, 3) == "PNG", file + " is not a PNG in " + work);
  const double shownAt = shown["frame"].get<double>();
  const json gone =
      lab.waitFor([](const json& st) { return st["notice"].get<std::string>().empty(); }, "the notice to go", 10.0);
  expect(gone["frame"].get<double>() > shownAt, "the notice vanished at once");
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

/// Width and height of a PNG file from its IHDR chunk (bytes 16–23, big-endian); (0, 0) if it is none.
std::pair<long, long> pngSize(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char b[24] = {};
  if (!in.read(reinterpret_cast<char*>(b), 24) || std::string(reinterpret_cast<char*>(b) + 12, 4) != "IHDR")
    return {0, 0};
  auto be = [&](int at) { return (long{b[at]} << 24) | (long{b[at + 1]} << 16) | (long{b[at + 2]} << 8) | b[at + 3]; };
  return {be(16), be(20)};
}

// --screenshot at --size WxH writes an image of exactly that size (the display's: 1280×720 or
// 1920×1080), in lecture mode too; a bad size is one line on stderr and exit code 2, with no image.
void checkScreenshotSize(const std::string& exe, const std::string& work) {
  const auto [w, h] = displaySize();
  const std::string size = std::to_string(w) + "x" + std::to_string(h);
  const fs::path png = fs::path(work) / ("cli-" + size + ".png"), err = fs::path(work) / "stderr.txt";
  const std::string base = "'" + exe + "' --frames 2 --screenshot '" + png.string() + "'";
  const int rc = std::system((base + " --lecture --size " + size + " 2>'" + err.string() + "'").c_str());
  expect(rc == 0, "--screenshot --size " + size + " failed (status " + std::to_string(rc) + ")");
  const auto [pw, ph] = pngSize(png);
  expect(pw == w && ph == h, png.string() + " is " + std::to_string(pw) + "x" + std::to_string(ph) + ", not " + size);
  fs::remove(png);
  const int bad = std::system((base + " --size 1920by1080 2>'" + err.string() + "'").c_str());
  expect(WIFEXITED(bad) && WEXITSTATUS(bad) == 2, "--size 1920by1080 did not exit with status 2");
  std::ifstream in(err);
  const std::string message((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  expect(message.find("--size") != std::string::npos && message.find('\n') == message.size() - 1,
         "--size 1920by1080: expected one line naming --size, got '" + message + "'");
  expect(!fs::exists(png), "a bad --size still wrote " + png.string());
  std::cout << "screenshot " << pw << "x" << ph << "; bad size: " << message;
}

// F9 starts a recording (MP4 with ffmpeg, else PNG files) and F9 stops it: every recorded frame is
// exactly one display frame (1/60 s) of simulated time, so the clock advanced by frames / 60 while it
// ran, whatever the wall clock did; the file is named on screen and exists.
void checkRecord(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  lab.frames(2);
  lab.key("F9");
  const json started =
      lab.waitFor([](const json& st) { return !st["recording"].get<std::string>().empty(); }, "F9 to start recording");
  const json later = lab.waitFor(
      [&](const json& st) { return st["frame"].get<long>() >= started["frame"].get<long>() + 20; }, "20 frames");
  lab.key("F9");
  const json stopped = lab.waitFor(
      [](const json& st) { return st["message"].get<std::string>().rfind("Recorded ", 0) == 0; }, "F9 to stop");
  expect(stopped["recording"].get<std::string>().empty(), "the recording indicator stayed on");
  const std::string message = stopped["message"];
  long frames = 0;
  char path[512] = {};
  expect(std::sscanf(message.c_str(), "Recorded %ld frames (%*f s at %*d frames/s) to %511s", &frames, path) == 2,
         "the message does not name the frames and the file: " + message);
  expect(frames >= 20, "only " + std::to_string(frames) + " frames recorded in 20 displayed frames");
  const fs::path file = fs::path(work) / path;
  expect(fs::exists(file) && (fs::is_directory(file) ? !fs::is_empty(file) : fs::file_size(file) > 0),
         file.string() + " was not written");
  // Every recorded frame advanced the clock by exactly one display frame (1/60 s), whatever the wall
  // clock did: the simulated time between the status that showed the recording start and the one that
  // showed it stopped is frames / 60.
  const double recorded = stopped["sim_time_s"].get<double>() - started["sim_time_s"].get<double>();
  expect(std::abs(recorded - static_cast<double>(frames) / 60.0) < 1e-9,
         "the clock advanced " + std::to_string(recorded) + " s while " + std::to_string(frames) +
             " frames were recorded (expected frames / 60 s)");
  expect(later["sim_time_s"].get<double>() > started["sim_time_s"].get<double>(),
         "the scene did not run while recording");
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

json setLecture(LabWindow& lab, const std::string& how, bool want) {
  if (how == "key")
    lab.key("l");
  else
    lab.clickWidget("lecture_checkbox", "View");
  json s = lab.waitFor([want](const json& st) { return st["lecture"] == want; },
                       how + (want ? " lecture on" : " lecture off"));
  return lab.frames(2);  // a few whole frames in the new mode: it renders, nothing aborts
}

bool savedLecture(const std::string& work, const std::string& lab) {
  std::ifstream in(fs::path(work) / "config" / "pba-labs" / lab / "settings.json");
  expect(static_cast<bool>(in), "no settings were saved");
  return json::parse(in).at("lecture").get<bool>();
}

// L toggles lecture mode on and off five times, the View checkbox twice, and lecture mode started from
// --lecture turns off: no abort, and the mode is in the settings the lab saves when it closes.
void checkLecture(const std::string& exe, const std::string& work) {
  const std::string labName = fs::path(exe).filename().string().substr(4);  // pba-<lab>
  {
    LabWindow lab(exe, {}, work);
    for (int i = 0; i < 5; ++i) {
      setLecture(lab, "key", true);
      setLecture(lab, "key", false);
    }
    setLecture(lab, "checkbox", true);
    setLecture(lab, "checkbox", false);
    setLecture(lab, "key", true);
    expect(lab.close() == 0, "the lab did not exit cleanly");
    expect(savedLecture(work, labName), "lecture mode on was not saved");
  }
  LabWindow lab(exe, {"--lecture"}, work);
  expect(lab.status()["lecture"] == true, "--lecture did not start in lecture mode");
  setLecture(lab, "key", false);
  expect(lab.close() == 0, "the lab did not exit cleanly");
  expect(!savedLecture(work, labName), "lecture mode off was not saved");
}

// Tab hides the panels and plots but keeps the legend; Tab again shows them.
void checkTab(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  expect(hasWindow(lab.status(), "###panel"), "no control panel at start");
  lab.key("Tab");
  const json hidden = lab.waitFor([](const json& s) { return s["ui_hidden"] == true; }, "Tab to hide");
  const json s = lab.frames(1);
  expect(!hasWindow(s, "###panel") && !hasWindow(s, "Plots"), "panels stayed with Tab");
  if (s["legend_entries"].get<int>() > 0) expect(hasWindow(s, "##legend"), "Tab hid the legend");
  lab.key("Tab");
  lab.waitFor([](const json& st) { return st["ui_hidden"] == false && hasWindow(st, "###panel"); }, "Tab to show");
  (void)hidden;
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

double eyeHeight(const json& s) { return vecAt(s["camera"]["eye"], 1); }

// Orbiting down past the horizon stops above the ground; zoomed out far, F frames the scene again with
// the elevation the window started with (the scene's preferred view, else the default pitch).
void checkFrame(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {}, work);
  const auto [x, y] = freePoint(lab.status());
  const double initialPitch = lab.status()["camera"]["pitch"];  // the framing the window starts with
  double lowest = 1e30;
  lab.move(x, y);
  lab.frames(2);
  lab.press(3);
  lab.frames(2);
  for (int i = 1; i <= 6; ++i) {  // 600 px up: 3.6 rad of pitch downward without the ground rule
    lab.move(x, y - 100.0 * i);
    lowest = std::min(lowest, eyeHeight(lab.frames(2)));
  }
  lab.release(3);
  lab.move(x, y);
  lowest = std::min(lowest, eyeHeight(lab.frames(2)));
  expect(lowest > 0.0, "the eye went below the ground (y = " + std::to_string(lowest) + " m)");
  lab.wheel(-25);  // far away
  lab.frames(2);
  lab.key("f");
  const long at = lab.status()["frame"];
  const json s = lab.waitFor([at](const json& st) { return st["frame"].get<long>() > at + 2; }, "F to frame");
  const double pitch = s["camera"]["pitch"];
  expect(near(pitch, initialPitch, 1e-4),
         "F left the pitch at " + std::to_string(pitch) + " rad, not the framing's " + std::to_string(initialPitch));
  expect(eyeHeight(s) > 0.0, "after F the eye is below the ground");
  expect(!s["scene_rect"].is_null(), "after F nothing of the scene is in front of the camera");
  const Rect scene = Rect::fromJson(s["scene_rect"]);
  const Rect view{0, 0, vecAt(s["viewport"], 0), vecAt(s["viewport"], 1)};
  expect(scene.intersect(view).area() > 0.5 * scene.area(), "after F the scene is mostly off screen: its picture " +
                                                                s["scene_rect"].dump() + " in " + s["viewport"].dump());
  expect(scene.area() > 0.02 * view.area(), "after F the scene is a speck");
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

// A bad scene file loaded from the panel shows its error and the running scene keeps running; the
// path field spans the panel.
void checkBadSceneFile(const std::string& exe, const std::string& work) {
  const std::string bad = (fs::absolute(work) / "bad.json").string();
  LabWindow lab(exe, {}, work);
  std::ofstream(bad) << "{ \"lab\": \"x\",, }\n";  // a syntax error on line 1
  const std::string scene = lab.status()["scene"];
  lab.clickWidget("file_field", "Scene file");
  {  // the path field spans the panel, so a long path can be read
    const json st = lab.frames(1);
    double panelWidth = 0.0;
    for (const auto& [name, r] : windows(st))
      if (name.find("###panel") != std::string::npos) panelWidth = r.width();
    const Rect field = Rect::fromJson(st["widgets"]["file_field"]);
    expect(field.width() >= 0.8 * panelWidth, "the scene file field is " + std::to_string(field.width()) + " px of a " +
                                                  std::to_string(panelWidth) + " px panel");
  }
  lab.key("ctrl+a");
  lab.type(bad);
  lab.frames(2);
  lab.clickWidget("load_button", "Scene file");
  const json s = lab.waitFor(
      [](const json& st) { return st["file_error"].get<std::string>().find("bad.json") != std::string::npos; },
      "the file's error");
  expect(s["scene"] == scene, "the bad file replaced the scene");
  const long steps = s["steps"];
  lab.waitFor([steps](const json& st) { return st["steps"].get<long>() > steps && st["paused"] == false; },
              "the scene to keep running");
  std::cout << "error shown: " << s["file_error"].get<std::string>() << '\n';
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

double panelWidthOf(const json& s) {
  for (const auto& [name, r] : windows(s))
    if (name.find("###panel") != std::string::npos) return r.width();
  return 0.0;
}

// Lecture mode: C collapses the control panel to a strip and the framing gives the scene the width; M hides
// and shows the plots; the strip's button and C bring the panel back.
void checkPanelStrip(const std::string& exe, const std::string& work) {
  LabWindow lab(exe, {"--lecture"}, work);
  pause(lab);
  const json before = lab.frames(3);
  const double wide = panelWidthOf(before), font = before["font_px"];
  const double view = vecAt(before["viewport"], 0);
  lab.key("c");
  lab.waitFor([](const json& s) { return s["panel_collapsed"] == true; }, "C to collapse the panel");
  const json framed = lab.frames(3);
  const double narrow = panelWidthOf(framed);
  std::printf("panel %.0f px, strip %.0f px of %.0f px\n", wide, narrow, view);
  expect(narrow > 0 && narrow <= 3.0 * font + 16.0, "the collapsed panel is " + std::to_string(narrow) + " px wide");
  expect(narrow < 0.05 * view, "the strip takes more than 5 % of the width");
  const Rect pictureBefore = Rect::fromJson(before["scene_rect"]), pictureAfter = Rect::fromJson(framed["scene_rect"]);
  expect(pictureAfter.x0 < pictureBefore.x0, "the scene did not move into the room the panel gave up");
  const bool hadPlots = hasWindow(before, "Plots");
  lab.key("m");
  lab.waitFor([](const json& s) { return s["plots_shown"] == false && !hasWindow(s, "Plots"); }, "M to hide the plots");
  lab.key("m");
  lab.waitFor([&](const json& s) { return s["plots_shown"] == true && hasWindow(s, "Plots") == hadPlots; },
              "M to show the plots");
  lab.clickWidget("expand_button", "");
  lab.waitFor([&](const json& s) { return s["panel_collapsed"] == false && panelWidthOf(s) > 2 * narrow; },
              "the strip's button to bring the panel back");
  lab.key("c");
  lab.waitFor([](const json& s) { return s["panel_collapsed"] == true; }, "C to collapse the panel again");
  lab.key("c");
  lab.waitFor([](const json& s) { return s["panel_collapsed"] == false; }, "C to bring the panel back");
  expect(lab.close() == 0, "the lab did not exit cleanly");
}

const std::map<std::string, Check> kChecks = {{"pause", checkPause},
                                              {"step", checkStep},
                                              {"reset", checkReset},
                                              {"rewind", checkRewind},
                                              {"demo", checkDemo},
                                              {"scenes", checkScenes},
                                              {"presets", checkPresets},
                                              {"help", checkHelp},
                                              {"screenshot", checkScreenshot},
                                              {"screenshot-size", checkScreenshotSize},
                                              {"record", checkRecord},
                                              {"lecture", checkLecture},
                                              {"tab", checkTab},
                                              {"frame", checkFrame},
                                              {"drag", checkDrag},
                                              {"drag-every-scene", checkDragEveryScene},
                                              {"throw-again", checkThrowAgain},
                                              {"orbit-zoom", checkOrbitAndZoom},
                                              {"bad-scene-file", checkBadSceneFile},
                                              {"lecture-layout", checkLectureLayout},
                                              {"panel-strip", checkPanelStrip}};

}  // namespace
}  // namespace pba::uitest

int main(int argc, char** argv) {
  using namespace pba::uitest;
  if (argc == 2 && std::string(argv[1]) == "--list") {
    for (const auto& [name, check] : kChecks) std::cout << name << '\n';
    return 0;
  }
  if (argc != 4 || !kChecks.count(argv[1])) {
    std::cerr << "usage: pba_ui_check CHECK LAB_EXE WORK_DIR (pba_ui_check --list names the checks)\n";
    return 2;
  }
  const std::string work = argv[3];
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  try {
    kChecks.at(argv[1])(argv[2], work);
  } catch (const NothingToCheck& e) {
    std::cout << "SKIPPED [" << argv[1] << "]: " << e.what() << '\n';
    return kSkipped;
  } catch (const std::exception& e) {
    // In a hand-out a check whose scene ran stubbed exercises may fail for that (the stubbed cloth falls
    // through the floor): it is skipped, naming them (docs/architecture.md §5), never failed.
    if (const std::string tags = stubbedExercises(work); !tags.empty()) {
      std::cout << "SKIPPED [" << argv[1] << "]: needs " << tags << " (with them stubbed: " << e.what() << ")\n";
      return kSkipped;
    }
    std::cout << "FAIL [" << argv[1] << "]: " << e.what() << '\n';
    return 1;
  }
  std::cout << "ok: " << argv[1] << '\n';
  return 0;
}
