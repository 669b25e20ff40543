// Where the labs find their resources (shaders, the UI font, models, scene files, the exercise catalog).
// A lab looks, in order: in $PBA_RESOURCE_DIR; in a resources/ folder next to its executable; in
// <prefix>/share/pba-labs/resources above a <prefix>/bin executable (what `cmake --install` lays out); and
// last in the source tree's resources/ folder, fixed at configure time (a build that has not moved).
#pragma once

#include <string>

namespace pba::app {

/// The path of the resources/ folder the labs use, without a trailing slash.
const std::string& resourceDir();

/// The folder above resourceDir(): the repository root in a build tree, share/pba-labs when installed.
std::string repositoryRoot();

/// A file named on the command line or in a scene: the path as given when it exists (or is absolute or
/// empty), else relative to the repository root ("resources/models/humanoid.bvh" from any directory).
std::string resolveRepositoryPath(const std::string& path);

}  // namespace pba::app
