// The particle ragdoll: building it from a RagdollDesc, the step, the measurements (particle_ragdoll.h).
#include "physics/ragdoll/particle_ragdoll.h"

#include <algorithm>
#include <cmath>

#include "physics/collision/raycast.h"

namespace pba::ragdoll {

namespace {
constexpr int kStickPairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

std::array<Vec3, 8> boxCorners(const Vec3& h) {
  std::array<Vec3, 8> c{};
  for (int i = 0; i < 8; ++i) c[i] = Vec3(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z);
  return c;
}
}  // namespace

ParticleSettings skeletonParticleSettings() {
  ParticleSettings s;
  s.minVolumeShare = 0.5;
  return s;
}

Result<ParticleRagdoll> ParticleRagdoll::build(const RagdollDesc& desc, const ParticleSettings& settings) {
  if (Status s = validate(desc); !s) return Error{s.error()};
  if (settings.iterations < 1) return Error{"ragdoll.iterations: must be at least 1"};
  ParticleRagdoll r;
  r.settings_ = settings;
  for (const BoneDesc& b : desc.bones) {
    Bone bone;
    bone.first = static_cast<int>(r.x_.size());
    bone.halfExtents = b.halfExtents;
    bone.mass = b.mass;
    bone.fixed = b.fixed;
    bone.rest = tetrahedronOffsets(b.halfExtents);
    bone.restInverse = restEdgesInverse(bone.rest);
    bone.restSixVolume = sixVolume(bone.rest);
    bone.shape = collision::makeBox(b.halfExtents).value();
    const std::array<Vec3, 8> corners = boxCorners(b.halfExtents);
    for (int i = 0; i < 8; ++i) bone.corners[i] = barycentric(bone.rest, corners[i]);
    for (int i = 0; i < 8; ++i)
      for (int k = 0; k < 4; ++k) bone.cornerWeights[k][i] = bone.corners[i][k];
    for (const Vec3& offset : bone.rest) {
      const Vec3 p = b.center + b.orientation * offset;
      r.x_.push_back(p);
      r.xOld_.push_back(p);
      r.m_.push_back(0.25 * b.mass);
      r.w_.push_back(b.fixed ? 0.0 : 4.0 / b.mass);
      r.startVelocity_.push_back(b.fixed ? Vec3(0.0) : b.velocity + glm::cross(b.angularVelocity, p - b.center));
    }
    for (const auto& e : kStickPairs)
      r.sticks_.push_back({bone.first + e[0], bone.first + e[1], glm::length(bone.rest[e[0]] - bone.rest[e[1]])});
    r.bones_.push_back(bone);
  }
  r.jointedWith_.assign(r.bones_.size(), {});
  for (const JointDesc& jd : desc.joints) {
    Joint j;
    j.kind = jd.kind;
    j.a = jd.boneA, j.b = jd.boneB;
    j.limited = jd.limited;
    j.lower = jd.lower, j.upper = jd.upper, j.cone = jd.coneAngle;
    const Vec3 axis = glm::normalize(jd.axis);
    const Bone& A = r.bones_[j.a];
    const Bone& B = r.bones_[j.b];
    // Lengths of the embedded offsets: the smaller bone's size, so that the points stay near both.
    const Real reach = std::min(glm::length(A.halfExtents), glm::length(B.halfExtents));
    // The hinge's two points: at the faces of the thinner bone along the axis (not beyond them, where
    // large barycentric weights would turn small joint corrections into large deformations).
    const auto extentAlong = [&](int bone, const Vec3& u) {
      const Vec3 local = glm::conjugate(desc.bones[bone].orientation) * u;
      return glm::dot(glm::abs(local), desc.bones[bone].halfExtents);
    };
    const Real axisHalf = std::min(extentAlong(j.a, axis), extentAlong(j.b, axis));
    const auto pairAt = [&](const Vec3& p) { return PointPair{r.weightsOf(j.a, p), r.weightsOf(j.b, p)}; };
    if (j.kind == JointKind::Ball) {
      j.points.push_back(pairAt(jd.anchor));
    } else {
      j.points.push_back(pairAt(jd.anchor - axisHalf * axis));
      j.points.push_back(pairAt(jd.anchor + axisHalf * axis));
    }
    j.origin = r.weightsOf(j.a, jd.anchor);
    j.axisEnd = r.weightsOf(j.a, jd.anchor + reach * axis);
    // The hinge's angle 0: towards B's centre (⟂ axis), or any ⟂ direction.
    const Vec3 toB = desc.bones[j.b].center - jd.anchor;
    const Vec3 radial = toB - glm::dot(toB, axis) * axis;
    const Vec3 zero = glm::length(radial) > 1e-6 ? glm::normalize(radial) : anyPerpendicular(axis);
    j.zero = r.weightsOf(j.a, jd.anchor + reach * zero);
    j.reference = r.weightsOf(j.b, jd.anchor + reach * (j.kind == JointKind::Hinge ? zero : axis));
    r.joints_.push_back(j);
    r.jointedWith_[j.a].push_back(j.b);
    r.jointedWith_[j.b].push_back(j.a);
  }
  r.touched_.assign(r.bones_.size(), 0);
  r.touchNormal_.assign(r.bones_.size(), Vec3(0.0));
  return r;
}

collision::Transform ParticleRagdoll::boneFrame(int bone) const {
  return fitFrame(particlesOf(bone), bones_[bone].restInverse);
}

void ParticleRagdoll::integrate(Real dt) {
  if (!started_) {  // the initial velocities need the step: x_old = x − v h
    for (std::size_t i = 0; i < x_.size(); ++i) xOld_[i] = x_[i] - dt * startVelocity_[i];
    started_ = true;
  }
  const Real keep = std::max(0.0, 1.0 - settings_.damping * dt);
  const Vec3 gravityStep = settings_.gravity * (dt * dt);
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (w_[i] == 0.0) continue;
    const Vec3 current = x_[i];
    x_[i] += keep * (current - xOld_[i]) + gravityStep;
    xOld_[i] = current;
  }
}

