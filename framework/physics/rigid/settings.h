#pragma once
// Every knob of the rigid-body world in one place (docs/architecture.md §2: a description apart from the runtime
// object; the lab's panel edits these). Defaults follow Box2D v3 (b2DefaultWorldDef) where it has the
// same setting.
#include <string>
#include <vector>

#include "physics/collision/broad_phase.h"
#include "physics/core/enum_names.h"
#include "physics/core/types.h"

namespace pba::rigid {

/// How penetration is removed (Catto, "Solver2D", 2024, compares them):
///  Soft      soft constraints (b2MakeSoft: a spring of `contactHertz` and `contactDampingRatio`) with
///            relax iterations after the position update: Box2D v3's "soft step" (the default).
///  Baumgarte velocity bias β/h · (penetration − slop) in every iteration (Catto GDC 2006, Bullet).
///  None      no position correction (drift shows what the bias is for).
enum class PositionCorrection { Soft, Baumgarte, None };
/// Friction as two independent tangent directions clamped each to ±μλ_n (a pyramid, Bullet's default),
/// or the 2-D tangent impulse clamped to the disk |λ_t| ≤ μλ_n (the Coulomb cone).
enum class FrictionModel { Cone, Pyramid };
/// Gyroscopic term ω × Iω of Euler's equations:
///  Off       ω stays constant in free flight (what Box2D and many games do: stable, but a free body
///            never shows the intermediate-axis flip and |L| is not conserved);
///  Implicit  Catto, "Numerical Methods", GDC 2015: one Newton step of backward Euler in the body frame
///            (stable at large ω, slowly dissipates energy and |L|);
///  Midpoint  implicit midpoint rule on L̇ = L × I⁻¹L in the body frame with the orientation advanced by
///            the same Cayley rotation, which conserves L exactly and the energy up to the solve's
///            tolerance (the conservative choice of the `spinning` scene; see
///            docs/decisions/2026-12-01-rigid-bodies-as-box2d-v3-in-3d.md).
enum class GyroscopicMode { Off, Implicit, Midpoint };

inline constexpr auto kPositionCorrectionNames =
    enumNames<PositionCorrection>({{PositionCorrection::Soft, "soft"},
                                   {PositionCorrection::Baumgarte, "baumgarte"},
                                   {PositionCorrection::None, "none"}});
inline constexpr auto kFrictionModelNames =
    enumNames<FrictionModel>({{FrictionModel::Cone, "cone"}, {FrictionModel::Pyramid, "pyramid"}});
inline constexpr auto kGyroscopicModeNames = enumNames<GyroscopicMode>(
    {{GyroscopicMode::Off, "off"}, {GyroscopicMode::Implicit, "implicit"}, {GyroscopicMode::Midpoint, "midpoint"}});
inline std::vector<std::string> positionCorrectionNames() { return kPositionCorrectionNames.names(); }
inline std::vector<std::string> frictionModelNames() { return kFrictionModelNames.names(); }
inline std::vector<std::string> gyroscopicModeNames() { return kGyroscopicModeNames.names(); }

struct WorldSettings {
  Vec3 gravity{0.0, -kStandardGravity, 0.0};  ///< [m/s²]
  int substeps = 4;                           ///< per step (Box2D v3 default 4); each solves then relaxes
  int iterations = 1;                         ///< velocity iterations per substep (with bias)
  int relaxIterations = 1;                    ///< per substep, without bias (Soft only)
  bool warmStarting = true;                   ///< start from last step's impulses (matched by feature id)
  PositionCorrection positionCorrection = PositionCorrection::Soft;
  FrictionModel friction = FrictionModel::Cone;
  GyroscopicMode gyroscopic = GyroscopicMode::Implicit;
  Real contactHertz = 30.0;         ///< [Hz] contact stiffness (capped at a quarter of the substep rate)
  Real contactDampingRatio = 10.0;  ///< contact damping ratio ζ (heavily over-damped, no bounce)
  Real jointHertz = 120.0;          ///< [Hz] joint stiffness (Box2D 60; 120 holds a 10-link chain within 1 mm)
  Real jointDampingRatio = 2.0;
  Real contactPushSpeed = 3.0;      ///< [m/s] the fastest a soft contact pushes bodies apart
  Real baumgarte = 0.2;             ///< β of the Baumgarte bias
  Real linearSlop = 0.005;          ///< [m] penetration allowed without correction
  Real speculativeDistance = 0.02;  ///< [m] contact points are made this far before touching
  Real restitutionThreshold = 1.0;  ///< [m/s] slower impacts do not bounce
  /// Passes of the restitution stage (Box2D: 1). More let a bounce travel along a row of touching bodies
  /// (Newton's cradle) instead of being shared out.
  int restitutionIterations = 1;
  Real aabbMargin = 0.1;  ///< [m] broad-phase fattening
  /// Contact cache (Jolt's body-pair cache): a pair whose relative pose moved less than these since its
  /// manifold was made keeps that manifold (moved with the bodies) instead of running the narrow phase.
  /// 0 turns the cache off.
  Real contactCacheDistance = 1e-3;  ///< [m]
  Real contactCacheAngle = 0.035;    ///< [rad] (2°)
  collision::BroadPhaseKind broadPhase = collision::BroadPhaseKind::Tree;
  bool continuous = true;  ///< time of impact against static bodies for fast bodies (and bullets)
  bool sleeping = true;
  Real sleepLinearSpeed = 0.05;   ///< [m/s] below this (and the angular bound) a body may sleep
  Real sleepAngularSpeed = 0.05;  ///< [rad/s]
  Real timeToSleep = 0.5;         ///< [s] an island sleeps when all its bodies were slow this long
  Real maxLinearSpeed = 400.0;    ///< [m/s] clamp (Box2D's b2_huge guard against explosions)
};

}  // namespace pba::rigid
