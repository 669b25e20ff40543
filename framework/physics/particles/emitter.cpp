#include "physics/particles/emitter.h"

#include <algorithm>
#include <cmath>

#include "physics/core/basis.h"
#include "physics/core/validate.h"

namespace pba::particles {

Status validate(const EmitterDesc& d) {
  for (Status s : {checkPositive("emitter.rate", d.rate), checkPositive("emitter.lifetime", d.lifetime),
                   checkRange("emitter.lifetimeJitter", d.lifetimeJitter, 0.0, 0.99),
                   checkRange("emitter.spread", d.spread, 0.0, kPi), checkRange("emitter.speed", d.speed, 0.0, 1e4),
                   checkRange("emitter.speedJitter", d.speedJitter, 0.0, 1.0),
                   checkPositive("emitter.particleMass", d.particleMass), checkFinite("emitter.position", d.position)}) {
    if (!s) return s;
  }
  if (glm::length(d.direction) < 1e-9) return Error{"emitter.direction: must not be zero"};
  return Status::success();
}

Vec3 Emitter::sampleCone(const Vec3& axis, Real spread) {
  // Uniform on the spherical cap: cos θ uniform in [cos spread, 1], φ uniform in [0, 2π).
  std::uniform_real_distribution<Real> u(0.0, 1.0);
  const Real cosTheta = 1.0 - u(rng_) * (1.0 - std::cos(spread));
  const Real sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  const Real phi = 2.0 * kPi * u(rng_);
  const Vec3 a = glm::normalize(axis);
  const Basis around = orthonormalBasis(a);
  return cosTheta * a + sinTheta * (std::cos(phi) * around.tangent + std::sin(phi) * around.bitangent);
}

Color colorOverLife(const EmitterDesc& d, Real age, Real lifetime) {
  const float s = static_cast<float>(std::clamp(age / lifetime, 0.0, 1.0));
  const Color& a = d.startColor;
  const Color& b = d.endColor;
  return Color{a.r + s * (b.r - a.r), a.g + s * (b.g - a.g), a.b + s * (b.b - a.b), a.a + s * (b.a - a.a)};
}

std::size_t Emitter::update(Particles& p, Real h) {
  for (std::size_t i = p.size(); i-- > 0;) {
    p.age[i] += h;
    if (p.age[i] >= p.lifetime[i]) {
      p.swapRemove(i);
      continue;
    }
    p.color[i] = colorOverLife(desc_, p.age[i], p.lifetime[i]);
  }
  return spawn(p, h);
}

std::size_t Emitter::spawn(Particles& p, Real h) {
  carry_ += desc_.rate * h;
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  std::size_t spawned = 0;
  while (carry_ >= 1.0) {
    carry_ -= 1.0;
    if (p.size() >= desc_.maxParticles) continue;
    const Vec3 dir = sampleCone(desc_.direction, desc_.spread);
    const Real speed = desc_.speed * (1.0 + desc_.speedJitter * u(rng_));
    const Real life = desc_.lifetime * (1.0 + desc_.lifetimeJitter * u(rng_));
    p.add(desc_.position, speed * dir, desc_.particleMass, desc_.startColor, life);
    ++spawned;
  }
  return spawned;
}

}  // namespace pba::particles
