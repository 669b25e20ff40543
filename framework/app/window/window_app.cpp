// Window mode of the lab runner: GLFW window, renderer, ImGui panels, keys and mouse, fonts and
// lecture mode, persisted settings, screenshots. With --screenshot it renders a fixed number of
// frames at exactly 1/60 s of simulated time each (deterministic), saves the PNG and exits.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/lab.h"
#include "app/runner/compare_run.h"
#include "app/runner/metrics_report.h"
#include "app/runner/pose_json.h"
#include "app/runner/resource_dir.h"
#include "app/runner/scene_file.h"
#include "app/runner/scene_registry.h"
#include "app/window/lab_session.h"
#include "app/window/lab_ui.h"
#include "app/window/scene_draw.h"
#include "app/window/scene_image.h"
#include "app/window/ui_status.h"
#include "app/window/ui_style.h"
#include "app/window/window_demo.h"
#include "app/window/window_input.h"
#include "app/window/window_recording.h"
#include "graphics/debug_renderer.h"
#include "graphics/gl.h"
#include "graphics/renderer.h"
#include "graphics/screenshot.h"
#include "graphics/window.h"

namespace pba::app {
namespace {

constexpr int kMaxStepsPerFrame = 2000;   // bounds one frame's physics so the window stays responsive
constexpr double kMaxFrameSeconds = 0.1;  // a stalled frame (dragging the window) never jumps far
constexpr float kMinFramedPitch = 0.12f;  // [rad] F keeps a pitch in this range, else restores the default
constexpr float kMaxFramedPitch = 1.35f;  // [rad]

// PBA_MSAA_SAMPLES=N (0 to 16) sets the window's multisampling, else `fallback` (4). The window-driving
// tests run at 0: software rendering under Xvfb pays for every sample, and they check behaviour, not edges.
int multisamplesFromEnvironment(int fallback) {
  const char* text = std::getenv("PBA_MSAA_SAMPLES");
  if (!text || !*text) return fallback;
  char* end = nullptr;
  const long n = std::strtol(text, &end, 10);
  return *end == '\0' && n >= 0 && n <= 16 ? static_cast<int>(n) : fallback;
}

// Ctrl+C in the terminal (SIGINT) or SIGTERM closes the window normally, so settings are saved.
std::atomic<bool> gStopRequested{false};
extern "C" void requestStop(int) { gStopRequested = true; }

struct ImGuiContextGuard {
  ImGuiContextGuard(GLFWwindow* window, bool useIni) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    if (!useIni) ImGui::GetIO().IniFilename = nullptr;
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init(graphics::kImGuiGlslVersion);
  }
  ~ImGuiContextGuard() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiContextGuard(const ImGuiContextGuard&) = delete;
  ImGuiContextGuard& operator=(const ImGuiContextGuard&) = delete;
};

// The scene's 3-D text labels in the UI font (the lecture font in lecture mode), each above and right
// of its anchor so it never covers what it labels, on a light halo for contrast, and kept inside
// `area` (the part of the window the panels leave free) so none runs off an edge.
void drawLabels(const graphics::DebugRenderer& debug, const graphics::OrbitCamera& camera, float w, float h,
                const LabelBox& area, float offsetX) {
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const float gap = 0.3f * ImGui::GetFontSize(), halo = 0.15f * ImGui::GetFontSize();
  for (const graphics::ScreenLabel& label : debug.projectLabels(camera, w, h)) {
    if (!label.visible) continue;
    const ImVec2 size = ImGui::CalcTextSize(label.text.c_str());
    const LabelBox box = placeLabel(label.pixel.x + offsetX, label.pixel.y, size.x, size.y, gap, area);
    list->AddRectFilled(ImVec2(box.x0 - halo, box.y0 - halo), ImVec2(box.x1 + halo, box.y1 + halo),
                        IM_COL32(255, 255, 255, 190), halo);
    const ImU32 colour =
        ImGui::ColorConvertFloat4ToU32(ImVec4(label.color.r, label.color.g, label.color.b, label.color.a));
    list->AddText(ImVec2(box.x0, box.y0), colour, label.text.c_str());
  }
}

std::string timestampedScreenshotName(const std::string& lab, const std::string& scene) {
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  return "pba-" + lab + "-" + scene + "-" + stamp + ".png";
}

// Fits the scene in view; shifts it right of the panel and, when plots or a legend are shown, up from the
// plot panel in the lower right corner and the legend in the lower left, so that none covers it.
// Frames the scene's bounds in the part of the window the panels leave free: the controls on the
// left (panelPixels), a scene's own column on the right (overlayPixels), the plots at the bottom.
void applyView(graphics::OrbitCamera& camera, const CameraView& view) {
  camera.target = glm::vec3(view.target);
  camera.distance = static_cast<float>(view.distance);
  camera.yaw = static_cast<float>(view.yaw);
  camera.pitch = static_cast<float>(view.pitch);
  camera.clampState();
}

CameraView viewOf(const graphics::OrbitCamera& camera) {
  return CameraView{Vec3(camera.target), camera.distance, camera.yaw, camera.pitch};
}

// A scene's preferred view is made for the free part of a full window; a narrower view (one half of an
// A/B run) steps back by `widen` so the same picture fits.
void frameCamera(graphics::OrbitCamera& camera, const Scene& scene, glm::vec2 viewport, float panelPixels,
                 float overlayPixels, bool plotsShown, float widen = 1.0f) {
  const float aspect = viewport.y > 0.0f ? viewport.x / viewport.y : 1.0f;
  if (const std::optional<CameraView> view = scene.preferredView()) {
    camera.target = glm::vec3(view->target);
    camera.distance = static_cast<float>(view->distance) * widen;
    camera.yaw = static_cast<float>(view->yaw);
    camera.pitch = static_cast<float>(view->pitch);
    camera.clampState();
    camera.pan(0.5f * (panelPixels - overlayPixels), 0.0f, viewport);
    return;
  }
  graphics::DebugRenderer probe;
  SceneDraw draw(probe);
  scene.draw(draw);
  glm::vec3 lo, hi;
  if (probe.bounds(&lo, &hi)) {
    lo.y = std::min(lo.y, 0.0f);  // keep the ground in view
    // F always recovers a view: a camera left looking along the ground or from far overhead gets the
    // default elevation back (frame() keeps yaw and pitch).
    if (!(camera.pitch >= kMinFramedPitch && camera.pitch <= kMaxFramedPitch))
      camera.pitch = graphics::OrbitCamera{}.pitch;
    camera.frame(lo, hi, aspect);
    camera.zoom(-2.0f);  // a margin around the scene: room to move
    camera.pan(0.5f * (panelPixels - overlayPixels), plotsShown ? -0.12f * viewport.y : 0.0f, viewport);
  }
}

// An A/B run's caption at the top of its view: which side, and what it was started with or where it differs.
void compareCaption(const std::string& text, float x0, float width, bool b) {
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const float pad = 0.4f * ImGui::GetFontSize();
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const ImVec2 at(x0 + 0.5f * (width - size.x), pad);
  list->AddRectFilled(ImVec2(at.x - pad, at.y - 0.5f * pad), ImVec2(at.x + size.x + pad, at.y + size.y + 0.5f * pad),
                      b ? IM_COL32(255, 236, 214, 230) : IM_COL32(222, 234, 255, 230), pad);
  list->AddText(at, b ? IM_COL32(150, 70, 0, 255) : IM_COL32(20, 60, 140, 255), text.c_str());
  if (b)  // the seam between the two views
    list->AddLine(ImVec2(x0, 0.0f), ImVec2(x0, ImGui::GetIO().DisplaySize.y), IM_COL32(90, 90, 90, 255), 2.0f);
}

std::string compareText(const LabSession& session, bool b) {
  std::string text = b ? "B" : "A";
  const std::string& side = session.sideText(b);
  if (!side.empty()) return text + "   " + side;
  if (!b) return text;
  std::string differences;
  for (const std::string& d : compareDifferences(session.runner(), *session.partner()))
    differences += (differences.empty() ? "" : "  ") + d;
  return text + "   " + (differences.empty() ? "same as A" : differences);
}

}  // namespace

