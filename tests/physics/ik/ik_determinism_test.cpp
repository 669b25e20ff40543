// Determinism of every solver (issue 3, "Tests: determinism"). Untagged: it holds against the
// exercise stubs too (they are deterministic), so it passes in the student release.
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "ik_random_targets.h"
#include "physics/core/byte_hash.h"
#include "physics/ik/builders.h"
#include "physics/ik/solver.h"

namespace pba::ik {
namespace {

using testing::chain;

// Determinism (issue 3): identical inputs give bitwise-identical results for every solver, on chains
// with limits, trees (where the stall recovery restarts often) and the analytic solver's limbs; a
// solve in between, of other goals, changes nothing (no hidden state), and the repeatability option
// (fromRest) makes the start pose irrelevant. Poses are compared by a hash of their bytes and
// field by field.
// The bits of a double (std::bit_cast is missing from Emscripten 3.1.6's libc++, which the browser build's
// tests use).
std::uint64_t bitsOf(double x) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

std::uint64_t poseHash(const Pose& pose) {
  ByteHash h;
  h.addAll(std::span<const Real>(pose.dofs));
  h.addAll(std::span<const Quat>(pose.rotations));
  return h.value();
}

void expectIdentical(const SolveResult& a, const Pose& pa, const SolveResult& b, const Pose& pb) {
  EXPECT_EQ(poseHash(pa), poseHash(pb));
  EXPECT_EQ(pa.dofs, pb.dofs);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.restarts, b.restarts);
  EXPECT_EQ(bitsOf(a.positionResidual), bitsOf(b.positionResidual));
  EXPECT_EQ(bitsOf(a.orientationResidual), bitsOf(b.orientationResidual));
}

TEST(IkDeterminism, EverySolverGivesBitwiseIdenticalResultsForIdenticalInputs) {
  struct Setup {
    const char* name;
    Rig rig;
  };
  std::vector<Setup> setups;
  setups.push_back({"10 hinges ±120°", chain(JointType::Hinge)});
  setups.push_back({"10 ball joints ±120°", chain(JointType::Ball)});
  setups.push_back({"double Y", buildDoubleY().value()});
  setups.push_back({"hand", buildHand().value()});
  setups.push_back({"two-bone arm", buildTwoBoneArm(TwoBoneDesc{}).value()});
  for (const SolverInfo& method : solverTable()) {
    for (Setup& setup : setups) {
      SCOPED_TRACE(::testing::Message() << method.name << " on " << setup.name);
      const Skeleton& sk = setup.rig.skeleton;
      std::mt19937_64 rng(7);
      for (int i = 0; i < 6; ++i) {
        std::vector<Effector> goals = setup.rig.effectors, other = setup.rig.effectors;
        setGoalsFromPose(sk, randomPose(sk, rng), goals);
        setGoalsFromPose(sk, randomPose(sk, rng), other);
        const Pose start = randomPose(sk, rng);
        SolveOptions o;
        o.solver = method.value;
        o.maxIterations = 300;
        o.restarts = 10;  // the stall recovery's random poses must be deterministic too
        Pose a = start, between = start, b = start;
        const SolveResult ra = solve(sk, a, goals, o);
        solve(sk, between, other, o);
        const SolveResult rb = solve(sk, b, goals, o);
        expectIdentical(ra, a, rb, b);
        // Repeatability: from the rest pose whatever the pose passed in.
        o.fromRest = true;
        Pose restStart = sk.restPose(), randomStart = start;
        const SolveResult rr = solve(sk, restStart, goals, o);
        const SolveResult rs = solve(sk, randomStart, goals, o);
        expectIdentical(rr, restStart, rs, randomStart);
      }
    }
  }
}

// A SolveWorkspace keeps storage and the last FABRIK method between the solves it serves: a solve
// through a workspace that has served other skeletons, sizes and methods gives the bits of the same
// solve through a fresh workspace, which starts with nothing kept.
TEST(IkDeterminism, ASolveThroughAUsedWorkspaceEqualsOneThroughAFreshOne) {
  const Rig balls = chain(JointType::Ball), hinges = chain(JointType::Hinge, 30), hand = buildHand().value();
  SolveWorkspace used;
  for (SolverKind kind : {SolverKind::Fabrik, SolverKind::Ccd, SolverKind::DampedLeastSquares}) {
    SCOPED_TRACE(solverName(kind));
    std::mt19937_64 rng(11);
    for (const Rig* rig : {&balls, &hinges, &hand}) {
      const Skeleton& sk = rig->skeleton;
      std::vector<Effector> goals = rig->effectors;
      setGoalsFromPose(sk, randomPose(sk, rng), goals);
      const Pose start = randomPose(sk, rng);
      SolveOptions o;
      o.solver = kind;
      Pose fresh = start;
      SolveResult onFresh;
      {
        SolveWorkspace freshWorkspace;
        onFresh = solve(sk, fresh, goals, o, freshWorkspace);
      }
      // The used workspace has served other problems (every rig, FABRIK and CCD) before this one.
      for (const Rig* other : {&hand, &hinges, &balls})
        for (SolverKind otherKind : {SolverKind::Fabrik, SolverKind::Ccd}) {
          std::vector<Effector> otherGoals = other->effectors;
          setGoalsFromPose(other->skeleton, randomPose(other->skeleton, rng), otherGoals);
          Pose p = other->skeleton.restPose();
          SolveOptions otherOptions;
          otherOptions.solver = otherKind;
          solve(other->skeleton, p, otherGoals, otherOptions, used);
        }
      Pose warm = start;
      const SolveResult onWarm = solve(sk, warm, goals, o, used);
      expectIdentical(onFresh, fresh, onWarm, warm);
    }
  }
}

}  // namespace
}  // namespace pba::ik
