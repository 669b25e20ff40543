// IK lab, scene "batch": K solves, each from the rest pose, toward goals made by forward kinematics
// of random poses inside the limits (reachable by construction), with statistics for scripts and CI:
//   pba-ik --headless --solver ccd --links 10 --joint hinge --targets 1000 --seed 1 --metrics -
// On an imported skeleton (the chosen effectors get the random goals; --targets after --skeleton,
// since the last flag that selects a scene wins):
//   pba-ik --headless --skeleton resources/models/humanoid.bvh --effectors LeftHand,RightFoot --targets 100 --metrics -
// On the tree scene's hand or double Y (every effector gets a goal):
//   pba-ik --headless --solver fabrik --targets 300 --seed 12 --set tree=hand --metrics -
// The solves run in reset(), so the metrics are ready after any number of frames and are identical
// for identical seeds, timings excepted (solve_us_median, solve_us_p95: the determinism check skips
// keys with a "us" or "ms" component). Every goal is solved twice: once by the method as published
// (no restarts: success_rate_no_restarts, iterations_mean_no_restarts) and once with the stall
// recovery of SolveOptions::restarts (success_rate and the other statistics; `restarts` says how
// many were allowed, `--set restarts=0` makes the two runs one). Batch mode refuses what it cannot measure, with exit code 2:
// analytic IK on more than 2 links or a tree, a skeleton without effectors or without a joint that
// moves them, a tree and a skeleton together.
#include <algorithm>
#include <cstdio>
#include <random>

#include "app/assets/character_rig.h"
#include "ik_scene.h"

namespace {
std::string solverChoices() {
  std::string choices;
  for (const pba::ik::SolverInfo& s : pba::ik::solverTable())
    choices += std::string(choices.empty() ? "" : "|") + std::string(s.name);
  return choices;
}
}  // namespace

PBA_REGISTER_LAB_FLAG("solver", "solver", "IK method: " + solverChoices(), "batch");
PBA_REGISTER_LAB_FLAG("links", "links", "number of links of the batch chain", "batch");
PBA_REGISTER_LAB_FLAG("joint", "joint", "joint type of the batch chain: hinge|ball", "batch");
// --targets means batch mode whatever else is given (priority 2 beats --skeleton's character scene).
PBA_REGISTER_LAB_FLAG("targets", "targets", "number of random reachable targets (solves)", "batch", 2);
PBA_REGISTER_LAB_FLAG("tolerance", "tolerance", "success tolerance [m]", "batch");
PBA_REGISTER_LAB_FLAG("max-iterations", "max_iterations", "iteration cap per solve", "batch");

