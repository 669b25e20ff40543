// host_system.h: the Windows, macOS and Linux calls side by side, each behind its own #if.
#include "app/runner/host_system.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#if defined(_WIN32)
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
// psapi.h after windows.h
#include <io.h>
#include <psapi.h>
#elif defined(__APPLE__)
#include <mach-o/dyld.h>
#include <mach/mach.h>
#include <malloc/malloc.h>
#include <unistd.h>
#else
#include <unistd.h>
#endif
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pba::app {
namespace {

std::filesystem::path fromEnvironment(const char* name) {
  const char* value = std::getenv(name);
  return value && *value ? std::filesystem::path(value) : std::filesystem::path();
}

}  // namespace

std::filesystem::path executablePath() {
  std::error_code ec;
#if defined(_WIN32)
  wchar_t buffer[32768];
  const DWORD length = GetModuleFileNameW(nullptr, buffer, static_cast<DWORD>(std::size(buffer)));
  if (length == 0 || length >= std::size(buffer)) return {};
  return std::filesystem::path(std::wstring(buffer, length));
#elif defined(__APPLE__)
  char buffer[4096];
  uint32_t size = sizeof buffer;
  if (_NSGetExecutablePath(buffer, &size) != 0) return {};
  const std::filesystem::path resolved = std::filesystem::canonical(buffer, ec);
  return ec ? std::filesystem::path(buffer) : resolved;
#else
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : self;
#endif
}

std::size_t residentBytes() {
#if defined(_WIN32)
  PROCESS_MEMORY_COUNTERS counters{};
  if (!GetProcessMemoryInfo(GetCurrentProcess(), &counters, sizeof counters)) return 0;
  return static_cast<std::size_t>(counters.WorkingSetSize);
#elif defined(__APPLE__)
  mach_task_basic_info_data_t info{};
  mach_msg_type_number_t count = MACH_TASK_BASIC_INFO_COUNT;
  if (task_info(mach_task_self(), MACH_TASK_BASIC_INFO, reinterpret_cast<task_info_t>(&info), &count) != KERN_SUCCESS)
    return 0;
  return static_cast<std::size_t>(info.resident_size);
#else
#if defined(__GLIBC__)
  malloc_trim(0);  // glibc's malloc keeps freed pages otherwise
#endif
  std::ifstream statm("/proc/self/statm");
  std::size_t size = 0, resident = 0;
  if (!(statm >> size >> resident)) return 0;
  return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
#endif
}

void restartWithoutMallocThreadCache(const char* const* argv) {
#if defined(__GLIBC__)
  constexpr const char* kTunable = "glibc.malloc.tcache_count=0";
  const char* current = std::getenv("GLIBC_TUNABLES");
  if (current && std::strstr(current, kTunable)) return;
  const std::string value = current && *current ? std::string(current) + ":" + kTunable : std::string(kTunable);
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  execv("/proc/self/exe", const_cast<char* const*>(argv));  // returns only on failure
#else
  (void)argv;
#endif
}

bool standardErrorIsTerminal() {
#if defined(_WIN32)
  return _isatty(_fileno(stderr)) != 0;
#else
  return ::isatty(STDERR_FILENO) != 0;
#endif
}

std::filesystem::path userConfigDir() {
#if defined(_WIN32)
  return fromEnvironment("APPDATA");
#elif defined(__APPLE__)
  const std::filesystem::path home = fromEnvironment("HOME");
  return home.empty() ? home : home / "Library" / "Application Support";
#else
  if (std::filesystem::path xdg = fromEnvironment("XDG_CONFIG_HOME"); !xdg.empty()) return xdg;
  const std::filesystem::path home = fromEnvironment("HOME");
  return home.empty() ? home : home / ".config";
#endif
}

}  // namespace pba::app
