// Child processes through the C runtime's pipes: the POSIX and the Windows spellings side by side.
#include "graphics/child_process.h"

#include <cstdlib>
#include <filesystem>

#if defined(_WIN32)
#include <cstdio>
#else
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#endif

namespace pba::graphics {
namespace {

#if defined(_WIN32)
constexpr char kPathSeparator = ';';
#else
constexpr char kPathSeparator = ':';
#endif

bool isExecutableFile(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return false;
#if defined(_WIN32)
  return true;  // Windows has no execute bit: the .exe name is what counts
#else
  return ::access(file.c_str(), X_OK) == 0;
#endif
}

}  // namespace

std::string findProgramOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  const std::string dirs = path;
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(kPathSeparator, start), dirs.size());
    const std::string dir = dirs.substr(start, end - start);
    if (!dir.empty()) {
      const std::filesystem::path candidate = std::filesystem::path(dir) / name;
      if (isExecutableFile(candidate)) return candidate.string();
#if defined(_WIN32)
      const std::filesystem::path exe = std::filesystem::path(dir) / (name + ".exe");
      if (isExecutableFile(exe)) return exe.string();
#endif
    }
    start = end + 1;
  }
  return {};
}

std::string quotedArgument(const std::string& argument) {
#if defined(_WIN32)
  // cmd.exe: double quotes; a double quote inside is doubled (file names cannot hold one anyway).
  std::string out = "\"";
  for (char c : argument) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
#else
  std::string out = "'";
  for (char c : argument) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
#endif
}

std::FILE* openWritePipe(const std::string& command) {
#if defined(_WIN32)
  // cmd.exe /c strips one pair of outer quotes from the whole line: wrap it in one more pair.
  return ::_popen(("\"" + command + "\"").c_str(), "wb");
#else
  std::signal(SIGPIPE, SIG_IGN);
  return ::popen(command.c_str(), "w");
#endif
}

int closeWritePipe(std::FILE* pipe) {
#if defined(_WIN32)
  return ::_pclose(pipe);
#else
  const int status = ::pclose(pipe);
  if (status == -1) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
#endif
}

}  // namespace pba::graphics
