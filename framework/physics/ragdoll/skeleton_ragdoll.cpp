#include "physics/ragdoll/skeleton_ragdoll.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace pba::ragdoll {

namespace {

constexpr Real kMinBone = 0.02;  // [m] shorter segments make no bone of their own

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}
bool has(const std::string& s, const char* word) { return s.find(word) != std::string::npos; }

enum class Limb { None, Knee, Elbow };
Limb limbOf(const std::string& name) {
  const std::string n = lower(name);
  if (has(n, "knee") || has(n, "calf") || has(n, "shin") || has(n, "lowerleg") || (has(n, "leg") && !has(n, "upleg")))
    return Limb::Knee;
  if (has(n, "elbow") || has(n, "forearm") || has(n, "lowerarm")) return Limb::Elbow;
  return Limb::None;
}

Real coneOf(const std::string& name, Real fallback) {
  const std::string n = lower(name);
  if (has(n, "spine") || has(n, "chest") || has(n, "neck") || has(n, "head")) return degToRad(30.0);
  if (has(n, "clavicle") || has(n, "shoulder") || has(n, "collar")) return degToRad(20.0);
  if (has(n, "hip") || has(n, "upleg") || has(n, "thigh")) return degToRad(60.0);
  if (has(n, "arm")) return degToRad(80.0);
  if (has(n, "hand") || has(n, "foot") || has(n, "wrist") || has(n, "ankle")) return degToRad(40.0);
  if (has(n, "toe")) return degToRad(60.0);
  return fallback;
}

Quat rotationFromX(const Vec3& d) {
  if (d.x < -1.0 + 1e-12) return Quat(0.0, 0.0, 1.0, 0.0);
  const Vec3 axis = glm::cross(Vec3(1.0, 0.0, 0.0), d);
  const Real s = std::sqrt(2.0 * (1.0 + d.x));
  return glm::normalize(Quat(0.5 * s, axis.x / s, axis.y / s, axis.z / s));
}

Vec3 forwardOf(const std::vector<SkeletonJoint>& joints) {
  Vec3 left(0.0), right(0.0);
  int nl = 0, nr = 0;
  for (const SkeletonJoint& j : joints) {
    const std::string n = lower(j.name);
    if (n.rfind("left", 0) == 0 || n.rfind("l_", 0) == 0) left += j.position, ++nl;
    if (n.rfind("right", 0) == 0 || n.rfind("r_", 0) == 0) right += j.position, ++nr;
  }
  if (nl == 0 || nr == 0) return Vec3(0.0, 0.0, 1.0);
  Vec3 lateral = left / Real(nl) - right / Real(nr);
  lateral.y = 0.0;
  if (glm::length(lateral) < 1e-6) return Vec3(0.0, 0.0, 1.0);
  return glm::normalize(glm::cross(lateral, kUp));
}

/// Whether another joint with the same (merged) parent starts within kMinBone of joint i.
bool sharesStart(const std::vector<SkeletonJoint>& joints, const std::vector<int>& merged, int i) {
  if (joints[i].parent < 0 || merged[i] != i) return false;
  for (std::size_t k = 0; k < joints.size(); ++k) {
    const int j = static_cast<int>(k);
    if (j != i && merged[j] == j && joints[j].parent >= 0 && merged[joints[j].parent] == merged[joints[i].parent] &&
        glm::length(joints[j].position - joints[i].position) < kMinBone)
      return true;
  }
  return false;
}

}  // namespace

