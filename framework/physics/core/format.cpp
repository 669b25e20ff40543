#include "physics/core/format.h"

#include <cfenv>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace pba {

std::string formatExact(Real value) {
  // std::to_chars without a format is the shortest text that reads back to the same double, in fixed or
  // scientific notation, whichever is shorter (-0.1, not -0.10000000000000001; 10, not 1e+01).
  // Whole numbers below 2^53 print as integers (2000000, not 2e+06), as "%.17g" did.
  char buf[40];
  const bool whole = std::isfinite(value) && std::abs(value) < 9007199254740992.0 && value == std::floor(value);
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  const std::to_chars_result r = whole ? std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed)
                                       : std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, r.ptr);
#else
  // Standard libraries without floating-point to_chars (libc++ before 17, macOS before 13.3): the
  // fewest significant digits that read back to the same double, found by trying 1 to 17 ("%.17g"
  // always does). Same value on reading; the notation may differ in rare cases (1e+20 for 1e20).
  if (whole) {
    std::snprintf(buf, sizeof buf, "%.0f", value);
    return buf;
  }
  // A too-short text of a value near the largest double reads back as infinity and raises the overflow
  // flag: the floating-point environment is held (flags kept, traps off) while trying.
  std::fenv_t environment;
  std::feholdexcept(&environment);
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    if (!std::isfinite(value) || std::strtod(buf, nullptr) == value) break;
  }
  std::fesetenv(&environment);
  return buf;
#endif
}

std::string formatShort(Real value) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", value);
  return buf;
}

std::string formatFixed(Real value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

}  // namespace pba
