// The IK methods' name tables and the validation of SolveOptions (solver.h).
#include <array>
#include <limits>
#include <string>
#include <string_view>

#include "physics/core/format.h"
#include "physics/core/validate.h"
#include "physics/ik/solver.h"

namespace pba::ik {

namespace {

constexpr std::array<SolverInfo, 9> kSolvers = {{
    {SolverKind::Analytic, "analytic", "Analytic"},
    {SolverKind::Ccd, "ccd", "Cyclic coordinate descent"},
    {SolverKind::Fabrik, "fabrik", "FABRIK"},
    {SolverKind::JacobianTranspose, "jt", "Jacobian transpose"},
    {SolverKind::PseudoInverse, "pinv", "Pseudo-inverse (SVD)"},
    {SolverKind::DampedLeastSquares, "dls", "Damped least squares"},
    {SolverKind::SelectivelyDamped, "sdls", "Selectively damped least squares"},
    {SolverKind::GradientDescent, "gradient", "Gradient descent"},
    {SolverKind::Lbfgs, "lbfgs", "L-BFGS (quasi-Newton)"},
}};

constexpr bool tableInEnumOrder() {
  for (size_t i = 0; i < kSolvers.size(); ++i)
    if (static_cast<size_t>(kSolvers[i].kind) != i) return false;
  return true;
}
static_assert(tableInEnumOrder(), "kSolvers must list the methods in SolverKind order");

template <typename Enum>
bool inTable(Enum e, const std::vector<std::string>& names) {
  return static_cast<size_t>(e) < names.size();  // a negative value wraps to a huge one
}

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();

Status checkNonNegative(std::string_view field, Real value) { return checkRange(field, value, 0.0, kInfinity); }

// The messages of the two checks below, built only when a check fails (as validate.h's checks; out of
// line, so that the checks stay small enough to inline).
[[gnu::noinline]] Status belowOneError(const char* field, Real value) {
  return Error{std::string(field) + ": must be in [0, 1), got " + formatExact(value)};
}
[[gnu::noinline]] Status atLeastError(const char* field, long long value, long long lowest) {
  return Error{std::string(field) + ": must be >= " + std::to_string(lowest) + ", got " + std::to_string(value)};
}

Status checkBelowOne(const char* field, Real value) {
  if (isFinite(value) && value >= 0.0 && value < 1.0) return Status::success();
  return belowOneError(field, value);
}

Status checkAtLeast(const char* field, long long value, long long lowest) {
  if (value >= lowest) return Status::success();
  return atLeastError(field, value, lowest);
}

}  // namespace

std::span<const SolverInfo> solverTable() { return kSolvers; }
const char* solverName(SolverKind k) { return kSolvers[static_cast<size_t>(k)].name; }
const char* solverLongName(SolverKind k) { return kSolvers[static_cast<size_t>(k)].longName; }

bool solverFromName(const std::string& name, SolverKind* kind) {
  for (const SolverInfo& s : kSolvers)
    if (name == s.name) {
      *kind = s.kind;
      return true;
    }
  return false;
}

std::vector<std::string> solverNames() {
  std::vector<std::string> names;
  for (const SolverInfo& s : kSolvers) names.emplace_back(s.name);
  return names;
}

const std::vector<std::string>& lineSearchNames() {
  static const std::vector<std::string> names = {"fixed", "backtracking", "golden"};
  return names;
}
const char* lineSearchName(LineSearch s) { return lineSearchNames()[static_cast<size_t>(s)].c_str(); }

const std::vector<std::string>& jacobianLimitModeNames() {
  static const std::vector<std::string> names = {"clamp", "zero_columns"};
  return names;
}

const std::vector<std::string>& jacobianSourceNames() {
  static const std::vector<std::string> names = {"analytic", "differences"};
  return names;
}

Status validate(const SolveOptions& o) {
  // One check after the other, the first failure returned (every solve starts here: a valid set
  // builds no message and no table of results).
  if (static_cast<size_t>(o.solver) >= kSolvers.size()) return Error{"options.solver: no such method"};
  if (Status s = checkPositive("options.tolerance", o.tolerance); !s) return s;
  if (Status s = checkPositive("options.angleTolerance", o.angleTolerance); !s) return s;
  if (Status s = checkAtLeast("options.maxIterations", o.maxIterations, 1); !s) return s;
  if (Status s = checkNonNegative("options.maxSeconds", o.maxSeconds); !s) return s;
  if (Status s = checkAtLeast("options.stallIterations", o.stallIterations, 0); !s) return s;
  if (Status s = checkBelowOne("options.stallRatio", o.stallRatio); !s) return s;
  if (!inTable(o.limitMode, jacobianLimitModeNames())) return Error{"options.limitMode: no such mode"};
  if (!inTable(o.jacobian, jacobianSourceNames())) return Error{"options.jacobian: no such source"};
  if (Status s = checkNonNegative("options.damping", o.damping); !s) return s;
  if (Status s = checkBelowOne("options.singularCutoff", o.singularCutoff); !s) return s;
  if (Status s = checkNonNegative("options.maxErrorStep", o.maxErrorStep); !s) return s;
  if (Status s = checkNonNegative("options.maxJointStep", o.maxJointStep); !s) return s;
  if (Status s = checkNonNegative("options.orientationScale", o.orientationScale); !s) return s;
  if (Status s = checkFinite("options.polePoint", o.polePoint); !s) return s;
  if (!inTable(o.lineSearch, lineSearchNames())) return Error{"options.lineSearch: no such line search"};
  if (Status s = checkPositive("options.gradientStep", o.gradientStep); !s) return s;
  if (Status s = checkPositive("options.lineSearchMaxStep", o.lineSearchMaxStep); !s) return s;
  if (Status s = checkAtLeast("options.lbfgsMemory", o.lbfgsMemory, 1); !s) return s;
  if (Status s = checkAtLeast("options.restarts", o.restarts, 0); !s) return s;
  return Status::success();
}

}  // namespace pba::ik
