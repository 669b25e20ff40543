#pragma once
// A fast path against the scalar route it replaces, to the bit (docs/architecture.md §5, "Fast paths").
#include <cstddef>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "physics/core/types.h"

namespace pba::test {

/// Every vector of `fast` has the same bits as the one of `scalar` at its index. The failure names the
/// first that differs ("particle i" followed by `what`).
inline ::testing::AssertionResult sameBits(const std::vector<Vec3>& scalar, const std::vector<Vec3>& fast,
                                           const char* what = "") {
  if (scalar.size() != fast.size())
    return ::testing::AssertionFailure() << "scalar has " << scalar.size() << " vectors, fast " << fast.size();
  for (std::size_t i = 0; i < scalar.size(); ++i) {
    if (std::memcmp(&scalar[i], &fast[i], sizeof(Vec3)) != 0)
      return ::testing::AssertionFailure()
             << "particle " << i << what << ": scalar (" << scalar[i].x << ", " << scalar[i].y << ", " << scalar[i].z
             << "), fast (" << fast[i].x << ", " << fast[i].y << ", " << fast[i].z << ")";
  }
  return ::testing::AssertionSuccess();
}

}  // namespace pba::test
