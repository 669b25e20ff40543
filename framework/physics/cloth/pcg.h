#pragma once
// The modified (filtered) preconditioned conjugate gradient of Baraff & Witkin 1998, §5.3, on systems
// A x = b over particles (3 unknowns each), with a constraint per particle:
//   S_i = I           free
//   S_i = I − p pᵀ    one direction p prescribed (a contact normal)
//   S_i = I − p pᵀ − q qᵀ  two directions prescribed (only p × q is free)
//   S_i = 0           fixed (a pin)
// The prescribed part of x_i is (I − S_i) z_i. Every residual and search direction is filtered by S,
// so the solve never moves a prescribed component and solves A x = b on the free ones:
//   x = S x₀ + (I − S) z;  r = S (b − A x);  c = S P⁻¹ r;  δ = rᵀ c;  δ₀ = (S b)ᵀ P⁻¹ (S b)
//   while δ > ε² δ₀:  q = S A c;  α = δ / cᵀq;  x += α c;  r −= α q;  s = P⁻¹ r;  δ' = rᵀs;  c = S(s + (δ'/δ) c)
// (The paper prints δ₀ = (Sb)ᵀ P (Sb) with P its diagonal preconditioner; the P⁻¹ used here makes the test
// δ ≤ ε² δ₀ compare like with like, as Ascher & Boxerman 2003 note.) A must be symmetric positive definite
// on the free subspace. P⁻¹ is block-diagonal: one 3 × 3 matrix per particle.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "physics/core/types.h"

namespace pba::cloth {

/// The constraint S_i of one particle (see the header).
struct ParticleFilter {
  enum class Kind : std::uint8_t { Free, OneDirection, TwoDirections, Fixed };
  Kind kind = Kind::Free;
  Vec3 p{0.0}, q{0.0};  ///< unit, orthogonal: the prescribed directions
};
/// S y for one particle.
Vec3 applyFilter(const ParticleFilter& f, const Vec3& y);

/// y ↦ A y on particle vectors (A symmetric).
using ParticleOperator = std::function<void(std::span<const Vec3> y, std::span<Vec3> out)>;

struct PcgSettings {
  int maxIterations = 500;
  /// ε: stop when rᵀP⁻¹r ≤ ε² (Sb)ᵀP⁻¹(Sb). One Newton step is itself an approximation, so a loose
  /// tolerance is the usual choice: a tighter one costs iterations without changing the strain or the
  /// energy of the step (docs/performance-cloth.md).
  Real tolerance = 1e-3;
};
struct PcgStats {
  int iterations = 0;
  Real relativeResidual = 0.0;  ///< |S(b − A x)| / |S b| at the end (0 when S b = 0)
  bool converged = false;
};
struct PcgWorkspace {
  std::vector<Vec3> r, c, q, s;
};

/// Solves A x = b with the filter; x holds the initial guess on entry (its free part; the prescribed part
/// is overwritten with (I − S) z). An empty preconditioner means P = I.
PcgStats filteredPcg(const ParticleOperator& A, std::span<const Vec3> b, std::span<const ParticleFilter> filter,
                     std::span<const Vec3> z, std::span<const Mat3> preconditionerInverse, const PcgSettings& settings,
                     std::span<Vec3> x, PcgWorkspace& w);

/// A greedy colouring of particles such that the two ends of every pair get different colours; returns
/// the colour of each particle (colours 0…count−1).
std::vector<std::uint32_t> colourParticles(std::size_t particles,
                                           std::span<const std::pair<std::uint32_t, std::uint32_t>> pairs,
                                           std::uint32_t* count);
/// Block-Jacobi preconditioner read off the operator itself (Curtis, Powell & Reid 1974): for a colouring
/// in which no two coupled particles share a colour, A applied to the unit vectors of one axis on all
/// particles of one colour returns, on each of them, one column of its own diagonal block. 3 × colours
/// products give every block; blocks that are not invertible become the identity. Returns P⁻¹.
void probedBlockJacobi(const ParticleOperator& A, std::span<const std::uint32_t> colour, std::uint32_t colours,
                       std::vector<Mat3>& inverse, std::vector<Vec3>& scratchIn, std::vector<Vec3>& scratchOut);

/// Inverts each block in place; one that is not invertible (or not finite) becomes the identity.
void invertBlocksOrIdentity(std::span<Mat3> blocks);

}  // namespace pba::cloth
