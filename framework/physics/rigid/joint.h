#pragma once
// Joints between two bodies (or a body and the world), solved by sequential impulses with soft
// constraints inside Box2D v3's soft step (Catto, "Solver2D", 2024; Box2D v3 src/revolute_joint.c,
// prismatic_joint.c, distance_joint.c, mouse_joint.c). Each type's derivation — constraint C, its
// time derivative Ċ = J v, the effective mass (J M⁻¹ Jᵀ)⁻¹ and the limiting cases — is written next to
// its code in joint_*.cpp. Anchors and axes are given in world coordinates at creation and stored in
// each body's frame.
#include <string>
#include <vector>

#include "physics/core/result.h"
#include "physics/rigid/softness.h"
#include "physics/rigid/solver_body.h"

namespace pba::rigid {

enum class JointKind { Ball, Hinge, ConeTwist, Fixed, Slider, Distance, Mouse };
const char* jointKindName(JointKind kind);

/// What a joint is made from (world frame at creation). Unused fields are ignored by other kinds.
struct JointDesc {
  JointKind kind = JointKind::Ball;
  int bodyA = -1;  ///< −1: the world
  int bodyB = -1;
  Vec3 anchor{0.0};          ///< [m] world point joined (distance: the anchor on A)
  Vec3 anchorB{0.0};         ///< [m] distance joint: the anchor on B
  Vec3 axis{1.0, 0.0, 0.0};  ///< hinge axis, slider direction, cone-twist twist axis (world, unit)
  bool enableLimit = false;
  Real lower = 0.0, upper = 0.0;  ///< hinge and twist [rad], slider [m]
  Real swingSpan = 0.0;           ///< cone-twist cone half-angle [rad]
  bool enableMotor = false;
  Real motorSpeed = 0.0;                   ///< [rad/s] hinge, [m/s] slider
  Real maxMotorTorque = 0.0;               ///< [N·m] hinge, [N] slider
  Real length = -1.0;                      ///< distance [m]; < 0: the distance between the anchors at creation
  Real minLength = 0.0, maxLength = 1e30;  ///< distance limits [m]
  Real hertz = 0.0;                        ///< distance spring [Hz]; 0: rigid. Mouse: 5 Hz typical
  Real dampingRatio = 0.0;                 ///< distance spring and mouse
  Real maxForce = 1e30;                    ///< mouse [N]
  bool collideConnected = false;
};

struct Joint {
  JointDesc desc;
  Vec3 localA{0.0}, localB{0.0};        ///< anchors relative to the centres of mass, body frames
  Vec3 axisA{1, 0, 0}, axisB{1, 0, 0};  ///< the axis in each body's frame
  Quat relative0{1, 0, 0, 0};           ///< conj(q_A) q_B at creation (fixed, slider, twist)
  Vec3 target{0.0};                     ///< mouse: where the anchor is pulled [m]
  Real restLength = 0.0;                ///< distance [m]
  // Solver data of the current step (world arms, effective masses) and accumulated impulses.
  Vec3 rA{0.0}, rB{0.0};
  Mat3 pointMass{0.0};                       ///< K⁻¹ of the point rows
  Mat3 angularMass{0.0};                     ///< K⁻¹ of the angular lock, (I_A⁻¹ + I_B⁻¹)⁻¹
  Vec3 hingeBasis[2]{Vec3(0.0), Vec3(0.0)};  ///< hinge: world directions ⟂ the axis for the two angular rows
  Vec3 axisWorld{0.0};                       ///< the axis in world axes for this step
  Vec3 pointImpulse{0.0};                    ///< [N·s]
  Vec3 angularImpulse{0.0};                  ///< [N·m·s] lock rows (or the 2 hinge rows in the first two)
  Real axialMass = 0.0;
  Real motorImpulse = 0.0, lowerImpulse = 0.0, upperImpulse = 0.0, springImpulse = 0.0;
  Real swingImpulse = 0.0;
  int a = -1, b = -1;  ///< solver-body indices for this step
};

/// Stores anchors and axes in the bodies' frames. Errors name `field`: unknown bodies, non-finite
/// values, a zero axis, lower > upper, a negative span or length.
Status initJoint(Joint& j, const std::vector<SolverBody>& bodiesAtCreation, const std::string& field = "joint");

struct JointStep {
  Real h = 0.0;   ///< substep [s]
  Softness soft;  ///< joint softness (Box2D: 2 × contact hertz, joint damping ratio)
  bool warmStarting = true;
};

void prepareJoint(Joint& j, const std::vector<SolverBody>& bodies, const JointStep& step);
void warmStartJoint(const Joint& j, std::vector<SolverBody>& bodies);
void solveJoint(Joint& j, std::vector<SolverBody>& bodies, const JointStep& step, bool useBias);
/// Distance between the two anchors [m] (the point constraint's error; 0 for distance and slider joints'
/// free directions), from the bodies' current poses.
Real jointPositionError(const Joint& j, const std::vector<SolverBody>& bodies);
/// Hinge angle [rad] (B relative to A about the axis); slider translation [m]; twist angle for cone-twist.
Real jointCoordinate(const Joint& j, const std::vector<SolverBody>& bodies);
/// Cone-twist: the angle between the twist axes [rad].
Real jointSwingAngle(const Joint& j, const std::vector<SolverBody>& bodies);

}  // namespace pba::rigid
