#include "physics/ik/skeleton.h"

#include "physics/core/enum_names.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "physics/core/validate.h"

namespace pba::ik {

int dofCount(JointType type) {
  switch (type) {
    case JointType::Hinge:
    case JointType::Prismatic:
      return 1;
    case JointType::Ball:
      return 3;
    case JointType::Fixed:
    case JointType::Free:
      return 0;
  }
  return 0;
}

namespace {
constexpr auto kJointTypeNames = enumNames<JointType>({{JointType::Fixed, "fixed"},
                                                       {JointType::Hinge, "hinge"},
                                                       {JointType::Ball, "ball"},
                                                       {JointType::Free, "free"},
                                                       {JointType::Prismatic, "prismatic"}});
}  // namespace

const char* jointTypeName(JointType type) { return kJointTypeNames.name(type).data(); }

Result<int> Skeleton::add(Joint j) {
  const int index = jointCount();
  const std::string field = "joint[" + std::to_string(index) + "]" + (j.name.empty() ? "" : " '" + j.name + "'");
  if (j.parent < -1 || j.parent >= index)
    return Error{field + ".parent: must be -1 or an earlier joint, got " + std::to_string(j.parent)};
  if (Status s = checkFinite(field + ".offset", j.offset); !s) return Error{s.error()};
  // Every test puts isFinite first: an ordered comparison with NaN raises the invalid-operation trap.
  const Real axisLength = isFinite(j.axis) ? glm::length(j.axis) : 0.0;
  if ((j.type == JointType::Hinge || j.type == JointType::Prismatic) && !(isFinite(axisLength) && axisLength > 1e-12))
    return Error{field + ".axis: must be a non-zero finite vector"};
  if (isFinite(axisLength) && axisLength > 1e-12) j.axis /= axisLength;
  const glm::dvec4 q(j.restRotation.x, j.restRotation.y, j.restRotation.z, j.restRotation.w);
  const Real qLength = isFinite(q.w) && isFinite(Vec3(q.x, q.y, q.z)) ? glm::length(q) : 0.0;
  if (!(isFinite(qLength) && qLength > 1e-12))
    return Error{field + ".restRotation: must be a non-zero finite quaternion"};
  j.restRotation = Quat(j.restRotation.w / qLength, j.restRotation.x / qLength, j.restRotation.y / qLength,
                        j.restRotation.z / qLength);
  for (int k = 0; k < ik::dofCount(j.type); ++k) {
    if (!isFinite(j.lo[k]) || !isFinite(j.hi[k]) || j.lo[k] > j.hi[k])
      return Error{field + ".limits[" + std::to_string(k) + "]: need finite lo <= hi"};
    if (!isFinite(j.weight[k]) || !(j.weight[k] > 0.0))
      return Error{field + ".weight[" + std::to_string(k) + "]: must be > 0"};
  }
  if (!isFinite(j.maxRotation) || j.maxRotation < 0.0 || j.maxRotation > kPi)
    return Error{field + ".maxRotation: must be in [0, pi]"};
  j.firstDof = dofTotal_;
  for (int k = 0; k < ik::dofCount(j.type); ++k) dofJoint_.push_back(index);
  dofTotal_ += ik::dofCount(j.type);
  children_.emplace_back();
  if (j.parent >= 0) children_[static_cast<size_t>(j.parent)].push_back(index);
  joints_.push_back(std::move(j));
  return index;
}

Real Skeleton::dofLo(int i) const {
  const Joint& j = joint(dofJoint(i));
  return j.lo[i - j.firstDof];
}
Real Skeleton::dofHi(int i) const {
  const Joint& j = joint(dofJoint(i));
  return j.hi[i - j.firstDof];
}
Real Skeleton::dofWeight(int i) const {
  const Joint& j = joint(dofJoint(i));
  return j.weight[i - j.firstDof];
}

int Skeleton::find(const std::string& name) const {
  for (int j = 0; j < jointCount(); ++j)
    if (joints_[static_cast<size_t>(j)].name == name) return j;
  return -1;
}

Pose Skeleton::restPose() const {
  Pose p;
  p.dofs.resize(static_cast<size_t>(dofTotal_));
  for (int i = 0; i < dofTotal_; ++i) p.dofs[static_cast<size_t>(i)] = std::clamp(0.0, dofLo(i), dofHi(i));
  p.rotations.assign(joints_.size(), Quat(1, 0, 0, 0));
  return p;
}

Status validate(const Skeleton& s, const Pose& p) {
  if (static_cast<int>(p.dofs.size()) != s.dofCount())
    return Error{"pose.dofs: expected " + std::to_string(s.dofCount()) + " values, got " +
                 std::to_string(p.dofs.size())};
  if (static_cast<int>(p.rotations.size()) != s.jointCount())
    return Error{"pose.rotations: expected " + std::to_string(s.jointCount()) + " values, got " +
                 std::to_string(p.rotations.size())};
  for (size_t i = 0; i < p.dofs.size(); ++i)
    if (!std::isfinite(p.dofs[i])) return Error{"pose.dofs[" + std::to_string(i) + "]: must be finite"};
  for (size_t j = 0; j < p.rotations.size(); ++j) {
    const Quat& q = p.rotations[j];
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.w) ||
        std::abs(glm::dot(q, q) - 1.0) > 1e-6)
      return Error{"pose.rotations[" + std::to_string(j) + "]: must be a unit quaternion"};
  }
  return Status::success();
}

