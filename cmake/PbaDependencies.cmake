# Every dependency comes from a package of the system (docs/architecture.md §6). CMake looks
# for each through its CONFIG package first, under the names vcpkg and Homebrew install (what a Windows
# or macOS student has), and falls back to pkg-config only where Debian ships nothing else (ImGui's and
# stb's .pc files). A missing one stops configure naming what to install on each system.
find_package(PkgConfig QUIET)

function(pba_missing what debian vcpkg)
  message(FATAL_ERROR "PBA Labs: ${what} not found. Install it: on Debian/Ubuntu `sudo apt-get install ${debian}` "
                      "(or run ./pba doctor); with vcpkg the manifest vcpkg.json lists it as `${vcpkg}`; "
                      "with Homebrew see README.md, \"On your own machine\".")
endfunction()

find_package(glm CONFIG QUIET)
if(NOT glm_FOUND)
  pba_missing("GLM" "libglm-dev" "glm")
endif()
if(NOT TARGET glm::glm)
  add_library(glm::glm INTERFACE IMPORTED)
endif()

# Eigen 3.4 (header-only): dense factorisations of the physics library where linear algebra is not
# the lesson (IK's SVD and Cholesky, Horn's 4 × 4 eigenproblem).
find_package(Eigen3 3.4 CONFIG QUIET)
if(NOT Eigen3_FOUND)
  pba_missing("Eigen 3.4" "libeigen3-dev" "eigen3")
endif()

find_package(nlohmann_json 3.10 CONFIG QUIET)
if(NOT nlohmann_json_FOUND)
  pba_missing("nlohmann-json" "nlohmann-json3-dev" "nlohmann-json")
endif()

if(EMSCRIPTEN)
  # The browser (tools/web_build.sh): GLFW is Emscripten's JavaScript library, exported by the ImGui
  # prefix as imgui::glfw; WebGL2 needs neither a GL library nor a loader.
  find_package(imgui CONFIG QUIET)
  if(NOT TARGET imgui::glfw)
    pba_missing("Dear ImGui built for Emscripten" "(./pba web builds it)" "imgui")
  endif()
  add_library(glfw INTERFACE IMPORTED)
  target_link_libraries(glfw INTERFACE imgui::glfw)
  add_library(OpenGL::GL INTERFACE IMPORTED)
  add_library(GLEW::GLEW INTERFACE IMPORTED)
else()
  find_package(glfw3 3.3 CONFIG QUIET)
  if(NOT glfw3_FOUND)
    pba_missing("GLFW 3.3" "libglfw3-dev" "glfw3")
  endif()

  set(OpenGL_GL_PREFERENCE GLVND)
  find_package(OpenGL QUIET)
  if(NOT OpenGL_FOUND)
    pba_missing("OpenGL" "libgl-dev" "(the system's OpenGL)")
  endif()

  # GLEW: vcpkg's and GLEW's own CONFIG package first, then CMake's FindGLEW module (Debian); both give
  # GLEW::GLEW.
  find_package(GLEW CONFIG QUIET)
  if(NOT GLEW_FOUND)
    find_package(GLEW MODULE QUIET)
  endif()
  if(NOT GLEW_FOUND)
    pba_missing("GLEW" "libglew-dev" "glew")
  endif()
  if(NOT TARGET GLEW::GLEW)
    foreach(candidate GLEW::glew GLEW::glew_s)
      if(TARGET ${candidate})
        add_library(GLEW::GLEW INTERFACE IMPORTED)
        target_link_libraries(GLEW::GLEW INTERFACE ${candidate})
        break()
      endif()
    endforeach()
  endif()
endif()

# Dear ImGui with its GLFW and OpenGL3 backends: vcpkg's port (features glfw-binding, opengl3-binding)
# exports imgui::imgui; Debian's libimgui-dev has only a .pc file. pba_imgui is whichever was found.
add_library(pba_imgui INTERFACE)
find_package(imgui CONFIG QUIET)
if(imgui_FOUND)
  target_link_libraries(pba_imgui INTERFACE imgui::imgui)
