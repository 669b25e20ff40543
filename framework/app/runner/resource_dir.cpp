// The one translation unit that sees PBA_RESOURCE_DIR (framework/app/CMakeLists.txt): every other compile command is
// then the same in any copy of the tree, so the compiler cache serves the copies that the exercise checks build
// (docs/decisions/2026-12-02-build-time-is-ci-time.md).
#include "app/runner/resource_dir.h"

#include <cstdlib>
#include <filesystem>

#include "app/runner/host_system.h"

namespace pba::app {
namespace {

namespace fs = std::filesystem;

/// A resources folder is one that holds the shaders (every lab needs them to draw).
bool isResourceDir(const fs::path& dir) {
  std::error_code ec;
  return !dir.empty() && fs::is_directory(dir / "shaders", ec);
}

std::string findResourceDir() {
  if (const char* over = std::getenv("PBA_RESOURCE_DIR"); over && *over && isResourceDir(over)) return over;
  const fs::path exe = executablePath();
  if (!exe.empty()) {
    const fs::path bin = exe.parent_path();
    for (const fs::path& candidate : {bin / "resources", bin.parent_path() / "share" / "pba-labs" / "resources"})
      if (isResourceDir(candidate)) return candidate.lexically_normal().string();
  }
  return PBA_RESOURCE_DIR;
}

}  // namespace

const std::string& resourceDir() {
  static const std::string dir = findResourceDir();
  return dir;
}

std::string repositoryRoot() { return fs::path(resourceDir()).parent_path().string(); }

std::string resolveRepositoryPath(const std::string& path) {
  std::error_code ec;
  if (path.empty() || fs::path(path).is_absolute() || fs::exists(path, ec)) return path;
  const fs::path fromRoot = fs::path(repositoryRoot()) / path;
  return fs::exists(fromRoot, ec) ? fromRoot.string() : path;
}

}  // namespace pba::app
