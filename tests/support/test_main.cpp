// Test main for every GoogleTest suite: floating-point traps on (docs/architecture.md §7), so an invalid
// operation, a division by zero or an overflow stops the test at the offending line (SIGFPE).
// Tests that must produce NaN on purpose wrap it in pba::testing::FloatingPointTrapsOff.
#include <gtest/gtest.h>

#include "support/fp_traps.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  pba::testing::enableFloatingPointTraps();
  return RUN_ALL_TESTS();
}
