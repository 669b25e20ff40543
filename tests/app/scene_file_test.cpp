// Scene files: errors name the file, the field and (for syntax errors) the line; load → save →
// load is exact; a bad file never replaces the running scene.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "app/runner/scene_file.h"
#include "app/runner/scene_runner.h"
#include "app/window/lab_session.h"
#include "test_scenes.h"

namespace pba::app {
namespace {
using testing::ConstantVelocityScene;

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("pba_scene_file_test_" + name)).string();
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(SceneFile, SyntaxErrorNamesTheFileAndTheLine) {
  const auto r = parseSceneJson("{\n  \"lab\": \"test\",\n  \"scene\": \"constant\",,\n}\n", "bad.json", "test");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().rfind("bad.json: line 3: not valid JSON", 0), 0u) << r.error();
}

TEST(SceneFile, FieldErrorsNameTheField) {
  auto error = [](const std::string& text) { return parseSceneJson(text, "f.json", "test").error(); };
  EXPECT_EQ(error(R"({"lab": "test", "scene": "constant", "params": {"speed": 99}})"),
            "f.json: params.speed: must be in [0, 10] m/s, got 99");
  EXPECT_EQ(error(R"({"lab": "test", "scene": "constant", "params": {"sped": 1}})"),
            "f.json: params.sped: no such parameter in this scene");
  EXPECT_EQ(error(R"({"lab": "other", "scene": "constant"})"), "f.json: lab: this file is for lab 'other', not 'test'");
  EXPECT_EQ(error(R"({"lab": "test", "scene": "nope"})"), "f.json: scene: unknown scene 'nope' (see --list-scenes)");
  EXPECT_EQ(error(R"({"lab": "test"})"), "f.json: scene: missing or not a string");
  EXPECT_EQ(error(R"({"lab": "test", "scene": "constant", "speed": 1})"),
            "f.json: speed: unknown key (expected lab, scene, dt, params, camera, description)");
  EXPECT_NE(error(R"({"lab": "test", "scene": "constant", "dt": 0})").find("f.json: dt:"), std::string::npos);
  EXPECT_NE(error(R"([1, 2])").find("top level"), std::string::npos);
  EXPECT_NE(loadSceneFile(tempPath("does-not-exist.json"), "test").error().find("cannot open"), std::string::npos);
}

TEST(SceneFile, LoadSaveLoadIsExact) {
  const std::string first = tempPath("first.json"), second = tempPath("second.json");
  write(first, R"({"lab": "test", "scene": "constant", "dt": 0.003,
                   "params": {"speed": 0.30000000000000004, "count": 5, "visible": false, "mode": "second", "heading": 12.5}})");
  auto a = loadSceneFile(first, "test");
  ASSERT_TRUE(a.ok()) << a.error();
  ASSERT_TRUE(saveSceneFile(second, "test", a.value().name, *a.value().scene, a.value().dt).ok());
  auto b = loadSceneFile(second, "test");
  ASSERT_TRUE(b.ok()) << b.error();
  EXPECT_EQ(sceneToJson("test", b.value().name, *b.value().scene, b.value().dt),
            sceneToJson("test", a.value().name, *a.value().scene, a.value().dt));
  const auto& scene = static_cast<const ConstantVelocityScene&>(*b.value().scene);
  EXPECT_EQ(scene.speed, 0.30000000000000004);
  EXPECT_EQ(scene.count, 5);
  EXPECT_EQ(scene.mode, 1);
  EXPECT_EQ(*b.value().dt, 0.003);
  std::remove(first.c_str());
  std::remove(second.c_str());
}

