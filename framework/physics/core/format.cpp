#include "physics/core/format.h"

#include <cstdio>
#include <cstdlib>

namespace pba {

std::string formatExact(Real value) {
  // The fewest significant digits that read back to the same double (-0.1, not -0.10000000000000001);
  // 17 always do.
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    if (std::strtod(buf, nullptr) == value) break;
  }
  return buf;
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
