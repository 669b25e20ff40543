#include "physics/ragdoll/builders.h"

#include <cmath>
#include <random>

namespace pba::ragdoll {

namespace {

constexpr Real kCm = 0.01;  // [m]

BoneDesc box(const std::string& name, const Vec3& center, const Vec3& halfExtents, Real mass) {
  BoneDesc b;
  b.name = name;
  b.center = center;
  b.halfExtents = halfExtents;
  b.mass = mass;
  return b;
}

JointDesc joint(JointKind kind, int a, int b, const Vec3& anchor, const Vec3& axis, Real lowerOrCone,
                Real upper = 0.0) {
  JointDesc j;
  j.kind = kind;
  j.boneA = a, j.boneB = b;
  j.anchor = anchor;
  j.axis = glm::normalize(axis);
  j.limited = true;
  if (kind == JointKind::Hinge) {
    j.lower = lowerOrCone, j.upper = upper;
  } else {
    j.coneAngle = lowerOrCone;
  }
  return j;
}

Quat rotationFromX(const Vec3& direction) {
  const Vec3 d = glm::normalize(direction);
  const Real c = d.x;
  if (c < -1.0 + 1e-12) return Quat(0.0, 0.0, 1.0, 0.0);  // 180° about y
  const Vec3 axis = glm::cross(Vec3(1.0, 0.0, 0.0), d);
  const Real s = std::sqrt(2.0 * (1.0 + c));
  return glm::normalize(Quat(0.5 * s, axis.x / s, axis.y / s, axis.z / s));
}

}  // namespace

const std::vector<std::string>& humanBoneNames() {
  static const std::vector<std::string> names = {
      "head",   "neck",   "chest",   "hip",     "upper arm.l", "upper arm.r", "forearm.l", "forearm.r",
      "fist.l", "fist.r", "thigh.l", "thigh.r", "calf.l",      "calf.r",      "foot.l",    "foot.r"};
  return names;
}

RagdollDesc buildHumanRagdoll(const HumanDesc& h) {
  // The paper's table (§5), H × W × D in cm: y = H, x = W, z = D. Centres (cm) stacked from the
  // ground with the feet's heels under the calves, the arms out in a T.
  struct Part {
    Vec3 size, center;
  };
  const std::vector<Part> parts = {{{15.7, 20.0, 20.0}, {0.0, 173.3, 0.0}},  {{10.9, 12.3, 10.9}, {0.0, 157.15, 0.0}},
                                   {{39.2, 40.9, 25.0}, {0.0, 130.55, 0.0}}, {{35.8, 14.5, 14.3}, {0.0, 102.85, 0.0}},
                                   {{36.6, 8.8, 8.8}, {37.9, 146.6, 0.0}},   {{36.6, 8.8, 8.8}, {-37.9, 146.6, 0.0}},
                                   {{28.8, 8.5, 8.5}, {70.6, 146.6, 0.0}},   {{28.8, 8.5, 8.5}, {-70.6, 146.6, 0.0}},
                                   {{8.9, 8.9, 8.9}, {89.45, 146.6, 0.0}},   {{8.9, 8.9, 8.9}, {-89.45, 146.6, 0.0}},
                                   {{16.9, 51.2, 16.9}, {9.45, 70.0, 0.0}},  {{16.9, 51.2, 16.9}, {-9.45, 70.0, 0.0}},
                                   {{10.6, 30.5, 10.6}, {9.45, 29.15, 0.0}}, {{10.6, 30.5, 10.6}, {-9.45, 29.15, 0.0}},
                                   {{9.9, 13.9, 27.3}, {9.45, 6.95, 8.35}},  {{9.9, 13.9, 27.3}, {-9.45, 6.95, 8.35}}};
  Real volume = 0.0;
  for (const Part& p : parts) volume += p.size.x * p.size.y * p.size.z;
  const Real s = h.scale * kCm;
  RagdollDesc d;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Real mass = h.totalMass * parts[i].size.x * parts[i].size.y * parts[i].size.z / volume;
    d.bones.push_back(box(humanBoneNames()[i], s * parts[i].center, 0.5 * s * parts[i].size, mass));
  }
  const auto at = [s](Real x, Real y, Real z) { return s * Vec3(x, y, z); };
  const Real deg = kPi / 180.0;
  using K = JointKind;
  d.joints.push_back(joint(K::Hinge, 1, 0, at(0, 163.3, 0), {1, 0, 0}, -45 * deg, 45 * deg));  // head–neck
  d.joints.push_back(joint(K::Ball, 2, 1, at(0, 151.0, 0), {0, 1, 0}, 45 * deg));              // neck–chest
  d.joints.push_back(joint(K::Ball, 2, 3, at(0, 110.1, 0), {0, -1, 0}, 45 * deg));             // chest–hip
  for (int side = 0; side < 2; ++side) {
    const Real x = side == 0 ? 1.0 : -1.0;  // left is +x
    // Elbows and wrists bend the forearm and fist to the front (+z): about −y on the left, +y on the right.
    const Vec3 flex(0.0, -x, 0.0);
    d.joints.push_back(joint(K::Ball, 2, 4 + side, at(x * 19.6, 146.6, 0), {x, 0, 0}, 90 * deg));           // shoulder
    d.joints.push_back(joint(K::Hinge, 4 + side, 6 + side, at(x * 56.2, 146.6, 0), flex, 0.0, 135 * deg));  // elbow
    d.joints.push_back(
        joint(K::Hinge, 6 + side, 8 + side, at(x * 85.0, 146.6, 0), flex, -90 * deg, 90 * deg));    // wrist
    d.joints.push_back(joint(K::Ball, 3, 10 + side, at(x * 9.45, 95.6, 0), {0, -1, 0}, 45 * deg));  // hip
    // Knees bend the calf backwards and ankles turn the toes down: both positive about +x.
    d.joints.push_back(
        joint(K::Hinge, 10 + side, 12 + side, at(x * 9.45, 44.4, 0), {1, 0, 0}, 0.0, 135 * deg));  // knee
    d.joints.push_back(
        joint(K::Hinge, 12 + side, 14 + side, at(x * 9.45, 13.9, 0), {1, 0, 0}, 0.0, 90 * deg));  // ankle
  }
  if (!h.limits)
    for (JointDesc& j : d.joints) j.limited = false;
  return rotated(translated(std::move(d), h.position), h.orientation, h.position);
}

