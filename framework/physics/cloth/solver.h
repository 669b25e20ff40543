#pragma once
// One object that steps a cloth with the solver chosen by name, live (the models share the particles):
//   explicit   symplectic Euler on the mass-spring model with substeps; stable only for h < 2/ω_max
//   implicit   Baraff & Witkin 1998 backward Euler, one Newton step per step, filtered PCG (implicit.h)
//   pbd        Müller et al. 2007: distance constraints on the edges + isometric bending, stiffness per
//              iteration (its effective stiffness depends on iterations and step)
//   xpbd       Macklin et al. 2016 with compliance; substeps × iterations, Macklin et al. 2019 "Small
//              steps": many substeps of one iteration beat many iterations of one step
// Every solver ends a (sub)step with self-collision (when on), collider projection and tearing (when on).
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "physics/cloth/cloth.h"
#include "physics/cloth/colliders.h"
#include "physics/cloth/forces.h"
#include "physics/cloth/implicit.h"
#include "physics/cloth/self_collision.h"
#include "physics/cloth/tearing.h"
#include "physics/core/enum_names.h"

namespace pba::cloth {

enum class ClothSolverKind { Explicit, Implicit, Pbd, Xpbd };
inline constexpr auto kClothSolverNames = enumNames<ClothSolverKind>({{ClothSolverKind::Explicit, "explicit"},
                                                                      {ClothSolverKind::Implicit, "implicit"},
                                                                      {ClothSolverKind::Pbd, "pbd"},
                                                                      {ClothSolverKind::Xpbd, "xpbd"}});
inline constexpr std::array kAllClothSolvers = kClothSolverNames.values();
inline std::string_view solverName(ClothSolverKind kind) { return kClothSolverNames.name(kind); }
inline std::optional<ClothSolverKind> parseSolver(std::string_view name) { return kClothSolverNames.parse(name); }
inline std::vector<std::string> solverNames() { return kClothSolverNames.names(); }
/// True for the mass-spring solvers (explicit, implicit), false for the constraint ones.
bool usesSprings(ClothSolverKind kind);

/// Bending of the constraint solvers (the spring solvers bend through their bend springs).
enum class BendingModel {
  Isometric,  ///< Bergou et al. 2006 as one linear vector constraint per inner edge (xpbd.h)
  Distance,   ///< TMP #14–15: the opposite vertices of every inner edge keep their rest distance (compliant)
  None,
};
inline constexpr auto kBendingModelNames = enumNames<BendingModel>(
    {{BendingModel::Isometric, "isometric"}, {BendingModel::Distance, "distance"}, {BendingModel::None, "none"}});

struct ClothSolverSettings {
  ClothSolverKind kind = ClothSolverKind::Xpbd;
  int substeps = 10;                               ///< per step: symplectic Euler / PBD / XPBD substeps, implicit steps
  int iterations = 1;                              ///< PBD/XPBD constraint sweeps per substep
  Real pbdStiffness = 1.0;                         ///< PBD stretch stiffness s ∈ (0, 1] per projection
  Real pbdBendStiffness = 0.05;                    ///< PBD bending stiffness ∈ [0, 1] per projection
  BendingModel bending = BendingModel::Isometric;  ///< PBD/XPBD
  ImplicitSettings implicit;
  bool selfCollision = false;
  Real selfFriction = 0.1;  ///< TMP #15 velocity averaging ∈ [0, 1]
  /// TMP #15's speed limit with self-collision: at most this many thicknesses per substep (0 = none).
  /// It bounds how far a particle travels in a frame, so the pair list of the frame stays complete.
  Real selfCollisionMaxTravel = 0.2;
  /// Gauss–Seidel sweeps over the self-collision pairs per substep (TMP: 1). From the second on (ours), each
  /// follows a frictionless collider pass and visits only the pairs the first found in contact.
  int selfCollisionSweeps = 1;
  /// Sweep a Verlet list of the pairs near contact, checked before every sweep (self_collision.h: every
  /// pair touching at a sweep's start is swept; ours). false: TMP's published form, the pairs within the
  /// frame's travel swept in TMP's order in every substep.
  bool selfCollisionNearList = true;
  TearSettings tearing;
  /// [m/s] A safety limit, not part of any published method: a particle faster than this (or not finite)
  /// means the solver has diverged (symplectic Euler above its stability limit grows without bound). The
  /// step then stops at once: the explicit substeps stop at the first substep that diverges, and a step
  /// that starts from a diverged state does nothing. It bounds the cost of a blow-up (the self-collision
  /// search of a frame grows with the speeds; one frame of the ribbon took 80 s) until the lab's guard
  /// pauses. 0 turns the check off. No cloth in the labs comes near it (a free fall from 10 m: 14 m/s).
  Real divergedSpeed = 1000.0;
  /// Explicit only (ours, not part of symplectic Euler): when > 0, each substep is at most this fraction
  /// of the stability limit 2/ω_max (explicitStabilityLimit), taking more substeps than `substeps` where
  /// needed (at most kMaxStableSubsteps). 0: exactly `substeps`, the published method, which grows without
  /// bound above the limit. The lab turns it on so that switching to explicit keeps the scene running.
  Real explicitLimitFraction = 0.0;
  /// PBD/XPBD: long range attachments (Kim, Chentanez & Müller 2012): after the constraint sweeps, every free
  /// particle farther from a pinned particle than their rest distance is moved back onto that distance
  /// (unilateral). One sweep of Gauss–Seidel cannot carry a hanging cloth's weight up to its pins, so the
  /// edges at the pins stretch by tens of per cent; these bound that stretch. The rest distance is the
  /// straight one, the geodesic of a flat cloth (shorter than it for a curved rest shape). Not with tearing
  /// (a tear changes the geodesics). false: the published PBD/XPBD.
  bool longRangeAttachments = false;
};
/// The most substeps explicitLimitFraction may ask for in one step (k = 10⁶ N/m at 60 steps/s needs ~2,000).
inline constexpr int kMaxStableSubsteps = 4000;
Status validate(const ClothSolverSettings& s);

struct ClothStepStats {
  int cgIterations = 0;          ///< implicit: CG iterations of the last step
  Real cgResidual = 0.0;         ///< implicit: relative residual of the last solve
  int constraintIterations = 0;  ///< PBD/XPBD: sweeps per step (substeps × iterations)
  std::size_t contacts = 0;      ///< particle–collider contacts in the last (sub)step
  std::size_t selfContacts = 0;  ///< self-collision pairs separated in the last (sub)step
  std::size_t tears = 0;         ///< vertex splits this step
  int substepsPlanned = 0;       ///< substeps this step was split into (explicitLimitFraction may add some)
  int substepsTaken = 0;         ///< substeps done this step (fewer than planned when it diverged)
  bool diverged = false;         ///< a particle passed ClothSolverSettings::divergedSpeed (or is not finite)
  int implicitRetries = 0;       ///< implicit steps discarded by the step control and retried at half size
};

/// Stretch (l − L)/L of the mesh edges, the same measure for every model: largest and mean over the
/// edges (compressed edges count 0), and the largest compression (L − l)/L apart (cloth buckles rather than
/// compresses, so compression is the constraints' error, not the fabric's stretch).
struct StrainStats {
  Real max = 0.0, mean = 0.0, maxCompression = 0.0;
};
StrainStats edgeStrain(const Cloth& cloth);
/// Kinetic + gravitational + elastic energy [J]; the elastic part is the springs' for the mass-spring
/// solvers and ½ C²/α of the compliant constraints for PBD/XPBD.
Real clothEnergy(const Cloth& cloth, const ClothEnvironment& env, ClothSolverKind kind,
                 BendingModel bending = BendingModel::Isometric);
/// Upper bound of the highest angular frequency of the spring network (Gershgorin: ω² ≤ max_i Σ 2k/m_i)
/// and the explicit stability limit 2/ω it implies [s].
Real explicitStabilityLimit(const Cloth& cloth);
/// Substeps that split dt into steps of at most `fraction` of explicitStabilityLimit (at least 1, at most
/// kMaxStableSubsteps).
int stableExplicitSubsteps(const Cloth& cloth, Real dt, Real fraction);

class ClothSolver {
 public:
  /// Advances the cloth by dt [s] from time t [s].
  ClothStepStats step(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                      const ClothSolverSettings& settings, Real dt, Real t);
  /// Forgets what the solver remembers between steps (after a reset, a teleport or tearing).
  void reset();
  const SelfCollision& selfCollision() const { return self_; }

