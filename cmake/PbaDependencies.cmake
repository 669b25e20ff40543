# Every dependency comes from a system package (docs/architecture.md §6). A missing one stops configure
# with the Debian package to install; ./pba installs them all with apt-get.
find_package(PkgConfig)

function(pba_missing what package)
  message(FATAL_ERROR "PBA Labs: ${what} not found. Install it with: sudo apt-get install ${package}  (or run ./pba doctor)")
endfunction()

if(NOT PkgConfig_FOUND)
  pba_missing("pkg-config" "pkg-config")
endif()

find_package(glm CONFIG QUIET)
if(NOT glm_FOUND)
  pba_missing("GLM" "libglm-dev")
endif()
if(NOT TARGET glm::glm)
  add_library(glm::glm INTERFACE IMPORTED)
endif()

# Eigen 3.4 (header-only): dense factorisations of the physics library where linear algebra is not
# the lesson (IK's SVD and Cholesky, Horn's 4 × 4 eigenproblem).
find_package(Eigen3 3.4 CONFIG QUIET)
if(NOT Eigen3_FOUND)
  pba_missing("Eigen 3.4" "libeigen3-dev")
endif()

find_package(nlohmann_json 3.10 CONFIG QUIET)
if(NOT nlohmann_json_FOUND)
  pba_missing("nlohmann-json" "nlohmann-json3-dev")
endif()

find_package(glfw3 3.3 CONFIG QUIET)
if(NOT glfw3_FOUND)
  pba_missing("GLFW 3.3" "libglfw3-dev")
endif()

set(OpenGL_GL_PREFERENCE GLVND)
find_package(OpenGL QUIET)
if(NOT OpenGL_FOUND)
  pba_missing("OpenGL" "libgl-dev")
endif()

find_package(GLEW QUIET)
if(NOT GLEW_FOUND)
  pba_missing("GLEW" "libglew-dev")
endif()

pkg_check_modules(PBA_IMGUI QUIET IMPORTED_TARGET imgui)
if(NOT PBA_IMGUI_FOUND)
  pba_missing("Dear ImGui (pkg-config imgui)" "libimgui-dev")
endif()
pkg_check_modules(PBA_STB QUIET IMPORTED_TARGET stb)
if(NOT PBA_STB_FOUND)
  pba_missing("stb (pkg-config stb)" "libstb-dev")
endif()

find_package(assimp CONFIG QUIET)
if(NOT assimp_FOUND)
  pba_missing("Assimp" "libassimp-dev")
endif()

if(PBA_BUILD_TESTS)
  find_package(GTest CONFIG QUIET)
  if(NOT GTest_FOUND)
    pba_missing("GoogleTest" "googletest libgtest-dev")
  endif()
endif()
if(PBA_BUILD_BENCH)
  find_package(benchmark CONFIG QUIET)
  if(NOT benchmark_FOUND)
    pba_missing("Google Benchmark" "libbenchmark-dev")
  endif()
endif()
