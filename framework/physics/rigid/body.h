#pragma once
// Rigid bodies: a description (what the UI edits and scene files store) apart from the runtime body the
// world steps (Jolt's BodyCreationSettings / Body). The body's origin is its centre of mass; its shape
// is given about that point (hulls are re-centred when the body is made).
//
// State (Baraff & Witkin, SIGGRAPH 2001 course notes "Physically Based Modeling", Rigid Body Dynamics I
// §2): x (centre of mass, world), q (unit quaternion body → world), v (linear velocity), ω (angular
// velocity, world). Mass m and the body-frame inertia tensor I_body are constants; the world inertia is
// I = R I_body Rᵀ and L = I ω.
#include <optional>
#include <string>

#include "physics/collision/mass.h"
#include "physics/collision/shapes.h"
#include "physics/core/debug_draw.h"
#include "physics/core/result.h"

namespace pba::rigid {

enum class BodyType { Static, Kinematic, Dynamic };

struct BodyDesc {
  BodyType type = BodyType::Dynamic;
  collision::Shape shape;
  Vec3 position{0.0};            ///< [m] world position of the shape's origin; e.g. (0, 1, 0)
  Quat orientation{1, 0, 0, 0};  ///< unit quaternion, body → world
  Vec3 linearVelocity{0.0};      ///< [m/s] world
  Vec3 angularVelocity{0.0};     ///< [rad/s] world
  Real density = 1000.0;         ///< [kg/m³] water 1000, wood ~600, steel ~7850
  /// [kg] when > 0, the mass to use instead of density × volume (the inertia scales with it).
  Real mass = 0.0;
  /// [kg·m²] when not zero, the body-frame inertia about the centre of mass to use instead of the
  /// shape's (a body whose shape is only its collision proxy, e.g. the T-handle of `spinning`).
  Mat3 inertia{0.0};
  Real friction = 0.6;        ///< Coulomb coefficient μ (combined with the other body's by √(μ₁μ₂))
  Real restitution = 0.0;     ///< coefficient e ∈ [0, 1] (combined by max)
  Real linearDamping = 0.0;   ///< [1/s] v ← v / (1 + h c)
  Real angularDamping = 0.0;  ///< [1/s]
  Real gravityScale = 1.0;
  /// Continuous collision (time of impact) against static bodies when the body moves more than half its
  /// smallest extent in a step (Box2D v3's rule for fast bodies). Off: discrete, it may tunnel.
  bool continuous = true;
  /// Continuous collision in every step, however slow (small fast things: shots).
  bool bullet = false;
  bool allowSleep = true;
  Color color{0.55f, 0.57f, 0.60f, 1.0f};
  std::string name;  ///< for messages ("body 'bullet-ccd' position is NaN")
};

struct Body {
  BodyType type = BodyType::Dynamic;
  collision::Shape shape;
  Vec3 position{0.0};                  ///< [m] centre of mass, world
  Quat orientation{1, 0, 0, 0};        ///< body → world
  Vec3 linearVelocity{0.0};            ///< [m/s]
  Vec3 angularVelocity{0.0};           ///< [rad/s] world
  Real mass = 0.0, inverseMass = 0.0;  ///< [kg], [1/kg]; 0 for static and kinematic bodies
  Mat3 inertiaBody{0.0};               ///< [kg·m²] about the centre of mass, body axes
  Mat3 inverseInertiaBody{0.0};        ///< [1/(kg·m²)]
  Mat3 inverseInertiaWorld{0.0};       ///< R I_body⁻¹ Rᵀ, refreshed by the world each step
  Real friction = 0.6, restitution = 0.0;
  Real linearDamping = 0.0, angularDamping = 0.0, gravityScale = 1.0;
  bool continuous = true, bullet = false, allowSleep = true;
  bool isotropic = false;  ///< I_body is a multiple of 1 (a sphere, a cube): no gyroscopic term
  bool sleeping = false;
  Real sleepTime = 0.0;  ///< [s] how long the body has been slow enough to sleep
  int proxy = -1;        ///< broad-phase proxy
  Color color;
  std::string name;

  bool isDynamic() const { return type == BodyType::Dynamic; }
  collision::Transform pose() const { return {position, orientation}; }
  /// Velocity of the body point at world position p: v + ω × (p − x).
  Vec3 velocityAt(const Vec3& p) const { return linearVelocity + glm::cross(angularVelocity, p - position); }
};

/// Builds a body from its description: mass properties from the shape (Mirtich for boxes and hulls),
/// hulls re-centred on their centre of mass. Errors name `field`: non-positive density or mass,
/// non-finite values, a quaternion that is not unit length (|q| − 1 > 1e-6), a plane or mesh that is not
/// static, restitution or friction out of range.
Result<Body> makeBody(const BodyDesc& desc, const std::string& field = "body");

/// The inverse inertia in world axes, Σ_jk (I⁻¹)_jk a_j a_kᵀ with a_j the body's axes in world
/// coordinates (the columns of R): the tensor expressed in the rotated basis.
Mat3 worldInverseInertia(const Quat& orientation, const Mat3& inverseInertiaBody);

/// ½ m |v|² + ½ ω·(I ω) [J].
Real kineticEnergy(const Body& b);
/// I ω in world axes [kg·m²/s], about the body's centre of mass.
Vec3 angularMomentum(const Body& b);

}  // namespace pba::rigid
