// Fuzz target: the model loader (graphics/model.h: Assimp import through our validation). The first
// byte picks the file's extension, so one corpus reaches every reader; the rest is the file. Besides
// no sanitizer report: an error is one line starting with the path; a model that loads has finite
// rest transforms and triangles that index its vertices (what the labs rely on).
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include "fuzz_check.h"
#include "graphics/model.h"
#include "graphics/skinning.h"

using namespace pba;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string ext(graphics::kModelExtensions[data[0] % graphics::kModelExtensions.size()]);
  const std::string path = fuzz::writeInput(data + 1, size - 1, ext);
  std::string error;
  const std::optional<graphics::Model> model = graphics::loadModel(path, &error);
  std::filesystem::remove(path);
  if (!model) {
    fuzz::requireOneLineNaming(error, path + ": ");
    return 0;
  }
  for (const graphics::ModelMesh& m : model->meshes)
    for (const std::uint32_t i : m.indices) fuzz::require(i < m.positions.size(), "triangles index their mesh", path);
  for (const glm::mat4& g : graphics::globalTransforms(*model, graphics::restPose(*model)))
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) fuzz::require(std::isfinite(g[c][r]), "rest transforms are finite", path);
  return 0;
}
