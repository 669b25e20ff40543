#include "physics/animation/channel.h"

#include <algorithm>
#include <cmath>

namespace pba::animation {

namespace {
constexpr Real kSameTime = 1e-9;  // [s] two keys closer than this are "at equal times"
}

namespace detail {

Result<int> insertionIndex(const std::vector<Real>& times, Real time, const std::string& field) {
  const auto it = std::lower_bound(times.begin(), times.end(), time - kSameTime);
  if (it != times.end() && std::abs(*it - time) <= kSameTime)
    return Error{field + ": a key is already at " + formatShort(time) + " s (keys must be at distinct times)"};
  return static_cast<int>(it - times.begin());
}

Status checkIncreasing(const std::vector<Real>& times, const std::string& field) {
  for (size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k])) return Error{field + ": key " + std::to_string(k) + " has a non-finite time"};
    if (k > 0 && times[k] <= times[k - 1] + kSameTime)
      return Error{field + ": keys " + std::to_string(k - 1) + " and " + std::to_string(k) + " at equal times (" +
                   formatShort(times[k]) + " s)"};
  }
  return Status::success();
}

}  // namespace detail

Result<int> RotationChannel::insert(Real time, const Quat& q) {
  if (!std::isfinite(time)) return Error{"key time: must be finite"};
  const Result<int> at = detail::insertionIndex(times_, time, "key time");
  if (!at.ok()) return at;
  times_.insert(times_.begin() + at.value(), time);
  keys_.insert(keys_.begin() + at.value(), glm::normalize(q));
  return at;
}

void RotationChannel::remove(int k) {
  times_.erase(times_.begin() + k);
  keys_.erase(keys_.begin() + k);
}

Result<int> RotationChannel::move(int k, Real time) {
  const Quat q = value(k);
  const Real old = this->time(k);
  remove(k);
  const Result<int> at = insert(time, q);
  if (!at.ok()) static_cast<void>(insert(old, q));
  return at;
}

}  // namespace pba::animation
