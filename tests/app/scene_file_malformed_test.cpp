// Malformed scene files found by the corpora (tests/corpora): each is a bad file with one line that
// names the file and the field or line, never an exception, a crash or a second line.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "app/lab.h"
#include "app/runner/message_text.h"
#include "app/runner/scene_file.h"
#include "support/fp_traps.h"
#include "test_scenes.h"

namespace pba::app {
namespace {

std::string parseError(const std::string& text) {
  const Result<LoadedScene> r = parseSceneJson(text, "f.json", "test");
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error().find('\n'), std::string::npos) << r.error();
  return r.error();
}

TEST(SceneFileMalformed, ANumberBeyondTheRangeOfADoubleIsABadFileNamingItsLine) {
  // nlohmann reports it as out_of_range, not parse_error: it used to end the lab with exit 1.
  const pba::testing::FloatingPointTrapsOff traps;  // reading 1e400 overflows, as it should
  EXPECT_EQ(parseError("{\"lab\": \"test\",\n \"scene\": \"constant\",\n \"dt\": 1e400}"),
            "f.json: line 3: not valid JSON (number overflow parsing '1e400')");
}

TEST(SceneFileMalformed, DeepNestingIsRefusedBeforeAnyValueIsBuilt) {
  // 100,000 nested arrays overflowed the stack when the error message printed the value.
  const std::string deep =
      "{\"lab\": \"test\", \"scene\": \"constant\", \"params\": {\"speed\": " + std::string(100000, '[') +
      std::string(100000, ']') + "}}";
  EXPECT_EQ(parseError(deep), "f.json: line 1: nested deeper than 64 levels");
  // 64 levels are still JSON (the value is then the wrong type, not a bad file).
  const std::string ok =
      "{\"lab\": \"test\", \"scene\": \"constant\", \"params\": {\"speed\": " + std::string(62, '[') +
      std::string(62, ']') + "}}";
  EXPECT_EQ(parseError(ok), "f.json: params.speed: expected a number, got an array of 1 elements");
}

TEST(SceneFileMalformed, AKeyGivenTwiceIsAnErrorNamingIt) {
  EXPECT_EQ(parseError(R"({"lab": "test", "scene": "constant", "params": {"speed": 1, "speed": 2}})"),
            "f.json: params.speed: given twice (each key at most once)");
  EXPECT_EQ(parseError(R"({"lab": "test", "lab": "test", "scene": "constant"})"),
            "f.json: lab: given twice (each key at most once)");
  // The same key in two different objects is not a duplicate.
  EXPECT_TRUE(parseSceneJson(R"({"lab": "test", "scene": "constant", "params": {"speed": 1}, "description": "speed"})",
                             "f.json", "test")
                  .ok());
}

TEST(SceneFileMalformed, ControlCharactersAndLongTextAreShownOnOneShortLine) {
  EXPECT_EQ(parseError(R"({"lab": "test", "scene": "constant", "params": {"a\nb": 1}})"),
            "f.json: params.a\\nb: no such parameter in this scene");
  const std::string error = parseError(R"({"lab": "test", "scene": ")" + std::string(100000, 'x') + "\"}");
  EXPECT_LT(error.size(), 200u) << error;
  EXPECT_NE(error.find("... (100000 bytes)"), std::string::npos) << error;
}

TEST(SceneFileMalformed, ANulByteIsNamedWithItsLine) {
  EXPECT_EQ(parseError(std::string("{\n\"lab\": \"test\"\0}", 17)),
            "f.json: line 2: a NUL byte (this is not a text file)");
}

TEST(SceneFileMalformed, ADescriptionMustBeAString) {
  EXPECT_EQ(parseError(R"({"lab": "test", "scene": "constant", "description": 3})"),
            "f.json: description: expected a string, got 3");
}

TEST(SceneFileMalformed, ADirectoryIsNotASceneFile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "pba_scene_file_dir.json";
  std::filesystem::create_directories(dir);
  const Result<LoadedScene> r = loadSceneFile(dir.string(), "test");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), dir.string() + ": is a directory, not a scene file");
  std::filesystem::remove(dir);
}

TEST(SceneFileMalformed, ADeviceIsNotReadUntilItEnds) {
#if defined(_WIN32)
  GTEST_SKIP() << "no /dev/zero on Windows (under Wine it passes for a regular file)";
#endif
  // /dev/zero never ends: the lab used to read it until it ran out of memory.
  const Result<LoadedScene> r = loadSceneFile("/dev/zero", "test");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), "/dev/zero: is not a regular file (a device or a pipe?)");
}

TEST(SceneFileMalformed, AFileLargerThanTheLimitIsRefusedUnread) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "pba_scene_file_huge.json";
  std::ofstream(path).close();
  std::filesystem::resize_file(path, kMaxSceneFileBytes + 1);  // sparse: nothing is written
  const Result<LoadedScene> r = loadSceneFile(path.string(), "test");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), path.string() + ": is " + std::to_string(kMaxSceneFileBytes + 1) +
                           " bytes; a scene file is at most " + std::to_string(kMaxSceneFileBytes) + " bytes");
  std::filesystem::remove(path);
}

TEST(SceneFileMalformed, WhatTheFileNamesAndValidateRefusesNamesTheFileAndTheField) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "pba_scene_file_label.json";
  std::ofstream(path) << R"({"lab": "test", "scene": "constant", "params": {"label": "invalid"}})";
  LabOptions o;
  o.scene = path.string();
  SceneRunner runner;
  const Status s = prepareRunner("test", o, runner);
  EXPECT_EQ(s.error(), path.string() + ": params.label: 'invalid' is not a valid label");
  std::filesystem::remove(path);
}

TEST(MessageText, ShortPrintableTextIsUnchangedAndTheRestIsEscapedAndCut) {
  EXPECT_EQ(shownText("restitution"), "restitution");
  EXPECT_EQ(shownText("a\tb\x1b"), "a\\tb\\x1b");
  const std::string cut = shownText(std::string(kShownTextBytes - 1, 'x') + "é");  // é is two bytes
  EXPECT_EQ(cut, std::string(kShownTextBytes - 1, 'x') + "... (" + std::to_string(kShownTextBytes + 1) + " bytes)");
  EXPECT_EQ(oneLine("one\ntwo"), "one\\ntwo");
  EXPECT_EQ(shownJson(nlohmann::json::parse("[[1], 2]")), "an array of 2 elements");
  EXPECT_EQ(shownJson("x"), "\"x\"");
}

}  // namespace
}  // namespace pba::app
