// Malformed model files found by the corpora (tests/corpora/models): loadModel refuses each with one
// line naming the file and what is wrong (a line, a node, a mesh), before the labs see the data.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "graphics/model.h"
#include "support/fp_traps.h"

namespace gfx = pba::graphics;

namespace {

std::string write(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / ("pba_malformed_" + name)).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// loadModel's error for `text` saved as `name`; the test fails if the file loads.
std::string loadError(const std::string& name, const std::string& text) {
  const std::string path = write(name, text);
  std::string error;
  EXPECT_FALSE(gfx::loadModel(path, &error).has_value()) << name << " loaded";
  std::filesystem::remove(path);
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
  return error.substr(path.size() + 2);
}

/// A three-joint BVH with two frames; each argument replaces one part.
std::string bvh(const std::string& handOffset = "0 -30 0", const std::string& frames = "2",
                const std::string& frameTime = "0.033333") {
  return "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 90 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation "
         "Yrotation\n  JOINT Arm\n  {\n    OFFSET 10 40 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n    JOINT "
         "Hand\n    {\n      OFFSET " +
         handOffset +
         "\n      CHANNELS 3 Zrotation Xrotation Yrotation\n      End Site\n      {\n        OFFSET 0 -10 0\n      "
         "}\n    }\n  }\n}\nMOTION\nFrames: " +
         frames + "\nFrame Time: " + frameTime + "\n0 90 0 0 0 0 10 0 0 20 0 0\n0 90 0 0 0 0 10 0 0 20 0 0\n";
}

TEST(ModelMalformed, TheWellFormedBaseFileLoads) {
  const std::string path = write("good.bvh", bvh());
  std::string error;
  EXPECT_TRUE(gfx::loadModel(path, &error).has_value()) << error;
  std::filesystem::remove(path);
}

TEST(ModelMalformed, NonFiniteOffsetsAndVerticesNameTheirNodeOrMesh) {
  const pba::testing::FloatingPointTrapsOff traps;  // Assimp reads "nan" and "inf" as such
  EXPECT_EQ(loadError("nan.bvh", bvh("nan -30 0")), "node 'Hand': transform is not finite");
  EXPECT_EQ(loadError("inf.obj", "v 0 0 0\nv 1 0 0\nv 1 inf 0\nf 1 2 3\n"),
            "mesh 'defaultobject': vertex 2 is not finite");
}

TEST(ModelMalformed, AFrameCountTheFileCannotHoldIsRefusedBeforeAssimpReservesIt) {
  // Assimp reserved room for 2,000,000,000 frames and ended in std::bad_alloc.
  EXPECT_EQ(
      loadError("frames.bvh", bvh("0 -30 0", "2000000000")).rfind("line 22: Frames: 2000000000 frames cannot fit", 0),
      0u);
  EXPECT_EQ(loadError("negative.bvh", bvh("0 -30 0", "-2")), "line 22: Frames: must be a whole number >= 0");
}

TEST(ModelMalformed, AFrameTimeOfZeroOrBelowIsRefused) {
  // It played at Assimp's default 25 frames/s (negative) or collapsed the clip to an instant (zero).
  const pba::testing::FloatingPointTrapsOff traps;  // Assimp divides by the frame time
  EXPECT_EQ(loadError("zero-time.bvh", bvh("0 -30 0", "2", "0")),
            "animation 'Motion': inf ticks per second (a BVH Frame Time must be > 0)");
  EXPECT_NE(loadError("negative-time.bvh", bvh("0 -30 0", "2", "-0.5")).find("-2.000000 ticks per second"),
            std::string::npos);
}

TEST(ModelMalformed, JointsNestedBeyondTheLimitAreRefusedWithTheirLine) {
  // Assimp's BVH reader recurses once per joint: 100,000 nested joints would overflow its stack.
  std::string text = "HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 3 Xposition Yposition Zposition\n";
  for (int i = 0; i < 300; ++i) text += "JOINT J" + std::to_string(i) + "\n{\nOFFSET 0 1 0\nCHANNELS 1 Zrotation\n";
  EXPECT_EQ(loadError("deep.bvh", text), "line 1027: joints nested deeper than 256");
}

TEST(ModelMalformed, AssimpsFileAndLinePrefixBecomesALineNumber) {
  EXPECT_EQ(loadError("keyword.bvh", "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 1 Wrotation\n}\n"),
            "line 5: Invalid channel specifier \"Wrotation\".");
}

TEST(ModelMalformed, AFileGoesOnlyToTheReadersItsExtensionNames) {
  // Neither glTF reader recognises this .glb; Assimp then offered it to every reader it has, and the
  // OpenGEX reader, matching "indexarray", read past the end of the file (ASan, fuzz_model_import).
  const std::string notGlb("lTasset\":indexarray\0ON{\"asset\":", 31);
  EXPECT_EQ(loadError("opengex-bait.glb", notGlb).rfind("No suitable reader found for the file format", 0), 0u);
  EXPECT_EQ(loadError("mesh.3ds", "MM"),
            "'.3ds' is not a model format read here (.bvh, .obj, .gltf, .glb, .dae, .fbx, .x, .ply, .stl, .off)");
  EXPECT_EQ(loadError("no-extension", "v 0 0 0\n").rfind("the name has no extension (.bvh, ", 0), 0u);
}

TEST(ModelMalformed, DirectoriesAndFilesOverTheSizeLimitAreRefusedUnread) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "pba_malformed_dir.bvh";
  std::filesystem::create_directories(dir);
  std::string error;
  EXPECT_FALSE(gfx::loadModel(dir.string(), &error).has_value());
  EXPECT_EQ(error, dir.string() + ": is a directory, not a model file");
  std::filesystem::remove(dir);
  const std::filesystem::path huge = std::filesystem::temp_directory_path() / "pba_malformed_huge.bvh";
  std::ofstream(huge).close();
  std::filesystem::resize_file(huge, gfx::kMaxModelFileBytes + 1);  // sparse: nothing is written
  EXPECT_FALSE(gfx::loadModel(huge.string(), &error).has_value());
  EXPECT_NE(error.find("is " + std::to_string(gfx::kMaxModelFileBytes + 1) + " bytes; model files are read up to"),
            std::string::npos)
      << error;
  std::filesystem::remove(huge);
}

}  // namespace
