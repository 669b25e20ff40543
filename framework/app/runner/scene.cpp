#include "app/runner/scene.h"

#include <algorithm>
#include <cmath>

namespace pba::app {

std::optional<PickHit> pickSphere(const Ray& ray, const Vec3& center, Real radius, int handle) {
  const std::optional<Real> t = intersectRaySphere(ray, center, radius);
  if (!t) return std::nullopt;
  return PickHit{handle, *t, pointAt(ray, *t)};
}

std::optional<Real> Scene::energyGainBound(Real reference) const {
  return kPassiveEnergySlack * std::max(std::abs(reference), kMinEnergyScale);
}

}  // namespace pba::app
