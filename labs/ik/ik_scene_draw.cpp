// IkScene's drawing: bones, joints, rotation axes, limits, goals, the effector's path over the
// iterations of the last solve (IK slides, "Visualising IK"; Workbook §2.1 task 5).
//
// Limits are drawn from the per-DOF ranges [lo, hi] the solvers enforce:
//  - hinge: the arc swept by its bone from lo to hi about the axis;
//  - ball (R = Rx(θ0)·Ry(θ1)·Rz(θ2) in the pre-rotation frame): the bone's reachable directions form
//    a "cone" whose rim is the image of the boundary of the rectangle [lo_a, hi_a] × [lo_b, hi_b] of
//    the two swing DOFs (the third, the twist about the bone, is held at its current value): the rim
//    is traced through that boundary, with rulings from the apex to its four corners. With equal
//    ranges on both swing DOFs it is close to a circular cone; with unequal ranges it is not;
//  - free (quaternion) joint: a rotation of angle ≤ maxRotation turns the bone by ≤ maxRotation, so
//    the reachable directions are exactly the circular cone of that half-angle about the rest bone.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "ik_scene.h"

namespace pba::lab {

using namespace pba::ik;

namespace {
constexpr int kRimSamples = 12;  // points per edge of the ball joint's limit rectangle
constexpr Real kFullTurn = 2.0 * kPi - 1e-9;

/// Bone direction of a ball joint for Euler angles t (the pre-rotation frame applied by the caller).
Vec3 ballDirection(const std::array<Real, 3>& t, const Vec3& bone) {
  return quatFromEulerXYZ(Vec3(t[0], t[1], t[2])) * bone;
}
}  // namespace

Vec3 IkScene::boneOf(int j) const {
  const std::vector<int>& kids = rig_.skeleton.children(j);
  for (int c : kids)
    if (glm::length(rig_.skeleton.joint(c).offset) > 1e-9) return rig_.skeleton.joint(c).offset;
  for (const Effector& e : rig_.effectors)
    if (e.joint == j && glm::length(e.localOffset) > 1e-9) return e.localOffset;
  return Vec3(1, 0, 0);
}

void IkScene::drawJointAxesAndLimits(DebugDraw& d, int j, const std::vector<Frame>& f) const {
  const Joint& joint = rig_.skeleton.joint(j);
  const Frame& fj = f[static_cast<size_t>(j)];
  const Real r = boneRadius_;
  const Vec3 boneDir = glm::normalize(boneOf(j));
  if (joint.type == JointType::Hinge) {
    const Vec3 a = fj.pre * joint.axis;
    d.line(fj.position - 3.0 * r * a, fj.position + 3.0 * r * a, colors::kRed);
    if (showLimits_ && joint.hi[0] - joint.lo[0] < kFullTurn) {
      const Vec3 from = fj.pre * glm::angleAxis(joint.lo[0], joint.axis) * boneDir;
      d.arc(fj.position, a, from, joint.hi[0] - joint.lo[0], 6.0 * r, colors::kOrange);
    }
    return;
  }
  if (joint.type == JointType::Free) {
    if (showLimits_ && joint.maxRotation < kPi - 1e-9 && joint.parent >= 0)
      d.cone(fj.position, fj.pre * boneDir, joint.maxRotation, 5.0 * r, colors::kOrange);
    return;
  }
  if (joint.type != JointType::Ball) return;
  const Real* dofs = &pose_.dofs[static_cast<size_t>(joint.firstDof)];
  if (showBallAxes_) {
    // The Euler axes in the order they act (IK slides, 3-DOF joints): x in the pre frame, y after
    // the x rotation, z after x and y.
    const Quat rx = glm::angleAxis(dofs[0], Vec3(1, 0, 0)), rxy = rx * glm::angleAxis(dofs[1], Vec3(0, 1, 0));
    const std::array<Vec3, 3> axes = {fj.pre * Vec3(1, 0, 0), fj.pre * rx * Vec3(0, 1, 0),
                                      fj.pre * rxy * Vec3(0, 0, 1)};
    const std::array<Color, 3> colour = {colors::kRed, colors::kGreen, colors::kBlue};
    for (int k = 0; k < 3; ++k) d.line(fj.position - 3.0 * r * axes[k], fj.position + 3.0 * r * axes[k], colour[k]);
  }
  if (!showLimits_ || joint.parent < 0) return;
  // The twist DOF is the one whose rest axis is most nearly along the bone; the other two swing it.
  int twist = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(boneDir[k]) > std::abs(boneDir[twist])) twist = k;
  const int a = (twist + 1) % 3, b = (twist + 2) % 3;
  if (joint.hi[a] - joint.lo[a] >= kFullTurn && joint.hi[b] - joint.lo[b] >= kFullTurn) return;
  const Real len = 5.0 * r;
  std::array<Real, 3> t = {dofs[0], dofs[1], dofs[2]};
  std::vector<Vec3> rim;
  const std::array<std::array<Real, 2>, 5> corners = {{{joint.lo[a], joint.lo[b]},
                                                       {joint.hi[a], joint.lo[b]},
                                                       {joint.hi[a], joint.hi[b]},
                                                       {joint.lo[a], joint.hi[b]},
                                                       {joint.lo[a], joint.lo[b]}}};
  for (size_t c = 0; c + 1 < corners.size(); ++c) {
    for (int i = 0; i < kRimSamples; ++i) {
      const Real s = Real(i) / kRimSamples;
      t[static_cast<size_t>(a)] = corners[c][0] + s * (corners[c + 1][0] - corners[c][0]);
      t[static_cast<size_t>(b)] = corners[c][1] + s * (corners[c + 1][1] - corners[c][1]);
      rim.push_back(fj.position + len * (fj.pre * ballDirection(t, boneDir)));
    }
    d.line(fj.position, rim[c * kRimSamples], colors::kOrange);  // ruling to a corner
  }
  for (size_t i = 0; i < rim.size(); ++i) d.line(rim[i], rim[(i + 1) % rim.size()], colors::kOrange);
}

