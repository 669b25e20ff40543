// Demo scripts: a valid script loads every field; structural errors name the file and the step's field;
// checking a step against the registry catches unknown scenes and bad parameter values.
#include <gtest/gtest.h>

#include <fstream>

#include "app/runner/demo_script.h"
#include "app/runner/scene_file.h"

namespace pba::app {
namespace {

std::string writeScript(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(DemoScript, AValidScriptLoadsEveryFieldOfItsSteps) {
  const std::string path = writeScript("ok.json", R"({"title": "T", "chapter": "c.md", "steps": [
      {"title": "one", "lab": "test", "scene": "constant", "params": {"speed": 2}, "dt": 0.01, "paused": true,
       "camera": {"target": [1, 2, 3], "distance": 4, "yaw_deg": 90, "pitch_deg": 30}, "record": "a.mp4",
       "notes": "say this"},
      {"lab": "other", "scene": "x", "notes": "n"}]})");
  Result<DemoScript> s = loadDemoScript(path);
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s.value().steps.size(), 2u);
  const DemoStep& a = s.value().steps[0];
  EXPECT_EQ(a.title, "one");
  EXPECT_EQ(a.params["speed"], 2);
  EXPECT_EQ(*a.dt, 0.01);
  EXPECT_TRUE(a.paused);
  EXPECT_EQ(a.record, "a.mp4");
  ASSERT_TRUE(a.camera);
  EXPECT_EQ(a.camera->target, Vec3(1, 2, 3));
  EXPECT_DOUBLE_EQ(a.camera->yaw, kPi / 2);
  EXPECT_TRUE(checkDemoStep(s.value(), 0).ok());
}

TEST(DemoScript, StructuralErrorsNameTheFileAndTheStepsField) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"title": "T", "steps": [{"lab": "test", "scene": "constant"}]})", "steps[0].notes: missing"},
      {R"({"title": "T", "steps": [{"lab": "test", "scene": "constant", "notes": "", "sound": 1}]})",
       "steps[0].sound: unknown key"},
      {R"({"title": "T", "steps": [{"lab": "test", "scene": "constant", "notes": "", "dt": 5}]})",
       "steps[0].dt: must be a number in [1e-06, 0.1] s, got 5"},
      {R"({"title": "T", "steps": [{"lab": "test", "scene": "constant", "notes": "", "camera": {"distance": -1}}]})",
       "steps[0].camera.distance: must be a number in [0.01, 10000] m, got -1"},
      {R"({"title": "T", "steps": []})", "steps: expected a non-empty list of steps"},
      {"{\"title\": \"T\",\n \"steps\": [,]}", "line 2: not valid JSON"},
  };
  int i = 0;
  for (const auto& [text, expected] : cases) {
    const std::string path = writeScript("bad" + std::to_string(i++) + ".json", text);
    Result<DemoScript> s = loadDemoScript(path);
    ASSERT_FALSE(s) << text;
    EXPECT_EQ(s.error().rfind(path + ": ", 0), 0u) << s.error();
    EXPECT_NE(s.error().find(expected), std::string::npos) << s.error();
  }
}

TEST(DemoScript, CheckingAStepFindsAnUnknownSceneAndABadParameter) {
  const std::string path = writeScript("check.json", R"({"title": "T", "steps": [
      {"lab": "test", "scene": "nope", "notes": ""},
      {"lab": "test", "scene": "constant", "params": {"speed": 99}, "notes": ""}]})");
  Result<DemoScript> s = loadDemoScript(path);
  ASSERT_TRUE(s) << s.error();
  EXPECT_EQ(checkDemoStep(s.value(), 0).error(), path + ": steps[0].scene: unknown scene 'nope' of lab 'test'");
  EXPECT_EQ(checkDemoStep(s.value(), 1).error(), path + ": steps[1].params.speed: must be in [0, 10] m/s, got 99");
}

TEST(CameraBookmark, ASceneFileCarriesItsCameraThroughSaveAndLoadAndABadOneIsNamed) {
  Result<LoadedScene> loaded = parseSceneJson(
      R"({"lab": "test", "scene": "constant", "camera": {"target": [0, 1, 0], "distance": 6, "yaw_deg": 45, "pitch_deg": 20}})",
      "f.json", "test");
  ASSERT_TRUE(loaded) << loaded.error();
  ASSERT_TRUE(loaded.value().camera);
  EXPECT_DOUBLE_EQ(loaded.value().camera->distance, 6.0);
  const nlohmann::json saved =
      sceneToJson("test", "constant", *loaded.value().scene, std::nullopt, loaded.value().camera);
  Result<LoadedScene> again = parseSceneJson(saved.dump(), "g.json", "test");
  ASSERT_TRUE(again) << again.error();
  EXPECT_EQ(again.value().camera->target, loaded.value().camera->target);
  EXPECT_DOUBLE_EQ(again.value().camera->yaw, loaded.value().camera->yaw);
  EXPECT_DOUBLE_EQ(again.value().camera->pitch, loaded.value().camera->pitch);
  Result<LoadedScene> bad =
      parseSceneJson(R"({"lab": "test", "scene": "constant", "camera": {"pitch_deg": 95}})", "h.json", "test");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error(), "h.json: camera.pitch_deg: must be a number in [-89, 89], got 95");
}

}  // namespace
}  // namespace pba::app
