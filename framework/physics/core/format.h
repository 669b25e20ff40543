#pragma once
// Number formatting for messages (validation errors, guard messages, labels). One place, so that
// every message prints numbers the same way.
#include <string>

#include "physics/core/types.h"

namespace pba {

/// Shortest text that reads back to the same double (std::to_chars): for values a user must copy
/// exactly. NaN and infinities read "nan", "inf", "-inf".
std::string formatExact(Real value);
/// Compact text ("%g", 6 significant digits): for ranges and bounds.
std::string formatShort(Real value);
/// Fixed number of decimals, e.g. formatFixed(1.23456, 3) == "1.235".
std::string formatFixed(Real value, int decimals);

}  // namespace pba
