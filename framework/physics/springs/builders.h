#pragma once
// Scene builders for mass-spring systems (docs/architecture.md §1: used by the lab, the tests and the benchmarks).
// Each takes a description with documented defaults, validates it and appends particles and springs to
// a ParticleSystem (so a scene can hold a rope and a chain side by side).
#include "physics/core/result.h"
#include "physics/particles/particle_system.h"

namespace pba::springs {

/// A rope or chain of `segments` springs from `start` to `end` (straight at rest length).
/// A chain is a rope with heavier, stiffer links; `bending` adds springs that skip one particle,
/// which resist folding (a stiff cable rather than a string).
struct RopeDesc {
  Vec3 start{0.0, 3.0, 0.0};   ///< [m] first particle
  Vec3 end{2.0, 3.0, 0.0};     ///< [m] last particle at rest
  int segments = 20;           ///< ≥ 1
  Real mass = 1.0;             ///< [kg] total, shared equally by the particles
  Real stiffness = 2000.0;     ///< [N/m] per segment
  Real damping = 2.0;          ///< [N·s/m] per segment, along the spring
  bool bending = false;
  bool pinStart = true;
  bool pinEnd = false;
};
Status validate(const RopeDesc& desc);
/// Appends the rope; returns the index of its first particle.
Result<std::size_t> appendRope(const RopeDesc& desc, particles::ParticleSystem& system);

/// A soft blob: particles on a sphere (Fibonacci lattice) plus one centre particle; surface springs to
/// the nearest neighbours and radial springs to the centre.
struct BlobDesc {
  Vec3 center{0.0, 2.0, 0.0};  ///< [m]
  Real radius = 0.5;           ///< [m] > 0
  int surfaceParticles = 48;   ///< ≥ 8
  int neighbours = 5;          ///< surface springs per particle (to the nearest ones)
  Real mass = 1.0;             ///< [kg] total
  Real stiffness = 300.0;      ///< [N/m]
  Real damping = 1.0;          ///< [N·s/m]
};
Status validate(const BlobDesc& desc);
Result<std::size_t> appendBlob(const BlobDesc& desc, particles::ParticleSystem& system);

/// A box lattice nx × ny × nz with structural springs along the axes and, optionally, shear springs
/// along the face and body diagonals.
struct LatticeDesc {
  Vec3 origin{-0.5, 1.0, -0.5};  ///< [m] corner
  int nx = 6, ny = 6, nz = 6;    ///< particles per axis, ≥ 2
  Real spacing = 0.2;            ///< [m] > 0
  Real particleMass = 0.01;      ///< [kg] > 0
  Real stiffness = 500.0;        ///< [N/m]
  Real damping = 0.5;            ///< [N·s/m]
  bool shear = true;
  bool pinTopLayer = false;
};
Status validate(const LatticeDesc& desc);
Result<std::size_t> appendLattice(const LatticeDesc& desc, particles::ParticleSystem& system);

}  // namespace pba::springs
