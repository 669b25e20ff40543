// Where the labs find their resources (shaders, scene files, the exercise catalog): the repository's
// resources/ folder, fixed at configure time.
#pragma once

#include <string>

namespace pba::app {

/// The absolute path of the repository's resources/ folder, without a trailing slash.
const std::string& resourceDir();

/// The repository root: the folder above resourceDir().
std::string repositoryRoot();

/// A file named on the command line or in a scene: the path as given when it exists (or is absolute or
/// empty), else relative to the repository root ("resources/models/humanoid.bvh" from any directory).
std::string resolveRepositoryPath(const std::string& path);

}  // namespace pba::app