void ParticleRagdoll::step(Real dt) {
  lastDt_ = dt;
  integrate(dt);
  std::fill(touched_.begin(), touched_.end(), 0);
  findPairs(dt);
  for (int it = 0; it < settings_.iterations; ++it) {
    relax();
    keepVolumes();
    if (it + 1 == settings_.iterations) strainAfterRelaxation_ = stickStrain();
    solveJoints();
    solveLimits();
    solveDrag();
    solveContacts(it + 1 == settings_.iterations);
  }
  applyFriction();
}

void ParticleRagdoll::findPairs(Real dt) {
  pairs_.clear();
  if (!settings_.boneCollisions) return;
  struct Entry {
    collision::Aabb box;
    int bone;
    bool fixed;  // the bone's, kept here: the sweep then reads only the entries
  };
  std::vector<Entry> entries;
  entries.reserve(bones_.size());
  for (int b = 0; b < boneCount(); ++b) {
    const collision::Transform t = boneFrame(b);
    const Mat3 r = glm::mat3_cast(t.rotation);
    const Vec3& h = bones_[b].halfExtents;
    const Vec3 extent(std::abs(r[0].x) * h.x + std::abs(r[1].x) * h.y + std::abs(r[2].x) * h.z,
                      std::abs(r[0].y) * h.x + std::abs(r[1].y) * h.y + std::abs(r[2].y) * h.z,
                      std::abs(r[0].z) * h.x + std::abs(r[1].z) * h.y + std::abs(r[2].z) * h.z);
    const int f = bones_[b].first;
    Real travel = 0.0;
    for (int k = 0; k < 4; ++k) travel = std::max(travel, glm::length(x_[f + k] - xOld_[f + k]));
    const Real margin = 2.0 * travel + 0.01 + glm::length(settings_.gravity) * dt * dt;
    entries.push_back({collision::Aabb{t.position - extent, t.position + extent}.fattened(margin), b, bones_[b].fixed});
  }
  const auto jointed = [this](int a, int b) {
    const std::vector<int>& n = jointedWith_[a];
    return std::find(n.begin(), n.end(), b) != n.end();
  };
  const auto consider = [&](const Entry& p, const Entry& q) {
    if (!collision::overlaps(p.box, q.box) || (p.fixed && q.fixed) || jointed(p.bone, q.bone)) return;
    pairs_.emplace_back(std::min(p.bone, q.bone), std::max(p.bone, q.bone));
  };
  if (!settings_.broadPhase) {
    for (std::size_t i = 0; i < entries.size(); ++i)
      for (std::size_t k = i + 1; k < entries.size(); ++k) {
        Entry p = entries[i], q = entries[k];
        p.box = q.box = collision::Aabb{Vec3(-1e30), Vec3(1e30)};  // every unjointed pair, as the paper
        consider(p, q);
      }
    return;
  }
  // Sweep and prune along the axis on which the boxes' centres spread most (Ericson, Real-Time Collision
  // Detection §7.5.2): on a fixed axis, figures lying in rows across it all overlap on it, and the sweep
  // tests every pair of a row (1,000 humans in 17 columns: ~900 candidates per bone along x).
  Vec3 sum(0.0), sum2(0.0);
  for (const Entry& e : entries) {
    const Vec3 c = 0.5 * (e.box.min + e.box.max);
    sum += c;
    sum2 += c * c;
  }
  const Vec3 spread = sum2 - sum * sum / std::max<Real>(1.0, static_cast<Real>(entries.size()));  // n × variance
  const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
  std::sort(entries.begin(), entries.end(),
            [axis](const Entry& p, const Entry& q) { return p.box.min[axis] < q.box.min[axis]; });
  for (std::size_t i = 0; i < entries.size(); ++i)
    for (std::size_t k = i + 1; k < entries.size() && entries[k].box.min[axis] <= entries[i].box.max[axis]; ++k)
      consider(entries[i], entries[k]);
  std::sort(pairs_.begin(), pairs_.end());  // the solver's order does not depend on the axis
}

