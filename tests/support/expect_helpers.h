#pragma once
// Typed expectations for vectors. Tolerances are chosen per test and explained at the call site.
#include <gtest/gtest.h>

#include "physics/core/types.h"

#define EXPECT_VEC3_NEAR(actual, expected, tolerance)                          \
  do {                                                                         \
    const ::pba::Vec3 pbaActual_ = (actual);                                   \
    const ::pba::Vec3 pbaExpected_ = (expected);                               \
    EXPECT_NEAR(pbaActual_.x, pbaExpected_.x, (tolerance)) << "x of " #actual; \
    EXPECT_NEAR(pbaActual_.y, pbaExpected_.y, (tolerance)) << "y of " #actual; \
    EXPECT_NEAR(pbaActual_.z, pbaExpected_.z, (tolerance)) << "z of " #actual; \
  } while (0)
