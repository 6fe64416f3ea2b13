// Requests larger than the machine (or --memory-limit) are refused with exit code 2 and the estimate
// before anything is allocated: the film, subdivision, tessellation, textures; polygons too large to
// triangulate are refused at once instead of taking minutes.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli/cli_runner.h"
#include "cli/file_test_support.h"
#include "support/test_paths.h"

namespace ochre::test::resource_limits_test {
namespace {

namespace fs = std::filesystem;

constexpr int kTimeout = 60;

CommandResult render(const fs::path& dir, const std::string& args) {
  return run_tool("ochre", "render scene.json -o out.exr -q " + args, dir, false, kTimeout);
}

void expect_refused(const fs::path& dir, const std::string& args, const std::vector<std::string>& parts) {
  const CommandResult r = render(dir, args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  for (const std::string& part : parts)
    EXPECT_TRUE(contains(r.output, part)) << args << ": message must contain '" << part << "'\n" << r.output;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
}

TEST(ResourceLimits, FilmLargerThanTheMachineIsRefusedWithTheEstimate) {
  const fs::path dir = scratch_dir();
  std::string scene = minimal_scene();
  scene.replace(scene.find("[8, 8]"), 6, "[65536, 65536]");
  write_text(dir / "scene.json", scene);
  expect_refused(dir, "",
                 {"error: film 65536x65536 (XYZ) with its output buffers needs 416 GiB; this machine has",
                  "(use --memory-limit to change the limit)"});
  expect_refused(dir, "--aovs --spectral-bins 16", {"film 65536x65536 (XYZ, AOVs, 16 spectral bins)", "TiB"});
}

TEST(ResourceLimits, MemoryLimitRefusesAndAdmits) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", minimal_scene());
  expect_refused(
      dir, "--memory-limit 1K",
      {"film 8x8 (XYZ) with its output buffers needs 6.5 KiB; the memory limit (--memory-limit) is 1 KiB"});
  const CommandResult r = render(dir, "--memory-limit 1G");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out.exr"));
}

TEST(ResourceLimits, MalformedMemoryLimitIsBadUsage) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", minimal_scene());
  for (const char* size : {"lots", "0", "-1G", "8Q"})
    expect_refused(dir, std::string("--memory-limit ") + size,
                   {"--memory-limit: expected a size such as 8G"});
}

// An n x n grid of quads in the xy plane.
void write_grid(const fs::path& file, int n) {
  std::ofstream out(file);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) out << "v " << i << " " << j << " 0\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i + 1;
      out << "f " << a << " " << a + 1 << " " << a + n + 2 << " " << a + n + 1 << "\n";
    }
}

std::string subdivided_scene(int level) {
  return minimal_scene("", fmt::format(R"("shapes": [{{"type": "mesh", "file": "grid.obj", "material": "grey",
                                          "subdivision": {{"level": {}}}}}])",
                                       level));
}

TEST(ResourceLimits, SubdivisionThatWouldExplodeIsRefusedWithTheEstimate) {
  const fs::path dir = scratch_dir();
  write_grid(dir / "grid.obj", 128);  // 16384 quads x 4^7 x 2 = 2^31 triangles at level 8
  write_text(dir / "scene.json", subdivided_scene(8));
  expect_refused(dir, "",
                 {"scene.json: shapes[0]",
                  "grid: subdivision level 8 of 16384 faces (2147483648 triangles) needs 600 "
                  "GiB"});
}

TEST(ResourceLimits, SubdivisionWithinAndBeyondTheMemoryLimit) {
  const fs::path dir = scratch_dir();
  write_grid(dir / "grid.obj", 2);
  write_text(dir / "scene.json", subdivided_scene(4));  // 16 corners x 2 x 4^3 = 2048 triangles x 300 bytes
  expect_refused(dir, "--memory-limit 100K",
                 {"grid: subdivision level 4 of 4 faces (2048 triangles) needs 600 KiB; the memory limit "
                  "(--memory-limit) is 100 KiB"});
  EXPECT_EQ(render(dir, "--memory-limit 1G").exit_code, 0);
}

// Renders a scene of the one shape `shape` (JSON) under --memory-limit `limit`, expecting the refusal.
void expect_shape_refused(const std::string& shape, const std::string& limit, const std::string& message) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", minimal_scene("", R"("shapes": [)" + shape + "]"));
  expect_refused(dir, "--memory-limit " + limit, {message});
}

TEST(ResourceLimits, SphereTessellationBeyondTheMemoryLimit) {
  expect_shape_refused(
      R"({"type": "sphere", "subdivisions": 4096, "material": "grey"})", "1G",
      "scene.json: shapes[0].subdivisions: a sphere of 67092480 triangles needs 9.4 GiB; the "
      "memory limit (--memory-limit) is 1 GiB");
}

