// One GoogleTest test and one gMock matcher, run under Wine by `./pba cross windows`.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <thread>

TEST(CrossSmoke, ThreadsAndMatchers) {
  int value = 0;
  std::thread worker([&] { value = 42; });
  worker.join();
  EXPECT_EQ(value, 42);
  EXPECT_THAT(std::vector<int>({1, 2, 3}), ::testing::ElementsAre(1, 2, 3));
}