RagdollDesc buildChain(const ChainDesc& c) {
  RagdollDesc d;
  const Vec3 dir = glm::normalize(c.direction);
  const Quat q = rotationFromX(dir);
  const Vec3& h = c.linkHalfExtents;
  const Real mass = c.density * 8.0 * h.x * h.y * h.z;
  for (int i = 0; i < c.links; ++i) {
    BoneDesc b = box("link " + std::to_string(i), c.start + (2.0 * h.x * i) * dir, h, mass);
    b.orientation = q;
    b.fixed = c.fixedTop && i == 0;
    d.bones.push_back(b);
    if (i == 0) continue;
    JointDesc j;
    j.kind = c.joint;
    j.boneA = i - 1, j.boneB = i;
    j.anchor = c.start + (2.0 * h.x * (i - 0.5)) * dir;
    j.axis = c.joint == JointKind::Hinge ? glm::normalize(c.hingeAxis) : dir;
    d.joints.push_back(j);
  }
  return d;
}

RagdollDesc buildBoxesTest() {
  RagdollDesc d;
  BoneDesc a = box("box a", Vec3(-1.0, 0.6, 0.0), Vec3(0.25), 50.0);
  a.velocity = Vec3(3.0, 0.0, 0.0);
  a.angularVelocity = Vec3(0.0, 0.0, -2.0);
  BoneDesc b = box("box b", Vec3(1.0, 1.2, 0.0), Vec3(0.25), 50.0);
  b.velocity = Vec3(-3.0, 0.0, 0.0);
  b.orientation = glm::angleAxis(degToRad(30.0), Vec3(0.0, 0.0, 1.0));
  d.bones = {a, b};
  return d;
}

RagdollDesc buildChainTest(JointKind kind) {
  ChainDesc c;
  c.joint = kind;
  c.start = Vec3(-0.75, 2.0, 0.0);
  RagdollDesc d = buildChain(c);
  d.bones.push_back(box("falling box", Vec3(0.1, 3.2, 0.0), Vec3(0.12), 8.0));
  return d;
}

RagdollDesc buildMassesTest() {
  RagdollDesc d;
  BoneDesc big = box("big box", Vec3(-1.5, 0.4, 0.0), Vec3(0.4), 80.0);
  big.velocity = Vec3(4.0, 0.0, 0.0);
  d.bones = {big, box("small box", Vec3(0.5, 0.2, 0.0), Vec3(0.2), 10.0)};
  return d;
}

std::vector<Real> limitsTestAngles() { return {0.0, degToRad(45.0), degToRad(90.0), degToRad(135.0)}; }