// Groove shapes: estimated like the sphere; a grooved cylinder of 2^33 triangles is refused for its 32-bit
// indices even when the memory limit would admit it (its groove count, 2^21, is computed, never wrapped).
TEST(ResourceLimits, GrooveShapesBeyondTheMemoryLimitOrTheIndexRange) {
  expect_shape_refused(R"({"type": "groove_plate", "count": 4194304, "tile": 0, "material": "grey"})", "1G",
                       "scene.json: shapes[0].count: a groove plate of 16777216 triangles needs 2.3 GiB; the "
                       "memory limit (--memory-limit) is 1 GiB");
  // Tiles multiply the triangles: 1024 grooves of pitch 1 cut every 8 pitches along 1e6.
  expect_shape_refused(R"({"type": "groove_plate", "count": 1024, "length": 1e6, "material": "grey"})", "1G",
                       "scene.json: shapes[0].count: a groove plate of 512000000 triangles (1024 grooves x "
                       "125000 tiles along them) needs");
  expect_shape_refused(R"({"type": "cylinder", "segments": 1048576, "material": "grey"})", "100M",
                       "scene.json: shapes[0].segments: a cylinder of 2097152 triangles needs 300 MiB");
  const std::string grooved =
      R"({"type": "grooved_cylinder", "height": 2097152, "pitch": 1, "segments": 1024, "material": "grey"})";
  expect_shape_refused(grooved, "1G",
                       "scene.json: shapes[0]: a grooved cylinder of 2097152 grooves x 1024 segments "
                       "(8589934592 triangles) needs 1.2 TiB; the memory limit (--memory-limit) is 1 GiB");
  expect_shape_refused(grooved, "2000T", "(8589934592 triangles): more than 2^31 triangles");
}

TEST(ResourceLimits, TextureBeyondTheMemoryLimit) {
  const fs::path dir = scratch_dir();
  write_png(dir / "big.png", 256, 256);  // 256 x 256 x 3 floats, copied by the MIP-map conversion
  write_text(dir / "scene.json",
             minimal_scene(R"("materials": {"grey": {"nodes": {"t": {"type": "texture", "file": "big.png"},
                              "d": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "d"}})"));
  const CommandResult r =
      run_tool("ochre", "render scene.json -o out.exr -q --memory-limit 256K", dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "converting texture")) << r.output;
  EXPECT_TRUE(contains(r.output, "big.png (256x256, 3 channels) needs 1.8 MiB")) << r.output;
}

TEST(ResourceLimits, PolygonTooLargeToTriangulateIsRefusedAtOnce) {
  const fs::path dir = scratch_dir();
  {
    std::ofstream out(dir / "disk.obj");
    const int n = 50000;  // Assimp's ear clipping would take minutes
    for (int i = 0; i < n; ++i)
      out << "v " << std::cos(2 * M_PI * i / n) << " " << std::sin(2 * M_PI * i / n) << " 0\n";
    out << "f";
    for (int i = 1; i <= n; ++i) out << " " << i;
    out << "\n";
  }
  write_text(dir / "scene.json",
             minimal_scene("", R"("shapes": [{"type": "mesh", "file": "disk.obj", "material": "grey"}])"));
  const auto start = std::chrono::steady_clock::now();
  expect_refused(
      dir, "",
      {"scene.json: shapes[0].file", "disk.obj: polygons too large to triangulate", "has 50000 vertices"});
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST(ResourceLimits, OutOfMemoryDespiteTheEstimateIsReportedAsBadInput) {
  // The estimate is passed with --memory-limit 100G, but the process may only map 3 GB: the film of
  // 8000 x 8000 pixels (4.8 GiB) cannot be allocated.
  const fs::path dir = scratch_dir();
  std::string scene = minimal_scene();
  scene.replace(scene.find("[8, 8]"), 6, "[8000, 8000]");
  write_text(dir / "scene.json", scene);
  const std::string command = "cd '" + dir.string() + "' && ulimit -v 3000000 && '" +
                              (bin_dir() / "ochre").string() +
                              "' render scene.json -o out.exr -q --memory-limit 100G 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[4096];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
  const int status = ::pclose(pipe);
  ASSERT_TRUE(WIFEXITED(status)) << output;
  EXPECT_EQ(WEXITSTATUS(status), 2) << output;
  EXPECT_EQ(output,
            "ochre: error: scene.json: out of memory while allocating the film (see --memory-limit in "
            "docs/cli.md)\n");
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
}

}  // namespace
}  // namespace ochre::test::resource_limits_test
