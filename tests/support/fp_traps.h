// Floating-point traps for the test mains (invalid, divide-by-zero, overflow): a NaN or an infinity
// stops the test at the operation that made it. glibc has feenableexcept; Windows' C runtime unmasks
// exceptions through _controlfp_s; elsewhere (macOS, libc++ on other C libraries, MinGW's headers
// without _controlfp_s) the traps are not available and the tests run without them, checking
// finiteness through their own assertions.
#pragma once
#include <cfenv>

#if defined(_MSC_VER) || (defined(_WIN32) && defined(__MINGW32__))
#include <float.h>
#define PBA_FP_TRAPS_WINDOWS 1
#elif defined(__GLIBC__)
#define PBA_FP_TRAPS_GLIBC 1
#endif

namespace pba::testing {

#if defined(PBA_FP_TRAPS_WINDOWS)
inline constexpr unsigned kTrappedExceptions = _EM_INVALID | _EM_ZERODIVIDE | _EM_OVERFLOW;
/// The currently unmasked (trapping) exceptions among kTrappedExceptions.
inline unsigned trappedNow() {
  unsigned control = 0;
  _controlfp_s(&control, 0, 0);
  return ~control & kTrappedExceptions;
}
inline void setTrapped(unsigned trapped) {
  unsigned control = 0;
  _clearfp();
  _controlfp_s(&control, ~trapped & kTrappedExceptions, kTrappedExceptions);
}
#elif defined(PBA_FP_TRAPS_GLIBC)
inline constexpr int kTrappedExceptions = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;
inline int trappedNow() { return fegetexcept(); }
inline void setTrapped(int trapped) {
  std::feclearexcept(FE_ALL_EXCEPT);
  fedisableexcept(FE_ALL_EXCEPT);
  feenableexcept(trapped);
}
#else
inline constexpr int kTrappedExceptions = 0;
inline int trappedNow() { return 0; }
inline void setTrapped(int) { std::feclearexcept(FE_ALL_EXCEPT); }
#endif

/// True where this build can trap floating-point exceptions.
inline constexpr bool kFloatingPointTrapsAvailable = kTrappedExceptions != 0;

inline void enableFloatingPointTraps() { setTrapped(kTrappedExceptions); }

/// Scope guard for the few tests that create NaN or Inf on purpose (e.g. the instability guard).
class FloatingPointTrapsOff {
 public:
  FloatingPointTrapsOff() : previous_(trappedNow()) { setTrapped(0); }
  ~FloatingPointTrapsOff() { setTrapped(previous_); }
  FloatingPointTrapsOff(const FloatingPointTrapsOff&) = delete;
  FloatingPointTrapsOff& operator=(const FloatingPointTrapsOff&) = delete;

 private:
  decltype(trappedNow()) previous_;
};

}  // namespace pba::testing
