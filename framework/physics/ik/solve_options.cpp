// The IK methods' name tables and the validation of SolveOptions (solver.h).
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <utility>

#include "physics/core/format.h"
#include "physics/core/validate.h"
#include "physics/ik/solver.h"

namespace pba::ik {

namespace {

constexpr auto kSolvers = enumNames<SolverKind>({
    {SolverKind::Analytic, "analytic", "Analytic"},
    {SolverKind::Ccd, "ccd", "Cyclic coordinate descent"},
    {SolverKind::Fabrik, "fabrik", "FABRIK"},
    {SolverKind::JacobianTranspose, "jt", "Jacobian transpose"},
    {SolverKind::PseudoInverse, "pinv", "Pseudo-inverse (SVD)"},
    {SolverKind::DampedLeastSquares, "dls", "Damped least squares"},
    {SolverKind::SelectivelyDamped, "sdls", "Selectively damped least squares"},
    {SolverKind::GradientDescent, "gradient", "Gradient descent"},
    {SolverKind::Lbfgs, "lbfgs", "L-BFGS (quasi-Newton)"},
});
constexpr auto kLineSearches = enumNames<LineSearch>(
    {{LineSearch::Fixed, "fixed"}, {LineSearch::Backtracking, "backtracking"}, {LineSearch::GoldenSection, "golden"}});
constexpr auto kLimitModes = enumNames<JacobianLimitMode>(
    {{JacobianLimitMode::Clamp, "clamp"}, {JacobianLimitMode::ZeroColumns, "zero_columns"}});
constexpr auto kJacobianSources = enumNames<JacobianSource>(
    {{JacobianSource::Analytic, "analytic"}, {JacobianSource::CentralDifferences, "differences"}});

template <typename Enum>
bool inTable(Enum e, const std::vector<std::string>& names) {
  return static_cast<size_t>(e) < names.size();  // a negative value wraps to a huge one
}

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();

// The checks of validate(): each is true when its value passes, else it sets *error to the message,
// which is built only then (every solve validates its options). validate.h's checks where they exist;
// the two messages of its own below.
[[gnu::noinline]] Status belowOneError(std::string_view field, Real value) {
  return Error{std::string(field) + ": must be in [0, 1), got " + formatExact(value)};
}
[[gnu::noinline]] Status atLeastError(std::string_view field, long long value, long long lowest) {
  return Error{std::string(field) + ": must be >= " + std::to_string(lowest) + ", got " + std::to_string(value)};
}

bool passes(Status status, Status* error) {
  if (status) return true;
  *error = std::move(status);
  return false;
}
bool positive(std::string_view field, Real value, Status* error) { return passes(checkPositive(field, value), error); }
bool nonNegative(std::string_view field, Real value, Status* error) {
  return passes(checkRange(field, value, 0.0, kInfinity), error);
}
bool finite(std::string_view field, const Vec3& value, Status* error) {
  return passes(checkFinite(field, value), error);
}
bool belowOne(std::string_view field, Real value, Status* error) {
  if (std::isfinite(value) && value >= 0.0 && value < 1.0) return true;
  *error = belowOneError(field, value);
  return false;
}
bool atLeast(std::string_view field, long long value, long long lowest, Status* error) {
  if (value >= lowest) return true;
  *error = atLeastError(field, value, lowest);
  return false;
}

}  // namespace

// Every name is a string literal, so the views' data() end in a NUL.
std::span<const SolverInfo> solverTable() { return kSolvers.entries; }
const char* solverName(SolverKind k) { return kSolvers.name(k).data(); }
const char* solverLongName(SolverKind k) { return kSolvers.description(k).data(); }

bool solverFromName(const std::string& name, SolverKind* kind) {
  const std::optional<SolverKind> k = kSolvers.parse(name);
  if (k) *kind = *k;
  return k.has_value();
}

std::vector<std::string> solverNames() { return kSolvers.names(); }

const std::vector<std::string>& lineSearchNames() {
  static const std::vector<std::string> names = kLineSearches.names();
  return names;
}
const char* lineSearchName(LineSearch s) { return kLineSearches.name(s).data(); }

const std::vector<std::string>& jacobianLimitModeNames() {
  static const std::vector<std::string> names = kLimitModes.names();
  return names;
}

const std::vector<std::string>& jacobianSourceNames() {
  static const std::vector<std::string> names = kJacobianSources.names();
  return names;
}

Status validate(const SolveOptions& o) {
  // One check after the other, the first failure returned (every solve starts here: a passing check
  // costs its comparisons and builds no message).
  Status e;
  if (static_cast<size_t>(o.solver) >= kSolvers.size()) return Error{"options.solver: no such method"};
  if (!positive("options.tolerance", o.tolerance, &e) || !positive("options.angleTolerance", o.angleTolerance, &e) ||
      !atLeast("options.maxIterations", o.maxIterations, 1, &e) ||
      !nonNegative("options.maxSeconds", o.maxSeconds, &e) ||
      !atLeast("options.stallIterations", o.stallIterations, 0, &e) ||
      !belowOne("options.stallRatio", o.stallRatio, &e))
    return e;
  if (!inTable(o.limitMode, jacobianLimitModeNames())) return Error{"options.limitMode: no such mode"};
  if (!inTable(o.jacobian, jacobianSourceNames())) return Error{"options.jacobian: no such source"};
  if (!nonNegative("options.damping", o.damping, &e) || !belowOne("options.singularCutoff", o.singularCutoff, &e) ||
      !nonNegative("options.maxErrorStep", o.maxErrorStep, &e) ||
      !nonNegative("options.maxJointStep", o.maxJointStep, &e) ||
      !nonNegative("options.orientationScale", o.orientationScale, &e) || !finite("options.polePoint", o.polePoint, &e))
    return e;
  if (!inTable(o.lineSearch, lineSearchNames())) return Error{"options.lineSearch: no such line search"};
  if (!positive("options.gradientStep", o.gradientStep, &e) ||
      !positive("options.lineSearchMaxStep", o.lineSearchMaxStep, &e) ||
      !atLeast("options.lbfgsMemory", o.lbfgsMemory, 1, &e) || !atLeast("options.restarts", o.restarts, 0, &e) ||
      !nonNegative("options.ccdMaxTurn", o.ccdMaxTurn, &e))
    return e;
  return Status::success();
}

}  // namespace pba::ik
