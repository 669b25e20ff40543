// A colour palette (sRGB, alpha 1) chosen to stay distinct and saturated on a light background and on
// a washed-out projector. Use these rather than ad-hoc RGB triples so that labs look alike.
#pragma once

#include <glm/vec4.hpp>

namespace pba::graphics::colors {

inline const glm::vec4 kRed{0.86f, 0.20f, 0.18f, 1.0f};
inline const glm::vec4 kGreen{0.20f, 0.62f, 0.24f, 1.0f};
inline const glm::vec4 kBlue{0.16f, 0.40f, 0.86f, 1.0f};
inline const glm::vec4 kOrange{0.96f, 0.55f, 0.12f, 1.0f};
inline const glm::vec4 kYellow{0.96f, 0.80f, 0.16f, 1.0f};
inline const glm::vec4 kPurple{0.56f, 0.30f, 0.78f, 1.0f};
inline const glm::vec4 kTeal{0.10f, 0.62f, 0.64f, 1.0f};
inline const glm::vec4 kPink{0.92f, 0.40f, 0.62f, 1.0f};
inline const glm::vec4 kGrey{0.55f, 0.57f, 0.60f, 1.0f};
inline const glm::vec4 kDark{0.16f, 0.18f, 0.22f, 1.0f};
inline const glm::vec4 kWhite{0.96f, 0.96f, 0.96f, 1.0f};

/// The i-th colour of a cycling categorical palette (bodies, particles, chains).
inline glm::vec4 categorical(int i) {
  static const glm::vec4 palette[] = {kBlue, kOrange, kGreen, kRed, kPurple, kTeal, kYellow, kPink};
  const int n = static_cast<int>(sizeof(palette) / sizeof(palette[0]));
  return palette[((i % n) + n) % n];
}

}  // namespace pba::graphics::colors