 private:
  void explicitSubstep(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                       const ClothSolverSettings& s, Real h, Real t, Real pinFraction, ClothStepStats& stats);
  void positionBasedSubstep(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                            const ClothSolverSettings& s, Real h, Real t, Real pinFraction, ClothStepStats& stats);
  void solveConstraints(Cloth& cloth, const ClothSolverSettings& s, Real h);
  void attachToPins(Cloth& cloth) const;
  void endSubstep(Cloth& cloth, std::span<const Collider> colliders, const ClothSolverSettings& s, Real h,
                  bool velocityLevel, ClothStepStats& stats);
  /// Where pin k is due at `fraction` of the step: on the straight path from where it began the step
  /// (pinStart_) to its target.
  Vec3 pinOnItsPath(const Cloth& cloth, std::size_t k, Real fraction) const;
  void movePins(Cloth& cloth, Real fraction);
  /// Implicit steps over [from, to] of the step (pin fractions) from time t, of size h, halved while the
  /// step control rejects them (ImplicitSettings::maxStrainGrowth).
  void implicitSpan(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                    const ClothSolverSettings& s, Real t, Real h, Real from, Real to, int halvings,
                    ClothStepStats& stats);
  void beginSelfCollision(Cloth& cloth, const ClothSolverSettings& s, Real dt);

  ImplicitWorkspace implicit_;
  SelfCollision self_;
  std::vector<Vec3> previous_, force_, beforeSelf_, pinStart_, savedVelocity_;
  std::vector<char> savedReleased_, savedSticking_;  ///< contact memory before a step the control may discard
  std::vector<Real> lambda_, bendLinkLambda_;
  std::vector<Vec3> bendLambda_;
};

}  // namespace pba::cloth
