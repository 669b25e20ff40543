#include "physics/core/types.h"

#include <cmath>

namespace pba {

bool isFinite(Real value) { return std::isfinite(value); }
bool isFinite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace pba
