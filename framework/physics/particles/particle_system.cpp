#include "physics/particles/particle_system.h"

#include <algorithm>
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

namespace {
// Pinned particles feel nothing (their inverse mass is 0 anyway; zeroing keeps the reported force clean).
void zeroPinned(std::span<const Real> inverseMass, std::span<Vec3> f) {
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (inverseMass[i] <= 0.0) f[i] = Vec3(0.0);
  }
}
}  // namespace

void ParticleSystem::force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const {
  assert(dofInverseMass_.size() == q.size() && "call syncMasses() after changing the particles");
  std::fill(out.begin(), out.end(), 0.0);
  const std::span<const Vec3> x = asVec3(q), vel = asVec3(v);
  const std::span<Vec3> f = asVec3(out);
  accumulateFieldForces(forces, t, x, vel, particles.inverseMass, f);
  springs::accumulateSpringForces(springs, x, vel, f);
  zeroPinned(particles.inverseMass, f);
}

void ParticleSystem::forceDifferential(Real t, std::span<const Real> q, std::span<const Real> v,
                                       std::span<const Real> dq, std::span<const Real> dv, std::span<Real> out) {
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
  std::fill(f.begin(), f.end(), 0.0);
  accumulateFieldForces(forces, t, x, vel, w, asVec3(f));
  zeroPinned(w, asVec3(f));
  // The blocks are column-major like glm's Mat3: the drag's blocks are written in place.
  std::fill(dfdq.begin(), dfdq.end(), 0.0);
  std::fill(dfdv.begin(), dfdv.end(), 0.0);
  accumulateDragJacobianDiagonal(forces, t, x, vel, w, {reinterpret_cast<Mat3*>(dfdv.data()), count});
}

}  // namespace pba::particles
