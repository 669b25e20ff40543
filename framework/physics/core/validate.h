#pragma once
// Boundary validation helpers: each returns a Status whose message names the field and the rule.
#include <string_view>

#include "physics/core/result.h"
#include "physics/core/types.h"

namespace pba {

/// value must be finite and in [lo, hi]. field is the dotted name shown to the user ("drop.mass").
Status checkRange(std::string_view field, Real value, Real lo, Real hi);
/// value must be finite and > 0 (time steps, masses, lengths).
Status checkPositive(std::string_view field, Real value);
/// every component finite.
Status checkFinite(std::string_view field, const Vec3& value);

}  // namespace pba