void IkScene::draw(DebugDraw& d) const {
  const std::vector<Frame> f = forwardKinematics(rig_.skeleton, pose_);
  const Real r = boneRadius_;
  const bool many = rig_.skeleton.jointCount() > 200;
  for (int j = 0; j < rig_.skeleton.jointCount(); ++j) {
    const Joint& joint = rig_.skeleton.joint(j);
    const Frame& fj = f[static_cast<size_t>(j)];
    if (joint.parent >= 0) d.capsule(f[static_cast<size_t>(joint.parent)].position, fj.position, r, colors::kBlue);
    if (many) continue;
    d.sphere(fj.position, 1.3 * r, joint.type == JointType::Fixed ? colors::kGrey : colors::kDark);
    drawJointAxesAndLimits(d, j, f);
  }
  for (size_t k = 0; k < rig_.effectors.size(); ++k) {
    const Effector& e = rig_.effectors[k];
    const Vec3 p = effectorPosition(e, f);
    d.capsule(f[static_cast<size_t>(e.joint)].position, p, r, colors::kBlue);
    d.sphere(p, 1.5 * r, colors::kGreen);
    d.sphere(e.targetPosition, kTargetRadiusFactor * r, dragging_ && k == selected_ ? colors::kYellow : colors::kRed);
    if (k == selected_ && rig_.effectors.size() > 1) {  // the goal the arrow keys move: a ring around it
      for (const Vec3& axis : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)})
        d.circle(e.targetPosition, axis, 1.6 * kTargetRadiusFactor * r, colors::kDark);
    }
    if (e.kind == EffectorKind::PositionOrientation) {
      d.frame(p, effectorOrientation(e, f), 8.0 * r);
      d.frame(e.targetPosition, e.targetOrientation, 10.0 * r);
    }
    if (showPath_ && k < last_.effectorPath.size()) {
      const std::vector<Vec3>& path = last_.effectorPath[k];
      for (size_t i = 1; i < path.size(); ++i) d.line(path[i - 1], path[i], colors::kPurple);
    }
  }
  // The scripted path of each goal, thin and grey: where the goal is going (and what "frame the
  // scene" fits in view).
  if (path_ == TargetPath::Circle || path_ == TargetPath::Figure8) {
    constexpr int kSegments = 64;
    for (size_t k = 0; k < centers_.size(); ++k)
      for (int i = 0; i < kSegments; ++i) {
        const Real a = 2.0 * kPi * i / kSegments, b = 2.0 * kPi * (i + 1) / kSegments, shift = 0.7 * Real(k);
        d.line(centers_[k] + pathOffset(k, a + shift), centers_[k] + pathOffset(k, b + shift), colors::kGrey);
      }
  }
  char label[128];
  std::snprintf(label, sizeof label, "%s: %s, %d it, %.2e m", solverName(options_.solver), statusName(last_.status),
                last_.iterations, last_.positionResidual);
  if (!rig_.effectors.empty()) d.text(rig_.effectors[0].targetPosition + Vec3(0, 4.0 * r, 0), label, colors::kDark);
}

}  // namespace pba::lab
