#include "physics/core/validate.h"

#include <string>

#include "physics/core/format.h"

namespace pba {
namespace {
std::string describe(Real v) { return formatExact(v); }
}  // namespace

Status rangeError(std::string_view field, Real value, Real lo, Real hi) {
  return Error{std::string(field) + ": must be in [" + describe(lo) + ", " + describe(hi) + "], got " +
               describe(value)};
}

Status positiveError(std::string_view field, Real value) {
  return Error{std::string(field) + ": must be a finite number > 0, got " + describe(value)};
}

Status finiteError(std::string_view field, const Vec3& v) {
  return Error{std::string(field) + ": must be finite, got (" + describe(v.x) + ", " + describe(v.y) + ", " +
               describe(v.z) + ")"};
}

}  // namespace pba
