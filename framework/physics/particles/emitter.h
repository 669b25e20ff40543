#pragma once
// A particle emitter: spawns particles at a rate into a cone, ages them, fades their colour over life
// and removes expired ones, recycling their storage (swap-remove into a pool of fixed capacity).
#include <cstdint>
#include <random>

#include "physics/core/debug_draw.h"
#include "physics/core/result.h"
#include "physics/particles/particles.h"

namespace pba::particles {

struct EmitterDesc {
  Vec3 position{0.0, 0.2, 0.0};      ///< [m] nozzle
  Vec3 direction{0.0, 1.0, 0.0};     ///< unit, cone axis
  Real rate = 2000.0;                ///< [particles/s] > 0
  Real lifetime = 3.0;               ///< [s] > 0, mean
  Real lifetimeJitter = 0.3;         ///< [1] relative spread of the lifetime, in [0, 1)
  Real spread = degToRad(12.0);      ///< [rad] half-angle of the emission cone
  Real speed = 8.0;                  ///< [m/s] mean initial speed
  Real speedJitter = 0.1;            ///< [1] relative spread of the speed
  Real particleMass = 0.01;          ///< [kg] > 0
  std::size_t maxParticles = 20000;  ///< pool capacity
  Color startColor = colors::kBlue;
  Color endColor = colors::kOrange;
};

Status validate(const EmitterDesc& desc);

/// The emitter's colour at `age` of a particle living `lifetime` [s]: startColor blended linearly into
/// endColor over the life. Emitter::update stores it in Particles::color every step; a huge pool
/// (the fused fountain) evaluates it only for the particles it draws.
Color colorOverLife(const EmitterDesc& desc, Real age, Real lifetime);

class Emitter {
 public:
  explicit Emitter(const EmitterDesc& desc = {}, std::uint64_t seed = 1) : desc_(desc), rng_(seed) {}
  const EmitterDesc& desc() const { return desc_; }
  EmitterDesc& desc() { return desc_; }

  /// Ages every particle by h, removes the expired ones (their slots are reused), updates colours, and
  /// spawns rate·h new particles (fractions carried to the next step) while the pool has room.
  /// Returns the number spawned.
  std::size_t update(Particles& p, Real h);
  /// Only the last part of update(): spawns rate·h new particles (age 0, startColor) while the pool has
  /// room. For callers that age and remove particles themselves (particles::stepFountain).
  std::size_t spawn(Particles& p, Real h);
  /// A random unit direction inside the cone of half-angle `spread` about `axis`, uniform in solid angle.
  Vec3 sampleCone(const Vec3& axis, Real spread);

 private:
  EmitterDesc desc_;
  std::mt19937_64 rng_;
  Real carry_ = 0.0;
};

}  // namespace pba::particles
