#include "physics/particles/particles.h"

#include <cmath>

namespace pba::particles {

static_assert(sizeof(Vec3) == 3 * sizeof(Real), "flat(): Vec3 must be three packed doubles");

std::size_t Particles::add(const Vec3& x, const Vec3& v, Real m, const Color& c, Real life) {
  position.push_back(x);
  velocity.push_back(v);
  inverseMass.push_back(m > 0.0 && std::isfinite(m) ? 1.0 / m : 0.0);
  age.push_back(0.0);
  lifetime.push_back(life);
  color.push_back(c);
  return position.size() - 1;
}

void Particles::swapRemove(std::size_t i) {
  const std::size_t last = size() - 1;
  if (i != last) {
    position[i] = position[last];
    velocity[i] = velocity[last];
    inverseMass[i] = inverseMass[last];
    age[i] = age[last];
    lifetime[i] = lifetime[last];
    color[i] = color[last];
  }
  position.pop_back();
  velocity.pop_back();
  inverseMass.pop_back();
  age.pop_back();
  lifetime.pop_back();
  color.pop_back();
}

void Particles::truncate(std::size_t n) {
  position.resize(n);
  velocity.resize(n);
  inverseMass.resize(n);
  age.resize(n);
  lifetime.resize(n);
  color.resize(n);
}

void Particles::clear() { *this = Particles{}; }

void Particles::reserve(std::size_t n) {
  position.reserve(n);
  velocity.reserve(n);
  inverseMass.reserve(n);
  age.reserve(n);
  lifetime.reserve(n);
  color.reserve(n);
}

Vec3 Particles::momentum() const {
  Vec3 p(0.0);
  for (std::size_t i = 0; i < size(); ++i) {
    if (inverseMass[i] > 0.0) p += velocity[i] / inverseMass[i];
  }
  return p;
}

Real Particles::kineticEnergy() const {
  Real e = 0.0;
  for (std::size_t i = 0; i < size(); ++i) {
    if (inverseMass[i] > 0.0) e += 0.5 * glm::dot(velocity[i], velocity[i]) / inverseMass[i];
  }
  return e;
}

std::span<Real> flat(std::vector<Vec3>& v) { return {reinterpret_cast<Real*>(v.data()), 3 * v.size()}; }
std::span<const Real> flat(const std::vector<Vec3>& v) {
  return {reinterpret_cast<const Real*>(v.data()), 3 * v.size()};
}
std::span<const Vec3> asVec3(std::span<const Real> f) {
  return {reinterpret_cast<const Vec3*>(f.data()), f.size() / 3};
}
std::span<Vec3> asVec3(std::span<Real> f) { return {reinterpret_cast<Vec3*>(f.data()), f.size() / 3}; }

std::optional<std::string> describeNonFinite(const Particles& p) {
  auto what = [](const Vec3& v) { return std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z) ? "NaN" : "infinite"; };
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!isFinite(p.position[i])) return "particle " + std::to_string(i) + " position is " + what(p.position[i]);
    if (!isFinite(p.velocity[i])) return "particle " + std::to_string(i) + " velocity is " + what(p.velocity[i]);
  }
  return std::nullopt;
}

}  // namespace pba::particles
