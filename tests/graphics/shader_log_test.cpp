// Shader preprocessing and log mapping (no GL): #include expansion with #line directives, and driver
// logs rewritten to file:line.
#include "graphics/shader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace gfx = pba::graphics;

TEST(ShaderLog, MesaNvidiaAndGenericLinesAreMappedToFileAndLine) {
  const std::vector<std::string> files = {"/s/lit.frag", "/s/lighting.glsl"};
  // Lines of the included file k are numbered k * 100000 + L by preprocessShaderFile.
  EXPECT_EQ(gfx::mapShaderLog("0:12(3): error: `x' undeclared\n", files), "/s/lit.frag:12: error: `x' undeclared\n");
  EXPECT_EQ(gfx::mapShaderLog("0:100045(9): error: `x' undeclared\n", files),
            "/s/lighting.glsl:45: error: `x' undeclared\n");
  EXPECT_EQ(gfx::mapShaderLog("0(100007) : error C0000: syntax error\n", files),
            "/s/lighting.glsl:7: error C0000: syntax error\n");
  EXPECT_EQ(gfx::mapShaderLog("ERROR: 0:4: 'y' : undeclared\n", files), "/s/lit.frag:4: ERROR: 'y' : undeclared\n");
  EXPECT_EQ(gfx::mapShaderLog("plain text\n", files), "plain text\n");
}

TEST(ShaderLog, IncludesExpandWithLineDirectivesNamingTheirFile) {
  const auto dir = std::filesystem::temp_directory_path() / "pba_shader_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "common.glsl") << "float f() { return 1.0; }\n";
  std::ofstream(dir / "main.frag") << "#version 330 core\n#include \"common.glsl\"\nvoid main() {}\n";
  std::vector<std::string> files;
  std::string source, error;
  ASSERT_TRUE(gfx::preprocessShaderFile((dir / "main.frag").string(), files, &source, &error)) << error;
  ASSERT_EQ(files.size(), 2u);
  EXPECT_NE(source.find("float f()"), std::string::npos);
  EXPECT_NE(source.find("#line 100001"), std::string::npos);
  EXPECT_EQ(source.rfind("#version 330 core", 0), 0u) << "#version must stay first";
  // A file without #version gets the platform's header first, and its own lines keep their numbers.
  std::ofstream(dir / "plain.frag") << "void main() {}\n";
  ASSERT_TRUE(gfx::preprocessShaderFile((dir / "plain.frag").string(), files, &source, &error)) << error;
  EXPECT_EQ(source.rfind(gfx::shaderHeader(), 0), 0u);
  EXPECT_NE(source.find("#line 1\nvoid main()"), std::string::npos);
  EXPECT_FALSE(gfx::preprocessShaderFile((dir / "absent.frag").string(), files, &source, &error));
  EXPECT_NE(error.find("absent.frag"), std::string::npos);
  std::filesystem::remove_all(dir);
}