Quat jointRotation(const Joint& j, const Pose& p, int jointIndex) {
  const Real* d = p.dofs.data() + j.firstDof;
  switch (j.type) {
    case JointType::Hinge:
      return glm::angleAxis(d[0], j.axis);
    case JointType::Ball:
      return quatFromEulerXYZ(Vec3(d[0], d[1], d[2]));
    case JointType::Free:
      return p.rotations[static_cast<size_t>(jointIndex)];
    case JointType::Fixed:
    case JointType::Prismatic:
      break;
  }
  return Quat(1, 0, 0, 0);
}

Vec3 jointTranslation(const Joint& j, const Pose& p) {
  if (j.type == JointType::Prismatic)
    return j.offset + j.restRotation * (j.axis * p.dofs[static_cast<size_t>(j.firstDof)]);
  return j.offset;
}

Frame childFrame(const Joint& j, const Pose& p, int jointIndex, const Frame* parent) {
  Frame f;
  const Quat parentRotation = parent ? parent->rotation : Quat(1, 0, 0, 0);
  const Vec3 parentPosition = parent ? parent->position : Vec3(0.0);
  f.pre = parentRotation * j.restRotation;
  f.position = parentPosition + parentRotation * jointTranslation(j, p);
  f.rotation = f.pre * jointRotation(j, p, jointIndex);
  return f;
}

void forwardKinematics(const Skeleton& s, const Pose& p, std::vector<Frame>& frames) {
  frames.resize(static_cast<size_t>(s.jointCount()));
  for (int j = 0; j < s.jointCount(); ++j) {
    const Joint& joint = s.joint(j);
    frames[static_cast<size_t>(j)] =
        childFrame(joint, p, j, joint.parent >= 0 ? &frames[static_cast<size_t>(joint.parent)] : nullptr);
  }
}

std::vector<Frame> forwardKinematics(const Skeleton& s, const Pose& p) {
  std::vector<Frame> frames;
  forwardKinematics(s, p, frames);
  return frames;
}

// R = Rx(a) Ry(b) Rz(c). Its matrix (rows) is
//   [ cb cc            −cb sc            sb    ]
//   [ ca sc + sa sb cc  ca cc − sa sb sc  −sa cb ]
//   [ sa sc − ca sb cc  sa cc + ca sb sc   ca cb ]
// so b = atan2(R02, hypot(R00, R01)), a = atan2(−R12, R22), c = atan2(−R01, R00). glm is column-major:
// m[col][row].
Vec3 eulerXYZFromQuat(const Quat& q) {
  const Mat3 m = glm::mat3_cast(q);
  const Real r02 = m[2][0], r12 = m[2][1], r22 = m[2][2], r00 = m[0][0], r01 = m[1][0];
  const Real cosB = std::sqrt(r00 * r00 + r01 * r01);  // entries of a rotation: no overflow, hypot not needed
  const Real b = std::atan2(std::clamp(r02, -1.0, 1.0), cosB);
  if (cosB < 1e-12) {
    // Gimbal lock (b = ±π/2): only a ± c is defined; put it all in a.
    const Real r10 = m[0][1], r11 = m[1][1];
    return Vec3(std::atan2(r10, r11), b, 0.0);
  }
  return Vec3(std::atan2(-r12, r22), b, std::atan2(-r01, r00));
}

