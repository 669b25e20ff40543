// Window: a GLFW window with an OpenGL 3.3 core context and GLEW loaded (RAII, one per process is
// the normal case; several are allowed). Creation never throws: it returns nullptr and a one-line
// error that says what to try (xvfb-run, --headless, a newer driver).
#pragma once

#include <glm/vec2.hpp>

#include <memory>
#include <string>

struct GLFWwindow;

namespace pba::graphics {

struct WindowDesc {
  std::string title = "PBA Labs";
  int width = 1280;  ///< window size in screen coordinates
  int height = 720;
  bool visible = true;  ///< under Xvfb keep it visible: hidden windows may not render with some Mesa setups
  bool vsync = true;
  int samples = 4;  ///< MSAA samples of the default framebuffer; falls back to 0 when unavailable
};

class Window {
 public:
  /// Opens the window and makes its context current. nullptr + *error (one line) on failure.
  static std::unique_ptr<Window> create(const WindowDesc& desc, std::string* error);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  glm::ivec2 framebufferSize() const;       ///< pixels (what glViewport wants)
  glm::ivec2 windowSize() const;            ///< screen coordinates (what cursor positions use)
  glm::vec2 contentScale() const;           ///< DPI scale, 1 on a normal monitor and under Xvfb
  int samples() const { return samples_; }  ///< MSAA samples actually obtained

  bool shouldClose() const;
  void setShouldClose(bool close);
  void swapBuffers();
  static void pollEvents();
  void setTitle(const std::string& title);
  void makeCurrent();
  std::string glRenderer() const;  ///< e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string glVersion() const;

 private:
  Window() = default;
  GLFWwindow* window_ = nullptr;
  int samples_ = 0;
};

}  // namespace pba::graphics
