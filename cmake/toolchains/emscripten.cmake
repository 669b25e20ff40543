# Builds for the browser (WebAssembly + WebGL2) with the system's Emscripten (Debian's `emscripten`
# package), as `./pba web` does (tools/web_build.sh). Emscripten's own toolchain file does the work; this
# one adds the dependency prefixes listed in PBA_WEB_PREFIX_PATH (a CMake list, or the environment
# variable of that name separated by ':'), which, with Emscripten's sysroot, are the only places searched
# for headers, libraries and CMake packages. No Emscripten port is used: ports are downloaded.
if(NOT EMSCRIPTEN_ROOT_PATH)
  find_program(_pba_emcc emcc REQUIRED)
  get_filename_component(_pba_emcc "${_pba_emcc}" REALPATH)
  get_filename_component(EMSCRIPTEN_ROOT_PATH "${_pba_emcc}" DIRECTORY)
endif()
include("${EMSCRIPTEN_ROOT_PATH}/cmake/Modules/Platform/Emscripten.cmake")

if(NOT PBA_WEB_PREFIX_PATH AND DEFINED ENV{PBA_WEB_PREFIX_PATH})
  set(PBA_WEB_PREFIX_PATH "$ENV{PBA_WEB_PREFIX_PATH}")
endif()
string(REPLACE ":" ";" PBA_WEB_PREFIX_PATH "${PBA_WEB_PREFIX_PATH}")
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES PBA_WEB_PREFIX_PATH)
list(APPEND CMAKE_FIND_ROOT_PATH ${PBA_WEB_PREFIX_PATH})
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
# Find modules that fall back to pkg-config (assimp's minizip) see the prefixes' .pc files only.
set(_pba_pc "")
foreach(_pba_prefix IN LISTS PBA_WEB_PREFIX_PATH)
  string(APPEND _pba_pc "${_pba_prefix}/lib/pkgconfig:${_pba_prefix}/share/pkgconfig:")
endforeach()
set(ENV{PKG_CONFIG_LIBDIR} "${_pba_pc}")
set(ENV{PKG_CONFIG_PATH} "")
# Exceptions are part of the labs' error handling (Result types aside, the JSON parser throws).
string(APPEND CMAKE_CXX_FLAGS_INIT " -fexceptions")
string(APPEND CMAKE_EXE_LINKER_FLAGS_INIT " -fexceptions")