TEST(LabSession, ABadSceneFileKeepsTheRunningSceneAndReportsTheError) {
  SceneRunner runner;
  ASSERT_TRUE(runner.load("constant", 1).ok());
  static_cast<ConstantVelocityScene&>(runner.scene()).speed = 7.0;
  runner.advanceFrame(0.5);
  const long steps = runner.steps();
  LabSession session("test", runner, 1);
  const std::string bad = tempPath("broken.json");
  write(bad, "{ not json");
  EXPECT_FALSE(session.loadSceneFile(bad));
  EXPECT_NE(session.fileError().find("broken.json: line 1"), std::string::npos) << session.fileError();
  EXPECT_EQ(static_cast<ConstantVelocityScene&>(runner.scene()).speed, 7.0);
  EXPECT_EQ(runner.steps(), steps) << "the running scene was not touched";
  std::remove(bad.c_str());
}

TEST(LabSession, PresetsApplyAndResetAndABadPresetChangesNothing) {
  SceneRunner runner;
  ASSERT_TRUE(runner.load("constant", 1).ok());
  LabSession session("test", runner, 1);
  runner.advanceFrame(0.5);
  session.applyPreset(0);
  EXPECT_EQ(static_cast<ConstantVelocityScene&>(runner.scene()).speed, 5.0);
  EXPECT_EQ(runner.steps(), 0) << "a preset resets the scene";
  session.applyPreset(1);  // speed 99 is out of range
  EXPECT_EQ(static_cast<ConstantVelocityScene&>(runner.scene()).speed, 5.0);
  EXPECT_NE(session.message().find("speed"), std::string::npos);
  session.applyPreset(8);
  EXPECT_NE(session.message().find("no preset 9"), std::string::npos);
}

// Issue 15: presets set only the parameters they name, so a key gave different setups depending on
// what was pressed before. Every parameter the preset does not name takes the scene's default.
TEST(LabSession, APresetSetsEveryParameterFromTheDefaultsThenItsOwnValues) {
  SceneRunner runner;
  ASSERT_TRUE(runner.load("constant", 1).ok());
  LabSession session("test", runner, 1);
  auto& scene = static_cast<ConstantVelocityScene&>(runner.scene());
  const ConstantVelocityScene defaults;  // an independent instance: the declared defaults
  scene.mode = 2;
  scene.visible = !defaults.visible;
  scene.count = defaults.count + 5;
  scene.heading = 1.0;
  scene.label = "changed";
  session.applyPreset(0);  // "fast": speed 5 and nothing else
  EXPECT_EQ(scene.speed, 5.0);
  EXPECT_EQ(scene.mode, defaults.mode);
  EXPECT_EQ(scene.visible, defaults.visible);
  EXPECT_EQ(scene.count, defaults.count);
  EXPECT_EQ(scene.heading, defaults.heading);
  EXPECT_EQ(scene.label, defaults.label);
}

TEST(LabSession, ABadPresetLeavesEveryParameterAsItWas) {
  SceneRunner runner;
  ASSERT_TRUE(runner.load("constant", 1).ok());
  LabSession session("test", runner, 1);
  auto& scene = static_cast<ConstantVelocityScene&>(runner.scene());
  scene.mode = 2;
  scene.label = "changed";
  session.applyPreset(1);  // "broken": speed 99 is out of range
  EXPECT_EQ(scene.mode, 2);
  EXPECT_EQ(scene.label, "changed");
  EXPECT_NE(session.message().find("speed"), std::string::npos) << session.message();
}

TEST(LabSession, SaveThenLoadRestoresTheParameters) {
  SceneRunner runner;
  ASSERT_TRUE(runner.load("constant", 1).ok());
  LabSession session("test", runner, 1);
  static_cast<ConstantVelocityScene&>(runner.scene()).speed = 2.25;
  const std::string path = tempPath("saved.json");
  ASSERT_TRUE(session.saveSceneFile(path));
  static_cast<ConstantVelocityScene&>(runner.scene()).speed = 1.0;
  ASSERT_TRUE(session.loadSceneFile(path)) << session.fileError();
  EXPECT_EQ(static_cast<ConstantVelocityScene&>(runner.scene()).speed, 2.25);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace pba::app