int runWindow(const std::string& lab, const LabOptions& options, SceneRunner& runner, SceneRunner* partner) {
  const bool recordCli = !options.record.empty();
  const bool capture = !options.screenshot.empty() || recordCli;
  const std::string settingsDir = capture ? std::string() : settingsDirectory(lab);
  LabSession session(lab, runner, options.seed);
  if (partner)
    session.startCompare(std::make_unique<SceneRunner>(std::move(*partner)),
                         options.compare ? options.compare->first : std::string(),
                         options.compare ? options.compare->second : std::string());
  session.settings() = loadLabSettings(settingsDir);
  session.setExercises(loadExercises(resourceDir() + "/exercises.tsv", lab));
  if (looksLikeSceneFile(options.scene)) {  // the file's camera bookmark
    Result<LoadedScene> file = loadSceneFile(options.scene, lab);
    if (file && file.value().camera) session.requestCamera(*file.value().camera);
  }
  WindowDemo demo;
  if (!options.demo.empty()) {
    if (Status s = demo.open(lab, options.demo, options.demoStep, options.demoNext); !s) {
      std::cerr << "pba-" << lab << ": " << s.error() << '\n';
      return kExitBadInput;
    }
  }
  if (!capture && options.scene.empty() && options.demo.empty() && !session.settings().lastScene.empty()) {
    const int index = sceneIndex(session.settings().lastScene);
    if (index >= 0) session.switchScene(index);
  }
  session.settings().lastScene = runner.sceneName();
  if (session.settings().plotted.empty()) session.settings().plotted = runner.scene().defaultPlots();

  graphics::WindowDesc desc;
  desc.samples = multisamplesFromEnvironment(desc.samples);
  desc.title = "PBA Labs - " + lab;
  const auto [defaultWidth, defaultHeight] =
      capture ? std::pair{1280, 720} : std::pair{session.settings().windowWidth, session.settings().windowHeight};
  desc.width = options.size ? options.size->first : defaultWidth;
  desc.height = options.size ? options.size->second : defaultHeight;
  desc.vsync = !capture;
  std::string error;
  std::unique_ptr<graphics::Window> window = graphics::Window::create(desc, &error);
  if (!window) {
    std::cerr << "pba-" << lab << ": " << error << '\n';
    return kExitInternal;
  }
  std::unique_ptr<graphics::Renderer> renderer = graphics::Renderer::create(resourceDir() + "/shaders", &error);
  if (!renderer) {
    std::cerr << "pba-" << lab << ": " << error << '\n';
    return kExitInternal;
  }

  std::string iniPath = settingsDir.empty() ? std::string() : settingsDir + "/imgui.ini";
  if (!iniPath.empty()) std::filesystem::create_directories(settingsDir);
  ImGuiContextGuard imgui(window->handle(), !iniPath.empty());
  if (!iniPath.empty()) ImGui::GetIO().IniFilename = iniPath.c_str();
  UiFonts fonts = loadUiFonts(window->contentScale().y);

  UiState ui;
  ui.lecture = options.lecture || (!capture && session.settings().lecture);
  ui.demoActive = demo.active();
  if (demo.active()) demo.printNotes();
  graphics::OrbitCamera camera;
  graphics::DebugRenderer debug;
  WindowInput input;
  input.install(window->handle());
  const long captureFrames = options.frameCount();
  WindowRecording recording;
  if (recordCli) {
    const glm::ivec2 fb = window->framebufferSize();
    if (Status s = recording.start(options.record, fb.x, fb.y, captureFrames); !s) {
      std::cerr << "pba-" << lab << ": " << s.error() << '\n';
      return kExitBadInput;
    }
    ui.hideUi = !options.recordUi;
  }
  std::string title = desc.title;
  std::string statusPath = uiStatusPath();  // tests/ui: the machine-readable status of every frame
  long frame = 0;
  bool demoRecording = false;  // the running recording is a demo step's
  bool leaveDemo = false;      // the next demo step is another lab's: close after this frame
  auto last = std::chrono::steady_clock::now();
  int exitCode = kExitOk;

  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);
  while (!window->shouldClose() && !gStopRequested) {
    graphics::Window::pollEvents();
    const auto now = std::chrono::steady_clock::now();
    const double wallSeconds = std::chrono::duration<double>(now - last).count();
    last = now;
    ui.frameMs = wallSeconds * 1000.0;

    const glm::ivec2 fb = window->framebufferSize();
    const glm::ivec2 ws = window->windowSize();
    // Between frames: the modes asked for during the last frame, then the style and font they imply.
    ui.applyPending();
    ui.sideFont = applyUiStyle(fonts, ui.lecture, static_cast<float>(ws.y));
    renderer->lectureMode(ui.lecture);

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();

    const float panelPixels = ui.hideUi ? 0.0f : panelWidthPixels(ui);
    float overlayPixels = ui.hideUi || !runner.scene().wantsOverlay() ? 0.0f : overlayWidthPixels(ui);
    // A demo's notes window takes the upper right: the framing leaves it that column.
    if (demo.active() && ui.showNotes && !ui.hideUi) overlayPixels = std::max(overlayPixels, demo.notesWidth() + 16.0f);
    // A/B: the part of the window the panels leave free, split in two views with one camera.
    const bool split = session.comparing();
    const float viewLeft = split ? panelPixels : 0.0f;
    const float viewWidth = split ? 0.5f * (static_cast<float>(ws.x) - overlayPixels - panelPixels) : float(ws.x);
    input.setSplit(split ? std::optional<std::pair<float, float>>({viewLeft, viewWidth}) : std::nullopt);
    if (!capture) input.update(session, ui, camera, static_cast<float>(ws.x), static_cast<float>(ws.y));
    // Demo steps: the recording of a step ends with it; another lab's step closes the window after this frame.
    if (demo.active() && (ui.demoMove != 0 || frame == 0)) {
      const int delta = ui.demoMove;
      ui.demoMove = 0;
      const WindowDemo::Move moved = delta == 0 ? WindowDemo::Move::Shown : demo.move(delta, session);
      if (moved != WindowDemo::Move::None && demoRecording && recording.active()) {
        Result<std::string> done = recording.finish();
        session.setMessage(done ? done.value() : done.error());
        demoRecording = false;
      }
      if (moved == WindowDemo::Move::Leave) leaveDemo = true;
      if (moved == WindowDemo::Move::Shown) {
        if (delta != 0) demo.printNotes();
        if (!demo.step().record.empty() && !recording.active() && !capture) {
          const Status s = recording.start(demo.step().record, fb.x, fb.y, 0);
          session.setMessage(s ? "Recording this step to " + demo.step().record : s.error());
          demoRecording = static_cast<bool>(s);
        }
      }
    }
    if (session.takeFrameRequest() || ui.frameRequested) {
      if (split)
        frameCamera(camera, runner.scene(), glm::vec2(viewWidth, ws.y), 0.0f, 0.0f, false,
                    (static_cast<float>(ws.x) - panelPixels - overlayPixels) / std::max(viewWidth, 1.0f));
      else
        frameCamera(camera, runner.scene(), glm::vec2(ws), panelPixels, overlayPixels,
                    !ui.hideUi && (!session.settings().plotted.empty() || !runner.scene().legend().empty()));
      ui.frameRequested = false;
    }
    // A camera bookmark (scene file, demo step) replaces the framing.
    if (std::optional<CameraView> view = session.takeCameraRequest()) applyView(camera, *view);
    if (std::optional<CameraView> view = demo.active() ? demo.takeCamera() : std::nullopt) applyView(camera, *view);
    session.setCurrentCamera(viewOf(camera));
    // Captures and recordings advance exactly one display frame of simulated time per frame.
    const bool fixedFrames = capture || recording.active();
    const Real frameSeconds = fixedFrames ? kDisplayFrame : std::min(wallSeconds, kMaxFrameSeconds);
    runner.advanceFrame(frameSeconds, fixedFrames ? -1 : kMaxStepsPerFrame);
    if (SceneRunner* b = session.partner()) b->advanceFrame(frameSeconds, fixedFrames ? -1 : kMaxStepsPerFrame);
    session.afterFrame(input.dragging());  // plots and the rewind history

    // One view, or A and B side by side: each drawn into its own viewport (framebuffer pixels).
    const float toFb = ws.x > 0 ? static_cast<float>(fb.x) / static_cast<float>(ws.x) : 1.0f;
    UiFrame status{frame + 1, glm::vec2(ws), input.pickedHandle(), glm::vec3(input.dragPlanePoint()), input.dragging()};
    auto drawView = [&](const Scene& scene, float x0, bool first) {
      renderer->beginFrame(camera, static_cast<int>(viewWidth * toFb), fb.y, static_cast<int>(x0 * toFb), 0);
      SceneDraw draw(debug);
      scene.draw(draw);
      debug.flush(*renderer);
      const LabelBox area =
          split ? LabelBox{x0, 0.0f, x0 + viewWidth, static_cast<float>(ws.y)}
                : LabelBox{panelPixels, 0.0f, static_cast<float>(ws.x) - overlayPixels, static_cast<float>(ws.y)};
      drawLabels(debug, camera, viewWidth, static_cast<float>(ws.y), area, x0);
      if (first) status.hasBounds = debug.bounds(&status.boundsMin, &status.boundsMax);
      debug.clear();
      renderer->endFrame();
    };
    // The UI tests' scene alone (app/window/scene_image.h): rendered first, the frame below clears it again.
    if (ui.screenshotRequested && !statusPath.empty() && !split) {
      const std::string path = sceneImagePath(timestampedScreenshotName(lab, runner.sceneName()));
      const Status s = writeSceneImage(*renderer, debug, camera, runner.scene(), fb, path);
      ui.lastSceneImage = s ? path : std::string();
      if (!s) std::cerr << "pba-" << lab << ": " << s.error() << '\n';
    }
    drawView(runner.scene(), viewLeft, true);
    if (split) {
      drawView(session.partner()->scene(), viewLeft + viewWidth, false);
      compareCaption(compareText(session, false), viewLeft, viewWidth, false);
      compareCaption(compareText(session, true), viewLeft + viewWidth, viewWidth, true);
    }
    drawLabUi(session, ui);
    if (demo.active() && !ui.hideUi)
      demo.notesWindow(ui, static_cast<float>(ws.x) - (runner.scene().wantsOverlay() ? overlayWidthPixels(ui) : 0.0f));
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    ++frame;
    const bool captureNow = capture && frame >= captureFrames;
    if (recording.active()) {
      if (Status s = recording.capture(fb.x, fb.y); !s) {
        std::cerr << "pba-" << lab << ": " << s.error() << '\n';
        static_cast<void>(recording.finish());
        if (recordCli) {
          exitCode = kExitBadInput;
          break;
        }
        session.setMessage(s.error());
      }
    }
    // F9 takes effect after this frame's capture: a recording holds whole frames of fixed steps.
    if (ui.recordRequested) {
      ui.recordRequested = false;
      if (!capture) {
        const std::string said = recording.toggle(lab, runner.sceneName(), fb.x, fb.y);
        session.setMessage(said);
        ui.showNotice(said, ImGui::GetTime());
      }
    }
    ui.recording = recording.statusText();
    ui.recordingFraction = recording.fraction();
    if (const std::string t = desc.title + (ui.recording.empty() ? "" : "  -  " + ui.recording); t != title) {
      window->setTitle(t);
      title = t;
    }
    if (ui.screenshotRequested || (captureNow && !recordCli)) {
      const std::string path = captureNow ? options.screenshot : timestampedScreenshotName(lab, runner.sceneName());
      if (!graphics::saveScreenshot(path, fb.x, fb.y, &error)) {
        std::cerr << "pba-" << lab << ": " << error << '\n';
        exitCode = kExitBadInput;
      } else {
        session.setMessage("Screenshot saved: " + path);
        ui.lastScreenshot = path;
        ui.showNotice("Screenshot saved: " + path, ImGui::GetTime());
      }
      ui.screenshotRequested = false;
    }
    if (!statusPath.empty()) {
      if (Status s = writeUiStatus(statusPath, uiStatus(session, ui, camera, status)); !s) {
        std::cerr << "pba-" << lab << ": " << s.error() << '\n';
        statusPath.clear();  // said once; the window goes on
      }
    }
    window->swapBuffers();
    if (captureNow || leaveDemo) break;
  }

  nlohmann::json recorded = nullptr;
  if (recording.active()) {
    const long frames = recording.frames();
    if (Result<std::string> done = recording.finish(); !done) {
      std::cerr << "pba-" << lab << ": " << done.error() << '\n';
      if (recordCli) exitCode = kExitBadInput;
    } else {
      std::cerr << "pba-" << lab << ": " << done.value() << '\n';
      if (recordCli) recorded = {{"path", options.record}, {"frames", frames}};
    }
  }
  if (capture && !options.metrics.empty()) {
    nlohmann::json report = metricsReport(lab, runner, frame);
    report["gl_renderer"] = window->glRenderer();
    if (!recorded.is_null()) report["recording"] = recorded;
    if (Status s = writeMetrics(report, options.metrics); !s) {
      std::cerr << "pba-" << lab << ": " << s.error() << '\n';
      return kExitBadInput;
    }
  }
  if (!options.poseJson.empty()) {  // the scene on screen at the end (the window may have switched scenes)
    if (Status s = writePoseJson(lab, runner, options.poseJson); !s) {
      std::cerr << "pba-" << lab << ": " << s.error() << '\n';
      exitCode = kExitBadInput;
    }
  }
  if (!capture) {
    const glm::ivec2 size = window->windowSize();
    session.settings().windowWidth = size.x;
    session.settings().windowHeight = size.y;
    session.settings().lecture = ui.lecture;
    saveLabSettings(settingsDir, session.settings());
  }
  return exitCode;
}

}  // namespace pba::app