namespace pba::lab {

using namespace pba::ik;
namespace {

enum class BatchJoint { Hinge, Ball };
constexpr auto kBatchJointNames = enumNames<BatchJoint>({{BatchJoint::Hinge, "hinge"}, {BatchJoint::Ball, "ball"}});
enum class BatchTree { None, Hand, DoubleY };
constexpr auto kBatchTreeNames =
    enumNames<BatchTree>({{BatchTree::None, "none"}, {BatchTree::Hand, "hand"}, {BatchTree::DoubleY, "double-y"}});

Real percentile(std::vector<Real> v, Real q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t i = static_cast<size_t>(q * static_cast<Real>(v.size() - 1) + 0.5);
  return v[std::min(i, v.size() - 1)];
}

class BatchScene final : public app::Scene {
 public:
  BatchScene() {
    options_.solver = SolverKind::Ccd;
    options_.maxIterations = 1000;
    params_.choiceEnum("solver", &options_.solver, solverNames(), "IK method.").needsReset();
    params_.integer("links", &desc_.links, 1, 10000, "", "Links of the chain.").needsReset().workload();
    params_.choiceEnum("joint", &joint_, kBatchJointNames, "Joint type of every link.").needsReset();
    params_.integer("targets", &targets_, 1, 1000000, "", "Number of solves.").needsReset().workload();
    params_.real("tolerance", &options_.tolerance, 1e-9, 1.0, "m", "Success tolerance. Typical 1e-4 m.")
        .logarithmic()
        .needsReset();
    params_.integer("max_iterations", &options_.maxIterations, 1, 100000, "", "Iteration cap per solve.")
        .needsReset()
        .workload();
    params_.angle("limit", &desc_.limit, 5.0, 180.0, "Every rotational DOF in ±limit.").needsReset();
    params_
        .flag("limits", &options_.enforceLimits,
              "Enforce the joint limits (IK-6's clamp). Off: the goals still come from poses inside them.")
        .needsReset();
    params_.choiceEnum("tree", &tree_, kBatchTreeNames,
                       "A tree of the tree scene instead of the chain: the hand (five finger tips) or Buss & Kim's "
                       "double Y. none: the chain.");
    declareMethodOptions(params_, options_, false);
    for (app::Param& p : params_.all())  // every setting of batch mode takes effect by re-running the solves
      p.needsReset = true;
    params_
        .text("skeleton", &character_.skeleton,
              "Skeleton file to use instead of the chain (BVH, FBX, COLLADA, glTF). Empty: the chain.")
        .needsReset();
    params_
        .text("effectors", &character_.effectors,
              "Comma-separated joint names of the skeleton's effectors. Empty: hands and feet.")
        .needsReset();
    targets_ = 100;
    options_.restarts = 10;  // both runs say something: as published, and with the stall recovery
  }
  Status validate() override {
    if (tree_ != BatchTree::None && !character_.skeleton.empty())
      return Error{"tree: " + character_.skeleton + " is given too; choose the tree or the skeleton"};
    if (tree_ != BatchTree::None && options_.solver == SolverKind::Analytic)
      return Error{"--solver analytic applies to 1 or 2 links, not to a tree"};
    if (character_.skeleton.empty()) {
      if (options_.solver == SolverKind::Analytic && desc_.links > 2)
        return Error{"--solver analytic applies to 1 or 2 links, got --links " + std::to_string(desc_.links)};
      return Status::success();
    }
    const Result<Rig> r = app::loadCharacterRig(character_);
    if (!r) return Error{r.error()};
    const Rig& rig = r.value();
    if (rig.effectors.empty())
      return Error{"effectors: " + character_.skeleton + " has none (name its joints with --effectors)"};
    bool moves = false;
    for (const Effector& e : rig.effectors)
      for (int j = e.joint; j >= 0 && !moves; j = rig.skeleton.joint(j).parent)
        moves = dofCount(rig.skeleton.joint(j).type) > 0 || rig.skeleton.joint(j).type == JointType::Free;
    if (!moves) return Error{"effectors: no joint of " + character_.skeleton + " above them moves"};
    if (options_.solver == SolverKind::Analytic) {
      Pose pose = rig.skeleton.restPose();
      const SolveResult trial = solve(rig.skeleton, pose, rig.effectors, options_, workspace_);
      if (trial.status == SolveStatus::NotApplicable)
        return Error{"--solver analytic: " + trial.message + " (it applies to 1 or 2 links)"};
    }
    return Status::success();
  }
  std::string description() const override {
    return "Batch statistics: K solves from rest toward random reachable goals (success rate, residuals, iterations, "
           "time).";
  }
  void reset() override {
    desc_.joint = joint_ == BatchJoint::Hinge ? JointType::Hinge : JointType::Ball;
    Result<Rig> character = character_.skeleton.empty() ? Result<Rig>(Error{""}) : app::loadCharacterRig(character_);
    rig_ = character                     ? std::move(character).value()
           : tree_ == BatchTree::Hand    ? buildHand().value()
           : tree_ == BatchTree::DoubleY ? buildDoubleY().value()
                                         : buildIkChain(desc_).value();
    std::mt19937_64 rng(seed());
    std::vector<Real> residuals, times;
    successes_ = 0;
    violations_ = 0;
    long iterations = 0, restarts = 0, plainIterations = 0;
    plainSuccesses_ = 0;
    SolveOptions plain = options_;
    plain.restarts = 0;
    for (int i = 0; i < targets_; ++i) {
      std::vector<Effector> effectors = rig_.effectors;
      setGoalsFromPose(rig_.skeleton, randomPose(rig_.skeleton, rng), effectors);
      pose_ = rig_.skeleton.restPose();
      last_ = solve(rig_.skeleton, pose_, effectors, plain, workspace_);
      plainSuccesses_ += last_.status == SolveStatus::Success;
      plainIterations += last_.iterations;
      if (options_.restarts > 0) {
        pose_ = rig_.skeleton.restPose();
        last_ = solve(rig_.skeleton, pose_, effectors, options_, workspace_);
      }
      successes_ += last_.status == SolveStatus::Success;
      violations_ += limitViolation(rig_.skeleton, pose_) > 1e-9;
      iterations += last_.iterations;
      restarts += last_.restarts;
      residuals.push_back(last_.positionResidual);
      times.push_back(last_.seconds * 1e6);
      lastGoals_.clear();
      for (const Effector& e : effectors) lastGoals_.push_back(e.targetPosition);
    }
    residualMax_ = residuals.empty() ? 0.0 : *std::max_element(residuals.begin(), residuals.end());
    residualMedian_ = percentile(residuals, 0.5);
    timeMedian_ = percentile(times, 0.5);
    timeP95_ = percentile(times, 0.95);
    iterationsMean_ = targets_ > 0 ? Real(iterations) / targets_ : 0.0;
    restartsMean_ = targets_ > 0 ? Real(restarts) / targets_ : 0.0;
    plainIterationsMean_ = targets_ > 0 ? Real(plainIterations) / targets_ : 0.0;
  }
  void step(Real) override {}
  void draw(DebugDraw& d) const override {
    const std::vector<Frame> f = forwardKinematics(rig_.skeleton, pose_);
    for (int j = 1; j < rig_.skeleton.jointCount(); ++j)
      d.capsule(f[static_cast<size_t>(rig_.skeleton.joint(j).parent)].position, f[static_cast<size_t>(j)].position,
                0.02, colors::kBlue);
    for (const Effector& e : rig_.effectors)
      d.capsule(f[static_cast<size_t>(e.joint)].position, effectorPosition(e, f), 0.02, colors::kBlue);
    for (const Vec3& g : lastGoals_) d.sphere(g, 0.05, colors::kRed);
    char label[128];
    std::snprintf(label, sizeof label, "%s: %d/%d solved, median %.1f us", solverName(options_.solver), successes_,
                  targets_, timeMedian_);
    d.text(Vec3(0.0, 1.2, 0.0), label, colors::kDark);
  }
  nlohmann::json metrics() const override {
    return {
        {"solver", solverName(options_.solver)},
        {"links", character_.skeleton.empty() && tree_ == BatchTree::None ? desc_.links : rig_.skeleton.jointCount()},
        {"joints", rig_.skeleton.jointCount()},
        {"effectors", rig_.effectors.size()},
        {"joint", !character_.skeleton.empty()  ? "skeleton"
                  : tree_ == BatchTree::Hand    ? "hand"
                  : tree_ == BatchTree::DoubleY ? "double-y"
                  : joint_ == BatchJoint::Hinge ? "hinge"
                                                : "ball"},
        {"targets", targets_},
        {"success_rate_no_restarts", targets_ > 0 ? Real(plainSuccesses_) / targets_ : 0.0},
        {"iterations_mean_no_restarts", plainIterationsMean_},
        {"restarts", options_.restarts},
        {"success_rate", targets_ > 0 ? Real(successes_) / targets_ : 0.0},
        {"residual_max", residualMax_},
        {"residual_median", residualMedian_},
        {"iterations_mean", iterationsMean_},
        {"limit_violations", violations_},
        {"restarts_mean", restartsMean_},
        {"solve_us_median", timeMedian_},
        {"solve_us_p95", timeP95_}};
  }
  std::optional<std::string> nonFiniteState() const override {
    for (Real v : pose_.dofs)
      if (!isFinite(v)) return "a joint angle is not finite";
    return std::nullopt;
  }

 private:
  ChainDesc desc_;
  BatchJoint joint_ = BatchJoint::Hinge;
  BatchTree tree_ = BatchTree::None;
  int targets_ = 100;
  SolveOptions options_;
  SolveWorkspace workspace_;  // reused by every solve of the batch
  Rig rig_;
  Pose pose_;
  SolveResult last_;
  std::vector<Vec3> lastGoals_;
  app::CharacterDesc character_{"", "", 1.7, degToRad(100.0)};
  int successes_ = 0, plainSuccesses_ = 0, violations_ = 0;
  Real plainIterationsMean_ = 0.0, residualMax_ = 0.0, residualMedian_ = 0.0, iterationsMean_ = 0.0,
       restartsMean_ = 0.0, timeMedian_ = 0.0, timeP95_ = 0.0;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Batch", "batch", pba::lab::BatchScene);
