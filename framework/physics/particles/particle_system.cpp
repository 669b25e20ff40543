#include "physics/particles/particle_system.h"

#include <algorithm>
#include <array>
#include <cassert>

namespace pba::particles {

void ParticleSystem::syncMasses() {
  dofInverseMass_.resize(3 * particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k) dofInverseMass_[3 * i + k] = particles.inverseMass[i];
  }
}

Real ParticleSystem::energy() const {
  return particles.kineticEnergy() + fieldPotentialEnergy(forces, particles.position, particles.inverseMass) +
         springs::springPotentialEnergy(springs, particles.position);
}

void ParticleSystem::force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const {
  assert(dofInverseMass_.size() == q.size() && "call syncMasses() after changing the particles");
  std::fill(out.begin(), out.end(), 0.0);
  const std::span<const Vec3> x = asVec3(q), vel = asVec3(v);
  const std::span<Vec3> f = asVec3(out);
  accumulateFieldForces(forces, t, x, vel, particles.inverseMass, f);
  springs::accumulateSpringForces(springs, x, vel, f);
  // Pinned particles feel nothing (their inverse mass is 0 anyway; zeroing keeps the reported force clean).
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.inverseMass[i] <= 0.0) f[i] = Vec3(0.0);
  }
}

void ParticleSystem::forceDifferential(Real t, std::span<const Real> q, std::span<const Real> v,
                                       std::span<const Real> dq, std::span<const Real> dv, std::span<Real> out) const {
  std::fill(out.begin(), out.end(), 0.0);
  const std::span<Vec3> df = asVec3(out);
  springs::accumulateSpringDifferential(springs, asVec3(q), asVec3(dq), asVec3(dv), df);
  accumulateDragDifferential(forces, t, asVec3(q), asVec3(v), particles.inverseMass, asVec3(dv), df);
}

bool ParticleSystem::forceJacobianDiagonalBlocks(Real t, std::span<const Real> q, std::span<const Real> v,
                                                 std::span<Mat3> dfdq, std::span<Mat3> dfdv) const {
  std::fill(dfdq.begin(), dfdq.end(), Mat3(0.0));
  std::fill(dfdv.begin(), dfdv.end(), Mat3(0.0));
  springs::accumulateSpringJacobianDiagonal(springs, asVec3(q), dfdq, dfdv);
  accumulateDragJacobianDiagonal(forces, t, asVec3(q), asVec3(v), particles.inverseMass, dfdv);
  return true;
}

void ParticleSystem::uncoupledForce(Real t, std::span<const Real> q, std::span<const Real> v, std::size_t first,
                                    std::span<Real> f, std::span<Real> dfdq, std::span<Real> dfdv) const {
  assert(springs.empty() && first % 3 == 0 && f.size() % 3 == 0);
  const std::size_t p0 = first / 3, count = f.size() / 3;
  const std::span<const Vec3> x = asVec3(q).subspan(p0, count), vel = asVec3(v).subspan(p0, count);
  const std::span<const Real> w = std::span<const Real>(particles.inverseMass).subspan(p0, count);
  const std::span<Vec3> force = asVec3(f);
  std::fill(f.begin(), f.end(), 0.0);
  accumulateFieldForces(forces, t, x, vel, w, force);
  std::fill(dfdq.begin(), dfdq.end(), 0.0);
  std::fill(dfdv.begin(), dfdv.end(), 0.0);
  constexpr std::size_t kBatch = 64;  // drag blocks made a batch at a time on the stack
  std::array<Mat3, kBatch> blocks;
  for (std::size_t b0 = 0; b0 < count; b0 += kBatch) {
    const std::size_t n = std::min(kBatch, count - b0);
    const std::span<Mat3> part = std::span<Mat3>(blocks).first(n);
    std::fill(part.begin(), part.end(), Mat3(0.0));
    accumulateDragJacobianDiagonal(forces, t, x.subspan(b0, n), vel.subspan(b0, n), w.subspan(b0, n), part);
    for (std::size_t i = 0; i < n; ++i) {
      Real* out = dfdv.data() + 9 * (b0 + i);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out[3 * r + c] = part[i][c][r];  // glm: [column][row]
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (w[i] <= 0.0) force[i] = Vec3(0.0);
  }
}

}  // namespace pba::particles
