// Random numbers that are the same on every system for a given seed. The engines of <random> are
// specified to the bit, but the distributions are not: libstdc++, libc++ and MSVC's library turn the
// same engine output into different uniform and normal samples, so a seed printed by a failing test
// on one system would not reproduce the case on another. These draw from the engine's raw output with
// one documented formula each.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "physics/core/types.h"

namespace pba::test {

/// Uniform in [0, 1): the top 53 bits of one 64-bit draw, scaled by 2^-53 (exact in a double).
inline Real unitUniform(std::mt19937_64& rng) { return static_cast<Real>(rng() >> 11) * 0x1.0p-53; }

/// Uniform in [lo, hi).
inline Real uniform(std::mt19937_64& rng, Real lo, Real hi) { return lo + (hi - lo) * unitUniform(rng); }

/// Standard normal (mean 0, deviation 1) by the Box-Muller transform of two uniform draws (the
/// first mapped to (0, 1] so that its logarithm is finite). The same sample everywhere up to the last
/// bits of the C library's log and cos.
inline Real standardNormal(std::mt19937_64& rng) {
  const Real u1 = 1.0 - unitUniform(rng), u2 = unitUniform(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace pba::test
