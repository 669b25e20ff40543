#include "physics/core/validate.h"

#include <string>

#include "physics/core/format.h"

namespace pba {
namespace {
std::string describe(Real v) { return formatExact(v); }
}  // namespace

Status checkRange(std::string_view field, Real value, Real lo, Real hi) {
  if (isFinite(value) && value >= lo && value <= hi) return Status::success();
  return Error{std::string(field) + ": must be in [" + describe(lo) + ", " + describe(hi) + "], got " +
               describe(value)};
}

Status checkPositive(std::string_view field, Real value) {
  if (isFinite(value) && value > 0.0) return Status::success();
  return Error{std::string(field) + ": must be a finite number > 0, got " + describe(value)};
}

Status checkFinite(std::string_view field, const Vec3& v) {
  if (isFinite(v)) return Status::success();
  return Error{std::string(field) + ": must be finite, got (" + describe(v.x) + ", " + describe(v.y) + ", " +
               describe(v.z) + ")"};
}

}  // namespace pba