Quat quatFromEulerXYZ(const Vec3& e) { return quatFromEulerXYZ(e, nullptr); }

Quat quatFromEulerXYZ(const Vec3& e, EulerHalfAngles* half) {
  if (e.x == 0.0 && e.y == 0.0 && e.z == 0.0) {  // rest poses: skip three sincos
    if (half) *half = EulerHalfAngles{};
    return Quat(1, 0, 0, 0);
  }
  // Rx(a)·Ry(b)·Rz(c) as quaternions (cos ½, sin ½ axis), with the products by their zero components
  // left out: the same roundings as the three general products, a third of the work.
  const Real cx = std::cos(0.5 * e.x), sx = std::sin(0.5 * e.x), cy = std::cos(0.5 * e.y), sy = std::sin(0.5 * e.y);
  const Real cz = std::cos(0.5 * e.z), sz = std::sin(0.5 * e.z);
  if (half) *half = EulerHalfAngles{e.x, e.y, cx, sx, cy, sy};
  const Real w = cx * cy, x = sx * cy, y = cx * sy, z = sx * sy;  // Rx·Ry
  return Quat(w * cz - z * sz, x * cz + y * sz, y * cz - x * sz, w * sz + z * cz);
}

Vec3 rotationVector(const Quat& qIn) {
  Quat q = qIn;
  if (q.w < 0.0) q = Quat(-q.w, -q.x, -q.y, -q.z);
  const Vec3 v(q.x, q.y, q.z);
  const Real s = glm::length(v);
  if (s < 1e-12) return (q.w > 0.5 ? 2.0 / q.w : 2.0) * v;  // small-angle limit 2 v / w
  const Real angle = 2.0 * std::atan2(s, q.w);
  return v * (angle / s);
}

Quat quatFromRotationVector(const Vec3& v) {
  const Real angle = glm::length(v);
  if (angle < 1e-12) {
    const Quat q(1.0, 0.5 * v.x, 0.5 * v.y, 0.5 * v.z);
    return q * (1.0 / glm::length(glm::dvec4(q.w, q.x, q.y, q.z)));
  }
  return glm::angleAxis(angle, v / angle);
}

Quat shortestArc(const Vec3& u, const Vec3& v) {
  const Real uu = glm::dot(u, u), vv = glm::dot(v, v);
  if (uu < 1e-24 || vv < 1e-24) return Quat(1, 0, 0, 0);
  // Eigen's Quaternion::FromTwoVectors step by step (the same operations in the same order, so the
  // same bits, without its set-up): unit vectors v0, v1, c = v1·v0, axis v0 × v1, s = √(2(1 + c)),
  // q = (s/2, axis/s); renormalised, since near-opposite vectors leave the half-angle form a little
  // off unit length. Opposite vectors (c < −1 + 10⁻¹², Eigen's dummy_precision) go to Eigen itself:
  // a half turn about a perpendicular axis found by its SVD.
  const Vec3 v0 = u / std::sqrt(uu), v1 = v / std::sqrt(vv);
  const Real c = glm::dot(v1, v0);
  if (c < -1.0 + 1e-12) {
    const Eigen::Quaterniond q =
        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d(u.x, u.y, u.z), Eigen::Vector3d(v.x, v.y, v.z));
    return glm::normalize(Quat(q.w(), q.x(), q.y(), q.z()));
  }
  const Vec3 axis = glm::cross(v0, v1);
  const Real s = std::sqrt((1.0 + c) * 2.0), invs = 1.0 / s;
  return glm::normalize(Quat(s * 0.5, axis.x * invs, axis.y * invs, axis.z * invs));
}

Vec3 anyPerpendicular(const Vec3& v) {
  const Vec3 n = glm::cross(v, std::abs(v.x) < 0.9 * glm::length(v) ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
  return n / glm::length(n);
}

Real limitViolation(const Skeleton& s, const Pose& p) {
  Real worst = 0.0;
  for (int i = 0; i < s.dofCount(); ++i) {
    const Real v = p.dofs[static_cast<size_t>(i)];
    worst = std::max({worst, s.dofLo(i) - v, v - s.dofHi(i)});
  }
  for (int j = 0; j < s.jointCount(); ++j) {
    if (s.joint(j).type != JointType::Free) continue;
    worst = std::max(worst, glm::length(rotationVector(p.rotations[static_cast<size_t>(j)])) - s.joint(j).maxRotation);
  }
  return worst;
}

}  // namespace pba::ik
