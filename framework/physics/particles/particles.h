#pragma once
// Particles as a structure of arrays (docs/architecture.md §2): one array per field, so that a kernel touching
// positions and velocities streams exactly those. A particle is {m, x, v} (Lobb notes, "Particle");
// inverse mass 0 marks a pinned particle (it ignores forces; kinematic when moved by hand).
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "physics/core/debug_draw.h"
#include "physics/core/types.h"

namespace pba::particles {

/// Lifetime of a particle that never expires [s].
inline constexpr Real kImmortal = 1e300;

struct Particles {
  std::vector<Vec3> position;     ///< [m] world, typical −10…10
  std::vector<Vec3> velocity;     ///< [m/s] world
  std::vector<Real> inverseMass;  ///< [1/kg]; 0 = pinned; typical 1–1000
  std::vector<Real> age;          ///< [s] since birth
  std::vector<Real> lifetime;     ///< [s]; kImmortal for permanent particles
  std::vector<Color> color;       ///< display colour (emitters fade it over life)

  std::size_t size() const { return position.size(); }
  bool empty() const { return position.empty(); }
  /// Appends a particle; mass ≤ 0 or infinite pins it. Returns its index.
  std::size_t add(const Vec3& x, const Vec3& v, Real mass, const Color& c = colors::kBlue, Real life = kImmortal);
  /// Removes particle i by moving the last one into its slot (O(1), order not kept: storage is recycled).
  void swapRemove(std::size_t i);
  /// Keeps the first n particles (n ≤ size()); the storage stays allocated.
  void truncate(std::size_t n);
  void clear();
  void reserve(std::size_t n);
  Real mass(std::size_t i) const { return inverseMass[i] > 0.0 ? 1.0 / inverseMass[i] : 0.0; }

  /// Sum of m v over free particles [kg·m/s] and of ½ m |v|² [J].
  Vec3 momentum() const;
  Real kineticEnergy() const;
};

/// Flat views of a Vec3 array as 3n reals (glm::dvec3 is three packed doubles).
std::span<Real> flat(std::vector<Vec3>& v);
std::span<const Real> flat(const std::vector<Vec3>& v);
std::span<const Vec3> asVec3(std::span<const Real> flatValues);
std::span<Vec3> asVec3(std::span<Real> flatValues);

/// "particle 17 position is NaN" for the first particle whose state is not finite; nothing otherwise.
std::optional<std::string> describeNonFinite(const Particles& p);

}  // namespace pba::particles