Result<RagdollDesc> buildSkeletonRagdoll(const std::vector<SkeletonJoint>& joints, const SkeletonRagdollDesc& s) {
  if (joints.empty()) return Error{"skeleton: has no joints"};
  const int n = static_cast<int>(joints.size());
  std::vector<std::vector<int>> children(n);
  // A joint within kMinBone of its parent's (merged) joint is merged into it: motion-capture files have
  // helper joints at the parent's very place (CMU: LHipJoint, RHipJoint and LowerBack at the hips,
  // LThumb at the hand). Each would start a bone at the parent's point, overlapping its siblings' bones
  // there without a joint between them, so that their contacts pushed against the joints.
  std::vector<int> merged(n);
  for (int i = 0; i < n; ++i) {
    if (joints[i].parent >= i) return Error{"skeleton: joint '" + joints[i].name + "' comes before its parent"};
    if (!isFinite(joints[i].position)) return Error{"skeleton: joint '" + joints[i].name + "' position is not finite"};
    merged[i] = i;
    if (joints[i].parent < 0) continue;
    const int p = merged[joints[i].parent];
    if (glm::length(joints[i].position - joints[p].position) < kMinBone)
      merged[i] = p;
    else
      children[p].push_back(i);
  }
  RagdollDesc d;
  std::vector<int> boneOf(n, -1);
  std::vector<Vec3> direction(n, Vec3(0.0));
  for (int i = 0; i < n; ++i) {
    if (children[i].empty()) continue;
    const Vec3 p = joints[i].position;
    BoneDesc b;
    b.name = joints[i].name;
    if (children[i].size() == 1) {
      const Vec3 seg = joints[children[i][0]].position - p;
      const Real length = glm::length(seg);
      if (length < kMinBone) continue;  // a helper node: its child joins the ancestor's bone
      const Vec3 u = seg / length;
      const Real half = std::clamp(0.5 * s.thickness * length, s.minHalfThickness, s.maxHalfThickness);
      // Bones that start at one point (a chest's neck and collars in some files) are each jointed to the
      // parent there but not to each other: their boxes would overlap at the joint and their contacts pull
      // the joint apart. Such a box starts twice its half thickness along its bone from the joint (at most
      // a third of its length); two such boxes at any angle are then apart, and the joint stays at p.
      const Real start = sharesStart(joints, merged, i) ? std::min(2.0 * half, length / 3.0) : 0.0;
      b.center = p + (0.5 * (length + start)) * u;
      b.halfExtents = Vec3(0.5 * (length - start), half, half);
      b.orientation = rotationFromX(u);
      direction[i] = u;
    } else {
      Vec3 lo = p, hi = p;
      for (int c : children[i]) lo = glm::min(lo, joints[c].position), hi = glm::max(hi, joints[c].position);
      b.center = 0.5 * (lo + hi);
      b.halfExtents = 0.5 * (hi - lo) + Vec3(s.minHalfThickness);
      Vec3 mean(0.0);
      for (int c : children[i]) mean += joints[c].position;
      mean /= static_cast<Real>(children[i].size());
      direction[i] = glm::length(mean - p) > 1e-9 ? glm::normalize(mean - p) : kUp;
    }
    b.mass = 8.0 * b.halfExtents.x * b.halfExtents.y * b.halfExtents.z;  // volume for now
    boneOf[i] = static_cast<int>(d.bones.size());
    d.bones.push_back(b);
  }
  if (d.bones.empty()) return Error{"skeleton: no segment is long enough for a bone (2 cm)"};
  // Mass ∝ volume, but no bone lighter than `minMassShare` of the total: fingers and toes of a detailed
  // file would be hundreds of times lighter than the hips, which a sequential-impulse solver handles poorly.
  const Real volume = totalMass(d);
  for (BoneDesc& b : d.bones) b.mass = std::max(b.mass / volume, s.minMassShare);
  const Real share = totalMass(d);
  for (BoneDesc& b : d.bones) b.mass *= s.totalMass / share;
  const Vec3 forward = forwardOf(joints);
  for (int i = 0; i < n; ++i) {
    if (boneOf[i] < 0) continue;
    int a = joints[i].parent;
    while (a >= 0 && boneOf[a] < 0) a = joints[a].parent;
    if (a < 0) continue;
    JointDesc j;
    j.boneA = boneOf[a], j.boneB = boneOf[i];
    j.anchor = joints[i].position;
    j.limited = true;
    const Vec3& u = direction[i];
    const Limb limb = limbOf(joints[i].name);
    const Vec3 axis = limb == Limb::Knee ? glm::cross(forward, u) : glm::cross(u, forward);
    if (limb != Limb::None && glm::length(axis) > 0.2) {
      j.kind = JointKind::Hinge;
      j.axis = glm::normalize(axis);
      j.lower = 0.0, j.upper = degToRad(150.0);
    } else {
      j.kind = JointKind::Ball;
      j.axis = u;
      j.coneAngle = coneOf(joints[i].name, s.defaultCone);
    }
    d.joints.push_back(j);
  }
  if (Status st = validate(d, "skeleton"); !st) return Error{st.error()};
  return d;
}

}  // namespace pba::ragdoll
