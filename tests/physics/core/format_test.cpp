// formatExact: the shortest text that reads back to the same double, as messages quote values.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "physics/core/format.h"

namespace pba {
namespace {

TEST(FormatExact, PrintsTheShortestTextThatReadsBackExactly) {
  EXPECT_EQ(formatExact(-0.1), "-0.1");  // "%.17g" printed -0.10000000000000001
  EXPECT_EQ(formatExact(0.30000000000000004), "0.30000000000000004");
  EXPECT_EQ(formatExact(1e308), "1e+308");
  EXPECT_EQ(formatExact(1.5), "1.5");
}

TEST(FormatExact, WholeNumbersPrintAsIntegers) {
  EXPECT_EQ(formatExact(10.0), "10");
  EXPECT_EQ(formatExact(2000000.0), "2000000");
  EXPECT_EQ(formatExact(-4.0), "-4");
}

TEST(FormatExact, EveryTextReadsBackToTheSameDoubleOverRandomValues) {
  std::mt19937_64 rng(13);  // fixed seed
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int i = 0; i < 10000; ++i) {
    const std::uint64_t b = bits(rng);
    double v;
    std::memcpy(&v, &b, sizeof v);
    if (!std::isfinite(v)) continue;
    EXPECT_EQ(std::strtod(formatExact(v).c_str(), nullptr), v) << "seed 13, case " << i << ": " << formatExact(v);
  }
}

}  // namespace
}  // namespace pba
