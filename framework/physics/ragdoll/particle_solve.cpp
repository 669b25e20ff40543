// The particle ragdoll's relaxation and projection (particle_ragdoll.h, step 3): sticks, joints, limits,
// the mouse, contacts. The sticks, the limits, the contacts and the moves of embedded points (joints,
// limits, the mouse) are the exercises RAG-1..4 and RAG-6 (exercises.h), called here and nowhere copied.
#include <algorithm>
#include <cmath>

#include "physics/collision/narrow_phase.h"
#include "physics/ragdoll/exercises.h"
#include "physics/ragdoll/particle_ragdoll.h"

namespace pba::ragdoll {

void ParticleRagdoll::relax() {
  relaxSticksFast(sticks_, x_, w_, settings_.stickSweeps);  // RAG-1, through its fast path (stick_fast_path.h)
}

void ParticleRagdoll::keepVolumes() {
  if (!(settings_.minVolumeShare > 0.0)) return;
  for (const Bone& b : bones_) {
    if (b.fixed) continue;
    std::array<Vec3, 4> p = particlesOf(static_cast<int>(&b - bones_.data()));
    if (!keepMinimumVolume(p, {w_[b.first], w_[b.first + 1], w_[b.first + 2], w_[b.first + 3]}, b.restSixVolume,
                           settings_.minVolumeShare))
      continue;
    for (int k = 0; k < 4; ++k) x_[b.first + k] = p[k];
  }
}

void ParticleRagdoll::pushApart(int a, const Weights& inA, int b, const Weights& inB, const Vec3& delta) {
  const int fb = bones_[b].first, fa = bones_[a].first;
  moveEmbeddedPoints({&x_[fa], &w_[fa], inA}, {&x_[fb], &w_[fb], inB}, delta);  // RAG-6
}

void ParticleRagdoll::solveJoints() {
  for (const Joint& j : joints_)
    for (const PointPair& p : j.points) {
      const Vec3 gap = pointOf(j.a, p.inA) - pointOf(j.b, p.inB);
      pushApart(j.a, p.inA, j.b, p.inB, gap);  // B's copy moves to A's, A's towards B's
    }
}

void ParticleRagdoll::solveLimits() {
  for (const Joint& j : joints_) {
    if (!j.limited) continue;
    Vec3 ref(0.0), target(0.0);
    if (j.kind == JointKind::Hinge) {
      const auto [frame, p] = hingeMeasure(j);
      ref = p;
      target = hingeLimit(frame, p, j.lower, j.upper).target;  // RAG-2
    } else {
      const Vec3 apex = pointOf(j.a, j.origin);
      const Vec3 axis = glm::normalize(pointOf(j.a, j.axisEnd) - apex);
      ref = pointOf(j.b, j.reference);
      target = coneLimit(apex, axis, ref, j.cone).target;  // RAG-3
    }
    if (target == ref) continue;
    // B's reference point moves onto the limit, A is pushed back at the same point (the paper's
    // "Newton's third law": the limit turns both bones, momentum is kept).
    pushApart(j.a, weightsOf(j.a, ref), j.b, j.reference, target - ref);
  }
}

void ParticleRagdoll::solveDrag() {
  if (dragBone_ < 0) return;
  // A stiff pull of the grabbed point halfway to the target per iteration (the mouse has no mass): RAG-6
  // with the bone alone on B's side.
  const Vec3 gap = dragTarget_ - pointOf(dragBone_, dragWeights_);
  if (!(glm::length(gap) > 1e-12)) return;
  const int first = bones_[dragBone_].first;
  moveEmbeddedPoints({}, {&x_[first], &w_[first], dragWeights_}, 0.5 * gap);
}

void ParticleRagdoll::solveContacts(bool record) {
  if (record) contacts_.clear();
  // Bone pairs first, the ground last: nothing ends a pass pushed into the floor.
  for (const auto& [a, b] : pairs_) solveBonePair(a, b, record);
  if (settings_.ground) solveGround(record);
}

void ParticleRagdoll::solveGround(bool record) {
  // Moving a bone's deepest corner up by c_i λ Δ also deforms its tetrahedron a little, which can lower
  // another corner: each bone is tested and pushed again (at most 4 times) until no corner is below the
  // ground. A bone's contacts touch only its own particles, so every bone's first push, then every
  // remaining bone's second, and so on, give each bone the results of its own four in a row, and the
  // pushes of one round go to RAG-4's fast path together.
  groundContacts_.clear();
  groundBones_.clear();
  for (int b = 0; b < boneCount(); ++b)
    if (!bones_[b].fixed && groundContact(b, record)) groundBones_.push_back(b);
  for (int round = 1;; ++round) {
    pushOutOfGroundFast(groundContacts_, x_);  // RAG-4, through its fast path (contact_fast_path.h)
    if (round == 4) return;
    std::size_t still = 0;
    groundContacts_.clear();
    for (const int b : groundBones_)
      if (groundContact(b, false)) groundBones_[still++] = b;
    if (still == 0) return;
    groundBones_.resize(still);
  }
}

bool ParticleRagdoll::groundContact(int bone, bool record) {
  const Bone& B = bones_[bone];
  // The corners' depths below the ground, from the heights of the four particles only (embedded()'s y,
  // summed in its order).
  const Real y[4] = {x_[B.first].y, x_[B.first + 1].y, x_[B.first + 2].y, x_[B.first + 3].y};
  std::array<Real, std::tuple_size_v<decltype(Bone::corners)>> depth;
  const auto& w = B.cornerWeights;
  for (std::size_t i = 0; i < depth.size(); ++i)  // the same sums, corner by corner (vectorised)
    depth[i] = settings_.groundHeight - (w[0][i] * y[0] + w[1][i] * y[1] + w[2][i] * y[2] + w[3][i] * y[3]);
  // The deepest corner; equally deep ones (within 0.1 mm) are averaged (paper §3.3).
  Real deepest = 0.0;
  for (const Real d : depth) deepest = std::max(deepest, d);
  if (!(deepest > 1e-9)) return false;
  Weights weights{0.0, 0.0, 0.0, 0.0};
  int count = 0;
  for (std::size_t i = 0; i < depth.size(); ++i)
    if (depth[i] > deepest - 1e-4) {
      for (int k = 0; k < 4; ++k) weights[k] += B.corners[i][k];
      ++count;
    }
  for (Real& c : weights) c /= count;
  touched_[bone] = 1;
  touchNormal_[bone] = kUp;
  if (record) contacts_.push_back({pointOf(bone, weights), kUp});
  groundContacts_.push_back({B.first, weights, deepest, B.mass});
  return true;
}

void ParticleRagdoll::solveBonePair(int a, int b, bool record) {
  // The broad phase's pairs are fattened for the whole step; most are apart in a given pass. Each box
  // lies inside the sphere about its particles' centroid (the fitted frame's centre) through its corners,
  // radius |h|: spheres apart means boxes apart, and the exact test below would find nothing to do.
  const Real reach = (glm::length(bones_[a].halfExtents) + glm::length(bones_[b].halfExtents)) * (1.0 + 1e-6);
  const Vec3 apart = centroid(particlesOf(b)) - centroid(particlesOf(a));
  if (glm::dot(apart, apart) > reach * reach) return;
  const collision::Transform ta = boneFrame(a), tb = boneFrame(b);
  const collision::Manifold m = collision::collideBoxes(bones_[a].shape, ta, bones_[b].shape, tb, 0.0);
  if (m.count == 0) return;
  // The deepest point only (paper §3.3), equally deep ones averaged.
  const Real deepest = m.deepest();
  if (!(deepest < 0.0)) return;
  Vec3 point(0.0);
  int count = 0;
  for (int k = 0; k < m.count; ++k)
    if (m.points[k].separation < deepest + 1e-4) point += m.points[k].point, ++count;
  point /= count;
  touched_[a] = touched_[b] = 1;
  touchNormal_[a] = -m.normal, touchNormal_[b] = m.normal;
  if (record) contacts_.push_back({point, m.normal});
  const Weights inA = weightsOf(a, point), inB = weightsOf(b, point);
  // RAG-4. The exercise's convention: the normal points from B to A, so A is the side pushed along +n.
  std::array<Vec3, 4> pa = particlesOf(a), pb = particlesOf(b);
  ContactSide sideB{&pb, inB, bones_[b].fixed ? 1e30 : bones_[b].mass};
  ContactSide sideA{&pa, inA, bones_[a].fixed ? 1e30 : bones_[a].mass};
  resolveDeepestContact(sideA, sideB, -m.normal, -deepest);
  for (int k = 0; k < 4; ++k) {
    if (!bones_[a].fixed) x_[bones_[a].first + k] = pa[k];
    if (!bones_[b].fixed) x_[bones_[b].first + k] = pb[k];
  }
}

}  // namespace pba::ragdoll