void ParticleRagdoll::applyFriction() {
  const Real f = std::clamp(settings_.friction, 0.0, 1.0);
  for (int b = 0; b < boneCount(); ++b) {
    if (!touched_[b] || bones_[b].fixed) continue;
    const Vec3 n = touchNormal_[b];
    for (int k = 0; k < 4; ++k) {
      const int i = bones_[b].first + k;
      const Vec3 v = x_[i] - xOld_[i];
      xOld_[i] += f * (v - glm::dot(v, n) * n);
    }
  }
}

Real ParticleRagdoll::jointAngle(int joint) const {
  // Measurements for the stats and the on-screen angles (the limits themselves are RAG-2 and RAG-3).
  const Joint& j = joints_[joint];
  if (j.kind == JointKind::Hinge) {
    const auto [f, ref] = hingeMeasure(j);
    const Vec3 q = ref - f.origin;  // angle about the axis from `zero`, right-hand rule, in (−π, π]
    return std::atan2(glm::dot(q, glm::cross(f.axis, f.zero)), glm::dot(q, f.zero));
  }
  const Vec3 apex = pointOf(j.a, j.origin);
  const Vec3 axis = glm::normalize(pointOf(j.a, j.axisEnd) - apex);
  const Vec3 d = pointOf(j.b, j.reference) - apex;  // angle from the cone axis, in [0, π]
  return std::atan2(glm::length(glm::cross(axis, d)), glm::dot(axis, d));
}

std::pair<HingeFrame, Vec3> ParticleRagdoll::hingeMeasure(const Joint& j) const {
  const std::array<Vec3, 4> a = particlesOf(j.a);
  HingeFrame f;
  f.origin = embedded(a, j.origin);
  f.axis = glm::normalize(embedded(a, j.axisEnd) - f.origin);
  const Vec3 z = embedded(a, j.zero) - f.origin;
  f.zero = glm::normalize(z - glm::dot(z, f.axis) * f.axis);
  return {f, pointOf(j.b, j.reference)};
}

