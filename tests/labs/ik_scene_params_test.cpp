// Every solver setting of the IK lab's scenes at both ends of its declared range (the slider
// extremes, the command line's limits) is a valid solve: no status "invalid_input", finite pose.
// The panel's ranges and SolveOptions' validation (ik/solve_options.cpp) must agree, or a slider
// extreme would make every solve fail.
#include <gtest/gtest.h>

#include "app/runner/scene_registry.h"
#include "physics/core/format.h"

namespace pba::lab {
namespace {

TEST(IkSceneParams, EverySettingAtBothEndsOfItsRangeGivesAValidSolve) {
  for (const char* name : {"limits", "tree", "two-bone"}) {
    const app::SceneEntry* entry = app::findScene(name);
    ASSERT_TRUE(entry) << name;
    const std::vector<app::Param> params = entry->create()->params().all();
    for (const app::Param& p : params) {
      if (p.kind != app::ParamKind::Real && p.kind != app::ParamKind::Integer) continue;
      for (double value : {p.min, p.max}) {
        std::unique_ptr<app::Scene> scene = entry->create();
        const std::string text = formatExact(value);  // min and max are in the units of the text (degrees for angles)
        ASSERT_TRUE(scene->params().setFromText(p.name, text).ok()) << name << " " << p.name << " = " << text;
        scene->reset();
        scene->step(1.0 / 60.0);
        const nlohmann::json m = scene->metrics();
        SCOPED_TRACE(::testing::Message() << name << ": " << p.name << " = " << text);
        EXPECT_NE(m.value("status", std::string()), "invalid_input");
        EXPECT_FALSE(scene->nonFiniteState().has_value());
      }
    }
  }
}

}  // namespace
}  // namespace pba::lab
