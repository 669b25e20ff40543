// A window with GLFW, GL functions through GLEW, an ImGui frame, a model read by Assimp, then one frame
// read back and written as PNG (argv[1]). Exit 0 when the frame is not blank.
#include <GL/glew.h>
#include <GLFW/glfw3.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <assimp/Importer.hpp>

#include <Eigen/Dense>
#include <cstdio>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <vector>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

int main(int argc, char** argv) {
  const char* obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFileFromMemory(obj, std::char_traits<char>::length(obj), aiProcess_Triangulate, "obj");
  const auto json = nlohmann::json::parse(R"({"eigen": 2})");
  Eigen::Matrix2d m = Eigen::Matrix2d::Identity() * json["eigen"].get<double>();
  const glm::vec3 v = glm::normalize(glm::vec3(1, 2, 2));
  std::printf("assimp: %s meshes %u; json+eigen det %.1f; glm %.3f\n", scene ? "ok" : importer.GetErrorString(),
              scene ? scene->mNumMeshes : 0u, m.determinant(), v.x);

  if (!glfwInit()) {
    std::puts("glfwInit failed");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  GLFWwindow* window = glfwCreateWindow(320, 240, "pba cross smoke", nullptr, nullptr);
  if (!window) {
    std::puts("glfwCreateWindow failed (OpenGL 3.3 core)");
    return 1;
  }
  glfwMakeContextCurrent(window);
  glewExperimental = GL_TRUE;
  if (glewInit() != GLEW_OK) {
    std::puts("glewInit failed");
    return 1;
  }
  std::printf("GL %s, %s\n", reinterpret_cast<const char*>(glGetString(GL_VERSION)),
              reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  int w = 0, h = 0;
  for (int frame = 0; frame < 3; ++frame) {
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(10, 10));
    ImGui::Begin("smoke");
    ImGui::Text("ImGui %s under MinGW-w64", IMGUI_VERSION);
    ImGui::End();
    ImGui::Render();
    glfwGetFramebufferSize(window, &w, &h);
    glViewport(0, 0, w, h);
    glClearColor(0.2f, 0.3f, 0.5f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (frame < 2) glfwSwapBuffers(window);
  }
  std::vector<unsigned char> rgb(static_cast<size_t>(w) * h * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  size_t distinct = 0;
  for (size_t i = 3; i < rgb.size(); i += 3) distinct += rgb[i] != rgb[0];
  if (argc > 1) {
    stbi_flip_vertically_on_write(1);
    stbi_write_png(argv[1], w, h, 3, rgb.data(), w * 3);
  }
  std::printf("frame %dx%d, %zu pixels differ from the clear colour\n", w, h, distinct);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return scene && distinct > 0 ? 0 : 1;
}
