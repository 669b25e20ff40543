#pragma once
// A uniformly distributed random rotation for tests: a normalised 4-D Gaussian sample.
#include <random>

#include "physics/core/types.h"

namespace pba::test {

inline Quat randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<Real> n(0.0, 1.0);
  return glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng)));
}

}  // namespace pba::test