ParticleStats ParticleRagdoll::measure(Real dt) const {
  ParticleStats s;
  s.bones = boneCount();
  s.particles = particleCount();
  s.constraints = static_cast<int>(sticks_.size());
  for (const Joint& j : joints_) s.constraints += static_cast<int>(j.points.size()) + (j.limited ? 1 : 0);
  s.pairs = static_cast<int>(pairs_.size());
  s.contacts = static_cast<int>(contacts_.size());
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const Vec3 v = (x_[i] - xOld_[i]) / dt;
    s.kineticEnergy += 0.5 * m_[i] * glm::dot(v, v);
    if (w_[i] > 0.0) s.potentialEnergy -= m_[i] * glm::dot(settings_.gravity, x_[i]);
  }
  if (!started_) s.kineticEnergy = 0.0;
  s.maxStickStrain = stickStrain();
  s.maxStickStrainAfterRelaxation = strainAfterRelaxation_;
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    const Joint& j = joints_[k];
    for (const PointPair& p : j.points)
      s.maxJointError = std::max(s.maxJointError, glm::length(pointOf(j.a, p.inA) - pointOf(j.b, p.inB)));
    if (!j.limited) continue;
    const Real angle = jointAngle(static_cast<int>(k));
    // A hinge's angle measured from the middle of its range, into (mid − π, mid + π]: a range wider than
    // π is then judged without a jump at ±π.
    const Real mid = 0.5 * (j.lower + j.upper);
    const Real unwrapped = mid + std::remainder(angle - mid, 2.0 * kPi);
    const Real beyond = j.kind == JointKind::Hinge ? std::max({0.0, unwrapped - j.upper, j.lower - unwrapped})
                                                   : std::max(0.0, angle - j.cone);
    s.maxLimitViolation = std::max(s.maxLimitViolation, beyond);
  }
  if (settings_.ground)
    for (int b = 0; b < boneCount(); ++b) {
      const std::array<Vec3, 4> p = particlesOf(b);
      for (const Weights& c : bones_[b].corners)
        s.maxPenetration = std::max(s.maxPenetration, settings_.groundHeight - embedded(p, c).y);
    }
  return s;
}

ParticleStats ParticleRagdoll::stats() const { return measure(lastDt_); }

std::size_t ParticleRagdoll::memoryBytes() const {
  const auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  std::size_t n = sizeof(*this) + bytes(x_) + bytes(xOld_) + bytes(w_) + bytes(m_) + bytes(startVelocity_) +
                  bytes(bones_) + bytes(sticks_) + bytes(joints_) + bytes(pairs_) + bytes(jointedWith_) +
                  bytes(touched_) + bytes(touchNormal_) + bytes(contacts_) + bytes(groundContacts_) +
                  bytes(groundBones_);
  for (const Joint& j : joints_) n += bytes(j.points);
  for (const std::vector<int>& v : jointedWith_) n += bytes(v);
  return n;
}

Real ParticleRagdoll::stickStrain() const {
  Real worst = 0.0;
  for (const Stick& st : sticks_)
    worst = std::max(worst, std::abs(glm::length(x_[st.b] - x_[st.a]) - st.rest) / st.rest);
  return worst;
}

std::optional<std::string> ParticleRagdoll::nonFiniteState() const {
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (!isFinite(x_[i]) || !isFinite(xOld_[i])) return "particle " + std::to_string(i) + " position is not finite";
  return std::nullopt;
}

std::optional<std::pair<int, Real>> ParticleRagdoll::rayCast(const Ray& ray, Real maxT) const {
  std::optional<std::pair<int, Real>> best;
  for (int b = 0; b < boneCount(); ++b) {
    const collision::Transform t = boneFrame(b);
    const Ray local{t.applyInverse(ray.origin), t.rotateInverse(ray.direction)};
    if (const auto hit = collision::rayCastBox(bones_[b].halfExtents, local, maxT);
        hit && (!best || hit->t < best->second))
      best = std::make_pair(b, hit->t);
  }
  return best;
}

void ParticleRagdoll::beginDrag(int bone, const Vec3& worldPoint) {
  if (bone < 0 || bone >= boneCount() || bones_[bone].fixed) return;
  dragBone_ = bone;
  dragWeights_ = weightsOf(bone, worldPoint);
  dragTarget_ = worldPoint;
}

void ParticleRagdoll::placeDragged() {
  if (dragBone_ < 0) return;
  const Vec3 shift = dragTarget_ - pointOf(dragBone_, dragWeights_);
  for (int k = 0; k < 4; ++k) {
    const int i = bones_[dragBone_].first + k;
    x_[i] += shift;
    xOld_[i] = x_[i];
  }
}

}  // namespace pba::ragdoll
