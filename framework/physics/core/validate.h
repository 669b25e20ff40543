#pragma once
// Boundary validation helpers: each returns a Status whose message names the field and the rule.
#include <string_view>

#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba {

/// The messages of the checks below, built only when a check fails (validate.cpp).
Status rangeError(std::string_view field, Real value, Real lo, Real hi);
Status positiveError(std::string_view field, Real value);
Status finiteError(std::string_view field, const Vec3& value);

// The checks are inline: one that passes costs its comparisons (a solve validates its options every
// call), one that fails builds its message out of line.

/// value must be finite and in [lo, hi]. field is the dotted name shown to the user ("drop.mass").
inline Status checkRange(std::string_view field, Real value, Real lo, Real hi) {
  if (isFinite(value) && value >= lo && value <= hi) return Status::success();
  return rangeError(field, value, lo, hi);
}
/// value must be finite and > 0 (time steps, masses, lengths).
inline Status checkPositive(std::string_view field, Real value) {
  if (isFinite(value) && value > 0.0) return Status::success();
  return positiveError(field, value);
}
/// every component finite.
inline Status checkFinite(std::string_view field, const Vec3& value) {
  if (isFinite(value)) return Status::success();
  return finiteError(field, value);
}

}  // namespace pba
