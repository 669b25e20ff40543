// The not-implemented banner names only the open lab's unfinished exercises, in one short line: start-up
// probes record every stub of the course, and the banner used to list all of them in every lab.
#include <gtest/gtest.h>

#include "app/runner/exercise_catalog.h"

namespace pba::app {
namespace {

std::vector<ExerciseInfo> labOf(std::initializer_list<const char*> tags) {
  std::vector<ExerciseInfo> out;
  for (const char* t : tags) out.push_back({t, "lab", "title", 10, "hint"});
  return out;
}

TEST(ExerciseBanner, NamesOnlyTheOpenLabsStubsInCatalogOrder) {
  const std::vector<std::string> courseStubs = {"CLOTH-1", "HELLO-1", "HELLO-3", "IK-2", "RAG-1"};
  EXPECT_EQ(stubbedExercises(labOf({"HELLO-3", "HELLO-1", "HELLO-2"}), courseStubs),
            (std::vector<std::string>{"HELLO-3", "HELLO-1"}));
  EXPECT_TRUE(stubbedExercises(labOf({"HELLO-2"}), courseStubs).empty());
  EXPECT_TRUE(stubbedExercises({}, courseStubs).empty());
}

TEST(ExerciseBanner, IsOneShortLineThatCountsWhatItDoesNotName) {
  EXPECT_EQ(stubBannerText({}), "");
  const std::string two = stubBannerText({"IK-1", "IK-2"});
  EXPECT_EQ(two.rfind("IK-1, IK-2 not implemented", 0), 0u) << two;
  const std::string many = stubBannerText({"A-1", "A-2", "A-3", "A-4", "A-5"});
  EXPECT_EQ(many.rfind("A-1, A-2, A-3 and 2 more not implemented", 0), 0u) << many;
  EXPECT_EQ(many.find("A-4"), std::string::npos);
  for (const std::string& text : {two, many}) {
    EXPECT_EQ(text.find('\n'), std::string::npos);
    EXPECT_LE(text.size(), 110u) << "one line in lecture mode: " << text;
    EXPECT_NE(text.find("Exercises"), std::string::npos) << "points at the panel that lists them all";
  }
}

}  // namespace
}  // namespace pba::app
