# Cross-compiles for 64-bit Windows with MinGW-w64's `-posix` compilers (std::thread through
# winpthreads), as `./pba cross windows` does (tools/cross_windows.sh). The dependencies come from
# the prefixes listed in PBA_MINGW_PREFIX_PATH (a CMake list, or the environment variable of that
# name separated by ':'); only they and the MinGW-w64 sysroot are searched for headers, libraries
# and CMake packages. Executables link libgcc, libstdc++ and winpthread statically, so a .exe runs
# under Wine (or on Windows) with no MinGW DLL beside it.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)

set(PBA_MINGW_TRIPLE x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${PBA_MINGW_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${PBA_MINGW_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${PBA_MINGW_TRIPLE}-windres)
set(CMAKE_AR ${PBA_MINGW_TRIPLE}-gcc-ar-posix CACHE FILEPATH "")
set(CMAKE_RANLIB ${PBA_MINGW_TRIPLE}-gcc-ranlib-posix CACHE FILEPATH "")

if(NOT PBA_MINGW_PREFIX_PATH AND DEFINED ENV{PBA_MINGW_PREFIX_PATH})
  set(PBA_MINGW_PREFIX_PATH "$ENV{PBA_MINGW_PREFIX_PATH}")
endif()
string(REPLACE ":" ";" PBA_MINGW_PREFIX_PATH "${PBA_MINGW_PREFIX_PATH}")
# try_compile projects read this file again: hand them the prefixes.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES PBA_MINGW_PREFIX_PATH)

set(CMAKE_FIND_ROOT_PATH ${PBA_MINGW_PREFIX_PATH} /usr/${PBA_MINGW_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# Find modules that fall back to pkg-config (assimp's minizip) see the prefixes' .pc files only.
set(_pba_pc "")
foreach(_pba_prefix IN LISTS PBA_MINGW_PREFIX_PATH)
  string(APPEND _pba_pc "${_pba_prefix}/lib/pkgconfig:${_pba_prefix}/share/pkgconfig:")
endforeach()
set(ENV{PKG_CONFIG_LIBDIR} "${_pba_pc}")
set(ENV{PKG_CONFIG_PATH} "")

set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
set(CMAKE_SHARED_LINKER_FLAGS_INIT "-static-libgcc -static-libstdc++")
set(CMAKE_MODULE_LINKER_FLAGS_INIT "-static-libgcc -static-libstdc++")

# ctest and add_test run the .exe files through Wine.
find_program(PBA_WINE NAMES wine wine64)
if(PBA_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR "${PBA_WINE}")
endif()
