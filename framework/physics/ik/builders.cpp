#include "physics/ik/builders.h"

#include <cmath>

#include "physics/core/validate.h"

namespace pba::ik {

namespace {
Joint makeJoint(std::string name, int parent, const Vec3& offset, JointType type, Real limit,
                const Vec3& axis = Vec3(0, 0, 1)) {
  Joint j;
  j.name = std::move(name);
  j.parent = parent;
  j.offset = offset;
  j.type = type;
  j.axis = axis;
  for (int k = 0; k < 3; ++k) {
    j.lo[k] = -limit;
    j.hi[k] = limit;
  }
  j.maxRotation = limit;
  return j;
}

// Adds a joint; the builders only pass valid joints, so an error is a programming mistake surfaced
// as the builder's error.
bool add(Skeleton& s, Joint j, std::string* error) {
  Result<int> r = s.add(std::move(j));
  if (!r && error->empty()) *error = r.error();
  return r.ok();
}

Result<Rig> finish(Rig rig, const std::string& error) {
  if (!error.empty()) return Error{error};
  setGoalsFromPose(rig.skeleton, rig.skeleton.restPose(), rig.effectors);
  return rig;
}
}  // namespace

Status validate(const ChainDesc& d) {
  if (d.links < 1 || d.links > 10000) return Error{"links: must be in [1, 10000], got " + std::to_string(d.links)};
  if (Status s = checkPositive("totalLength", d.totalLength); !s) return s;
  if (!(d.limit > 0.0) || d.limit > kPi) return Error{"limit: must be in (0, pi] rad"};
  if (d.joint == JointType::Fixed) return Error{"joint: a chain of fixed joints cannot move"};
  return checkFinite("base", d.base);
}

Result<Rig> buildIkChain(const ChainDesc& d) {
  if (Status s = validate(d); !s) return Error{s.error()};
  Rig rig;
  std::string error;
  const Real L = d.totalLength / d.links;
  for (int i = 0; i < d.links; ++i) {
    const Vec3 axis = (d.axes == HingeAxes::Alternating && i % 2 == 1) ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
    Joint j = makeJoint("link" + std::to_string(i), i - 1, i == 0 ? d.base : Vec3(L, 0, 0), d.joint, d.limit,
                        d.joint == JointType::Prismatic ? Vec3(1, 0, 0) : axis);
    if (d.joint == JointType::Prismatic) {
      j.lo[0] = -0.5 * L;
      j.hi[0] = 0.5 * L;
    }
    add(rig.skeleton, std::move(j), &error);
  }
  Effector e;
  e.joint = d.links - 1;
  e.localOffset = Vec3(L, 0, 0);
  rig.effectors.push_back(e);
  return finish(std::move(rig), error);
}

Result<Rig> buildSingleJoint(Real length) {
  if (Status s = checkPositive("length", length); !s) return Error{s.error()};
  Rig rig;
  std::string error;
  add(rig.skeleton, makeJoint("shoulder", -1, Vec3(0.0), JointType::Free, kPi), &error);
  Effector e;
  e.localOffset = Vec3(length, 0, 0);
  rig.effectors.push_back(e);
  return finish(std::move(rig), error);
}

Result<Rig> buildTwoBoneArm(const TwoBoneDesc& d) {
  if (Status s = checkPositive("upper", d.upper); !s) return Error{s.error()};
  if (Status s = checkPositive("lower", d.lower); !s) return Error{s.error()};
  Rig rig;
  std::string error;
  add(rig.skeleton, makeJoint("shoulder", -1, d.shoulder, JointType::Ball, kPi), &error);
  Joint elbow = makeJoint("elbow", 0, Vec3(d.upper, 0, 0), JointType::Hinge, kPi);
  elbow.lo[0] = 0.0;
  elbow.hi[0] = degToRad(150.0);
  add(rig.skeleton, elbow, &error);
  Effector e;
  e.joint = 1;
  e.localOffset = Vec3(d.lower, 0, 0);
  rig.effectors.push_back(e);
  return finish(std::move(rig), error);
}

Result<Rig> buildHand() {
  Rig rig;
  std::string error;
  add(rig.skeleton, makeJoint("wrist", -1, Vec3(0.0, 0.0, 0.0), JointType::Ball, degToRad(80.0)), &error);
  // Palm: knuckles spread along z at the end of a 0.09 m palm along +x; the thumb sits lower and turned.
  const Real spread[5] = {-0.045, -0.02, 0.0, 0.02, 0.04};
  const Real lengths[5] = {0.035, 0.045, 0.05, 0.047, 0.037};  // [m] per phalanx
  const char* names[5] = {"thumb", "index", "middle", "ring", "little"};
  for (int f = 0; f < 5; ++f) {
    const Vec3 knuckle = f == 0 ? Vec3(0.03, -0.015, -0.035) : Vec3(0.09, 0.0, spread[f]);
    const int base = rig.skeleton.jointCount();
    add(rig.skeleton, makeJoint(std::string(names[f]) + "1", 0, knuckle, JointType::Ball, degToRad(60.0)), &error);
    Joint mid = makeJoint(std::string(names[f]) + "2", base, Vec3(lengths[f], 0, 0), JointType::Hinge, degToRad(100.0));
    mid.lo[0] = -degToRad(100.0);
    mid.hi[0] = 0.0;
    add(rig.skeleton, mid, &error);
    Joint tip = mid;
    tip.name = std::string(names[f]) + "3";
    tip.parent = base + 1;
    add(rig.skeleton, tip, &error);
    Effector e;
    e.joint = base + 2;
    e.localOffset = Vec3(lengths[f] * 0.8, 0, 0);
    rig.effectors.push_back(e);
  }
  return finish(std::move(rig), error);
}

Result<Rig> buildDoubleY() {
  Rig rig;
  std::string error;
  const Real L = 0.3;
  auto chain = [&](const std::string& name, int parent, const Vec3& first, int n) {
    int last = parent;
    for (int i = 0; i < n; ++i) {
      add(rig.skeleton,
          makeJoint(name + std::to_string(i), last, i == 0 ? first : Vec3(L, 0, 0), JointType::Ball, degToRad(90.0)),
          &error);
      last = rig.skeleton.jointCount() - 1;
    }
    return last;
  };
  // Trunk along +x, then branches turned ±35° about z (the rest rotation) at each split.
  const int trunk = chain("trunk", -1, Vec3(0.0), 3);
  for (int side = 0; side < 2; ++side) {
    const Real turn = side == 0 ? 0.6 : -0.6;
    const int arm = chain(side == 0 ? "left" : "right", trunk, Vec3(L, 0, 0), 2);
    rig.skeleton.joint(rig.skeleton.jointCount() - 2).restRotation = glm::angleAxis(turn, Vec3(0, 0, 1));
    for (int k = 0; k < 2; ++k) {
      const Real turn2 = k == 0 ? 0.5 : -0.5;
      const int leaf = chain(std::string(side == 0 ? "left" : "right") + (k == 0 ? "A" : "B"), arm, Vec3(L, 0, 0), 2);
      rig.skeleton.joint(rig.skeleton.jointCount() - 2).restRotation = glm::angleAxis(turn2, Vec3(0, 0, 1));
      Effector e;
      e.joint = leaf;
      e.localOffset = Vec3(L, 0, 0);
      rig.effectors.push_back(e);
    }
  }
  return finish(std::move(rig), error);
}

Pose randomPose(const Skeleton& s, std::mt19937_64& rng) {
  std::uniform_real_distribution<Real> unit(0.0, 1.0);
  Pose p = s.restPose();
  for (int i = 0; i < s.dofCount(); ++i)
    p.dofs[static_cast<size_t>(i)] = s.dofLo(i) + (s.dofHi(i) - s.dofLo(i)) * unit(rng);
  for (int j = 0; j < s.jointCount(); ++j) {
    if (s.joint(j).type != JointType::Free) continue;
    const Real z = 2.0 * unit(rng) - 1.0, phi = 2.0 * kPi * unit(rng);
    const Real r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const Vec3 axis(r * std::cos(phi), r * std::sin(phi), z);
    p.rotations[static_cast<size_t>(j)] = glm::angleAxis(s.joint(j).maxRotation * unit(rng), axis);
  }
  return p;
}

void setGoalsFromPose(const Skeleton& s, const Pose& pose, std::vector<Effector>& effectors) {
  const std::vector<Frame> frames = forwardKinematics(s, pose);
  for (Effector& e : effectors) {
    e.targetPosition = effectorPosition(e, frames);
    e.targetOrientation = effectorOrientation(e, frames);
  }
}

}  // namespace pba::ik
