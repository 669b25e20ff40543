#pragma once
// CLOTH-5's fast path (docs/architecture.md §5, "Fast paths"): the product with the implicit system
// matrix A = M − h D − h² K (implicit.h) and the block-Jacobi preconditioner built from it, as the
// implicit solver calls them once per PCG iteration and once per step. The student's route is
// implicitSystemProduct (CLOTH-5) and the probed preconditioner (pcg.h), which applies that product
// 3 × colours times; the reference build's route works out the per-spring factors of each step once
// and reads the diagonal blocks off them. The product gives the scalar route's results to the bit
// (the same operations in the same order), the preconditioner agrees to rounding
// (tests/physics/cloth/cloth_implicit_fast_path_test.cpp). In the hand-out both run the scalar route.
#include <cstdint>
#include <span>
#include <vector>

#include "physics/cloth/forces.h"
#include "physics/cloth/pcg.h"

namespace pba::cloth {

/// The system of one implicit step: the inputs of implicitSystemProduct, plus what the fast route
/// works out from them once per step.
struct ImplicitSystem {
  std::span<const SpringJacobian> springs;
  std::span<const Real> mass;
  Real massDamping = 0.0;  ///< c [1/s]
  Real h = 0.0;            ///< step [s]

  /// Points the system at a step's inputs (they must outlive its use); prepareImplicitSystemFast next.
  void bind(std::span<const SpringJacobian> springs_, std::span<const Real> mass_, Real massDamping_, Real h_);

  // Fast route only (prepareImplicitSystemFast): one entry per spring (its two ends and factors) and per
  // particle (its mass term).
  struct Coupling {
    std::uint32_t i = 0, j = 0;
    Real lateral = 0.0, axial = 0.0;
    Vec3 n{0.0};
  };
  std::vector<Coupling> couplings;
  std::vector<Real> diagonal;
};

/// Works out the fast route's factors of a bound system (once per step, before the two below).
void prepareImplicitSystemFast(ImplicitSystem& system);

/// out = A y, as implicitSystemProduct(system.springs, system.mass, system.massDamping, system.h, y, out).
void implicitSystemProductFast(const ImplicitSystem& system, std::span<const Vec3> y, std::span<Vec3> out);

/// P⁻¹: the inverses of A's 3 × 3 diagonal blocks (the identity where one is not invertible), as
/// probedBlockJacobi(A, colour, colours, …) returns them for A the system's product.
void implicitBlockJacobiFast(const ImplicitSystem& system, const ParticleOperator& A,
                             std::span<const std::uint32_t> colour, std::uint32_t colours, std::vector<Mat3>& inverse,
                             std::vector<Vec3>& scratchIn, std::vector<Vec3>& scratchOut);

}  // namespace pba::cloth
