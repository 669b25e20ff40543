// What the labs ask of the operating system, with one path each for Windows, macOS and Linux (and other
// POSIX systems): where the running program is, how much memory it holds, whether
// stderr is a terminal, and where a user's settings live.
#pragma once

#include <cstddef>
#include <filesystem>

namespace pba::app {

/// The running executable's path; empty when the system cannot say.
std::filesystem::path executablePath();

/// Resident memory of this process [bytes] (Linux: VmRSS; macOS: the task's resident size; Windows: the
/// working set), after handing freed heap pages back to the system where the allocator keeps them.
/// 0 when the system cannot say.
std::size_t residentBytes();

/// glibc keeps up to 7 freed chunks of each of 64 sizes per thread and counts them as in use, so a heap
/// measure there moves with the allocation pattern. This runs the program again (same arguments) with that
/// cache off, once; it returns when the cache is already off, when the re-run fails, and on every other
/// system, whose allocators report freed memory as free.
void restartWithoutMallocThreadCache(const char* const* argv);

/// True when standard error is an interactive terminal (progress lines redraw in place there).
bool standardErrorIsTerminal();

/// The per-user folder for application settings: %APPDATA% on Windows, ~/Library/Application Support on
/// macOS, $XDG_CONFIG_HOME (default ~/.config) elsewhere; empty when no home folder is known.
std::filesystem::path userConfigDir();

}  // namespace pba::app