else()
  if(PkgConfig_FOUND)
    pkg_check_modules(PBA_IMGUI QUIET IMPORTED_TARGET imgui)
  endif()
  if(NOT PBA_IMGUI_FOUND)
    pba_missing("Dear ImGui with its GLFW and OpenGL3 backends" "libimgui-dev" "imgui[glfw-binding,opengl3-binding]")
  endif()
  target_link_libraries(pba_imgui INTERFACE PkgConfig::PBA_IMGUI)
  # Debian keeps the backends' headers in imgui/backends; vcpkg's port puts them beside imgui.h. The code
  # includes them by name alone (<imgui_impl_glfw.h>), so that folder joins the include path.
  pkg_get_variable(PBA_IMGUI_INCLUDEDIR imgui includedir)
  if(EXISTS "${PBA_IMGUI_INCLUDEDIR}/backends")
    target_include_directories(pba_imgui SYSTEM INTERFACE "${PBA_IMGUI_INCLUDEDIR}/backends")
  endif()
endif()

# stb (stb_image.h, stb_image_write.h): Debian builds the implementations into libstb (found through its
# .pc file); vcpkg and Homebrew install the headers alone, and then graphics/stb_implementation.cpp
# compiles them (PBA_STB_HEADER_ONLY). pba_stb is whichever was found.
add_library(pba_stb INTERFACE)
if(PkgConfig_FOUND)
  pkg_check_modules(PBA_STB QUIET IMPORTED_TARGET stb)
endif()
if(PBA_STB_FOUND)
  target_link_libraries(pba_stb INTERFACE PkgConfig::PBA_STB)
  set(PBA_STB_HEADER_ONLY OFF)
else()
  find_path(PBA_STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb)
  if(NOT PBA_STB_INCLUDE_DIR)
    pba_missing("stb (stb_image.h, stb_image_write.h)" "libstb-dev" "stb")
  endif()
  target_include_directories(pba_stb SYSTEM INTERFACE "${PBA_STB_INCLUDE_DIR}")
  set(PBA_STB_HEADER_ONLY ON)
endif()

find_package(assimp CONFIG QUIET)
if(NOT assimp_FOUND)
  pba_missing("Assimp" "libassimp-dev" "assimp")
endif()

# GoogleTest from its sources (PBA_GTEST_SOURCE_DIR, e.g. Debian's /usr/src/googletest) when the tests
# are built against another standard library than the system's GoogleTest was (the libcxx preset).
set(PBA_GTEST_SOURCE_DIR "" CACHE PATH "Build GoogleTest from these sources instead of finding its package")
if(PBA_BUILD_TESTS AND PBA_GTEST_SOURCE_DIR)
  set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
  set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
  add_subdirectory("${PBA_GTEST_SOURCE_DIR}" "${CMAKE_BINARY_DIR}/googletest" EXCLUDE_FROM_ALL)
  # Its headers as system headers: the project's warnings are for the project's code.
  get_target_property(pba_gtest_includes gtest INTERFACE_INCLUDE_DIRECTORIES)
  set_target_properties(gtest PROPERTIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${pba_gtest_includes}")
  if(NOT TARGET GTest::gtest)
    add_library(GTest::gtest ALIAS gtest)
  endif()
elseif(PBA_BUILD_TESTS)
  find_package(GTest CONFIG QUIET)
  if(NOT GTest_FOUND)
    pba_missing("GoogleTest" "googletest libgtest-dev" "gtest")
  endif()
endif()
if(PBA_BUILD_BENCH)
  find_package(benchmark CONFIG QUIET)
  if(NOT benchmark_FOUND)
    pba_missing("Google Benchmark" "libbenchmark-dev" "benchmark")
  endif()
endif()
