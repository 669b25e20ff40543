#pragma once
#include <cfenv>

namespace pba::testing {

inline constexpr int kTrappedExceptions = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;

inline void enableFloatingPointTraps() {
  std::feclearexcept(FE_ALL_EXCEPT);
  feenableexcept(kTrappedExceptions);
}

/// Scope guard for the few tests that create NaN or Inf on purpose (e.g. the instability guard).
class FloatingPointTrapsOff {
 public:
  FloatingPointTrapsOff() : previous_(fegetexcept()) { fedisableexcept(FE_ALL_EXCEPT); }
  ~FloatingPointTrapsOff() {
    std::feclearexcept(FE_ALL_EXCEPT);
    feenableexcept(previous_);
  }
  FloatingPointTrapsOff(const FloatingPointTrapsOff&) = delete;
  FloatingPointTrapsOff& operator=(const FloatingPointTrapsOff&) = delete;

 private:
  int previous_;
};

}  // namespace pba::testing