RagdollDesc buildLimitsTest(JointKind kind) {
  RagdollDesc d;
  const std::vector<Real> limits = limitsTestAngles();
  for (std::size_t i = 0; i < limits.size(); ++i) {
    const Real x = -1.6 + 1.0 * static_cast<Real>(i);
    BoneDesc holder = box("holder " + std::to_string(i), Vec3(x, 2.0, 0.0), Vec3(0.1), 1.0);
    holder.fixed = true;
    d.bones.push_back(holder);
    d.bones.push_back(box("arm " + std::to_string(i), Vec3(x + 0.3, 2.0, 0.0), Vec3(0.2, 0.05, 0.05), 2.0));
    const int a = static_cast<int>(d.bones.size()) - 2;
    const Vec3 anchor(x + 0.1, 2.0, 0.0);
    d.joints.push_back(kind == JointKind::Hinge ? joint(kind, a, a + 1, anchor, {0, 0, 1}, -limits[i], limits[i])
                                                : joint(kind, a, a + 1, anchor, {1, 0, 0}, limits[i]));
  }
  return d;
}

RagdollDesc buildSpider(const SpiderDesc& s) {
  RagdollDesc d;
  const Real r = s.bodyHalfSize;
  const auto massOf = [&](const Vec3& h) { return s.density * 8.0 * h.x * h.y * h.z; };
  d.bones.push_back(box("body", s.position, Vec3(r), massOf(Vec3(r))));
  const Real upper = 0.25, lower = 0.3, thick = 0.05;  // half lengths and half thickness [m]
  const Vec3 dirs[4] = {{1, 0, 0}, {0, 0, 1}, {-1, 0, 0}, {0, 0, -1}};
  for (int k = 0; k < 4; ++k) {
    const Vec3& u = dirs[k];
    const Vec3 half = glm::abs(u) * (upper - thick) + Vec3(thick);
    const Vec3 hip = s.position + r * u;
    d.bones.push_back(box("upper leg " + std::to_string(k), hip + upper * u, half, massOf(half)));
    const Vec3 knee = hip + 2.0 * upper * u;
    const Vec3 lowerHalf(thick, lower, thick);
    d.bones.push_back(
        box("lower leg " + std::to_string(k), knee + Vec3(0.0, -lower, 0.0) + thick * u, lowerHalf, massOf(lowerHalf)));
    const int up = static_cast<int>(d.bones.size()) - 2;
    d.joints.push_back(joint(JointKind::Ball, 0, up, hip, u, degToRad(45.0)));
    d.joints.push_back(joint(JointKind::Hinge, up, up + 1, knee, glm::cross(kUp, u), -degToRad(60.0), degToRad(60.0)));
  }
  return d;
}

RagdollDesc buildStairs(int steps, Real rise, Real run, Real width) {
  RagdollDesc d;
  for (int i = 0; i < steps; ++i) {
    const Real height = rise * (i + 1);
    BoneDesc b = box("step " + std::to_string(i), Vec3(-(i + 0.5) * run, 0.5 * height, 0.0),
                     Vec3(0.5 * run, 0.5 * height, 0.5 * width), 1.0);
    b.fixed = true;
    d.bones.push_back(b);
  }
  return d;
}

RagdollDesc buildPile(int count, unsigned seed) {
  RagdollDesc d = buildStairs(5, 0.2, 0.4, 3.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (int k = 0; k < count; ++k) {
    HumanDesc h;
    h.position = Vec3(-0.9 + 0.4 * u(rng), 1.6 + 0.45 * k, -0.9 + 0.1 * u(rng));
    // Lying face down, turned about the vertical.
    h.orientation = glm::angleAxis(kPi * u(rng), kUp) * glm::angleAxis(0.5 * kPi, Vec3(1.0, 0.0, 0.0));
    append(d, buildHumanRagdoll(h));
  }
  return d;
}

RagdollDesc rotated(RagdollDesc desc, const Quat& q, const Vec3& pivot) {
  for (BoneDesc& b : desc.bones) {
    b.center = pivot + q * (b.center - pivot);
    b.orientation = glm::normalize(q * b.orientation);
    b.velocity = q * b.velocity;
    b.angularVelocity = q * b.angularVelocity;
  }
  for (JointDesc& j : desc.joints) {
    j.anchor = pivot + q * (j.anchor - pivot);
    j.axis = q * j.axis;
  }
  return desc;
}

}  // namespace pba::ragdoll
