#pragma once
// An orthonormal basis around a unit vector, for drawing circles and cones and sampling directions about
// an axis. Duff, Burgess, Christensen, Hery, Kensler, Liani & Villemin, "Building an Orthonormal Basis,
// Revisited", JCGT 6(1), 2017, Listing 3: branch-free apart from the sign, continuous except across
// n.z = 0, exact orthonormality for unit n (no normalisation, no nearly parallel reference vector).
#include <cmath>

#include "physics/core/types.h"

namespace pba {

/// Unit tangent and bitangent with (tangent, bitangent, n) right-handed; n must be a unit vector.
struct Basis {
  Vec3 tangent;
  Vec3 bitangent;
};
inline Basis orthonormalBasis(const Vec3& n) {
  const Real sign = std::copysign(1.0, n.z);
  const Real a = -1.0 / (sign + n.z);
  const Real b = n.x * n.y * a;
  return {Vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3(b, sign + n.y * n.y * a, -n.y)};
}

}  // namespace pba
