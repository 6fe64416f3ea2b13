// Inputs that are not regular files, or are too large, are refused by every tool with exit code 2 and a
// message naming the file and why, quickly (a FIFO must not hang a reader: every run here is killed
// after 20 s, which would show as exit code 137), and no output is written.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli/cli_runner.h"
#include "cli/file_test_support.h"
#include "spectra/byte_size.h"
#include "support/test_paths.h"

namespace ochre::test::input_files_test {
namespace {

namespace fs = std::filesystem;

constexpr int kTimeout = 20;

// Runs `ochre render SCENE -o out.exr` in dir and checks a refusal naming `file` and `why`.
void expect_refused(const fs::path& dir, const std::string& scene, const std::string& file,
                    const std::string& why, const std::string& extra_args = "") {
  const CommandResult r =
      run_tool("ochre", "render " + scene + " -o out.exr " + extra_args, dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, file)) << "message must name " << file << "\n" << r.output;
  EXPECT_TRUE(contains(r.output, why)) << "message must say '" << why << "'\n" << r.output;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  EXPECT_TRUE(temporaries_in(dir).empty());
}

// A scene naming `name` (made a FIFO), then one naming /dev/zero, for a file of `kind` (e.g. "mesh file").
void expect_fifo_and_device_refused(std::string (*scene_naming)(const std::string&), const std::string& name,
                                    const std::string& kind) {
  const fs::path dir = scratch_dir();
  make_fifo(dir / name);
  write_text(dir / "scene.json", scene_naming(name));
  expect_refused(dir, "scene.json", name, "the " + kind + " is a FIFO, not a regular file");
  write_text(dir / "scene.json", scene_naming("/dev/zero"));
  expect_refused(dir, "scene.json", "/dev/zero", "the " + kind + " is a character device");
}

TEST(InputFiles, SceneThatIsAFifo) {
  const fs::path dir = scratch_dir();
  make_fifo(dir / "scene.json");
  expect_refused(dir, "scene.json", "scene.json", "the scene file is a FIFO, not a regular file");
}

TEST(InputFiles, SceneThatIsADevice) {
  const fs::path dir = scratch_dir();
  expect_refused(dir, "/dev/zero", "/dev/zero", "the scene file is a character device, not a regular file");
  expect_refused(dir, "/dev/urandom", "/dev/urandom", "is a character device");
}

TEST(InputFiles, SceneThatIsADirectory) {
  const fs::path dir = scratch_dir();
  fs::create_directory(dir / "scene.json");
  expect_refused(dir, "scene.json", "scene.json", "the scene file is a directory, not a regular file");
}

TEST(InputFiles, SceneLargerThanTheLimit) {
  const fs::path dir = scratch_dir();
  make_sparse_file(dir / "scene.json", 300 * kMiB);
  expect_refused(dir, "scene.json", "scene.json",
                 "the scene file is 300 MiB, larger than the 256 MiB limit for a scene file");
}

TEST(InputFiles, SceneThroughASymbolicLinkIsRead) {
  const fs::path dir = scratch_dir();
  write_text(dir / "real.json", minimal_scene());
  fs::create_symlink("real.json", dir / "scene.json");
  const CommandResult r = run_tool("ochre", "render scene.json -o out.exr", dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out.exr"));
}

std::string mesh_scene(const std::string& file) {
  return minimal_scene("", R"("shapes": [{"type": "mesh", "file": ")" + file + R"(", "material": "grey"}])");
}

TEST(InputFiles, MeshThatIsAFifoOrADevice) {
  expect_fifo_and_device_refused(mesh_scene, "mesh.obj", "mesh file");
}

TEST(InputFiles, FileNamedByAMeshThatIsAFifo) {
  const fs::path dir = scratch_dir();
  write_text(dir / "mesh.obj", "mtllib mesh.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  make_fifo(dir / "mesh.mtl");
  write_text(dir / "scene.json", mesh_scene("mesh.obj"));
  expect_refused(dir, "scene.json", "mesh.mtl", "the mesh file is a FIFO, not a regular file");
}

TEST(InputFiles, MeshLargerThanTheLimit) {
  const fs::path dir = scratch_dir();
  make_sparse_file(dir / "mesh.obj", 5 * kGiB);
  write_text(dir / "scene.json", mesh_scene("mesh.obj"));
  expect_refused(dir, "scene.json", "mesh.obj", "is 5 GiB, larger than the 4 GiB limit for a mesh file");
}

std::string spectrum_scene(const std::string& file) {
  return minimal_scene(R"("materials": {"grey": {"type": "lambert", "color": {"file": ")" + file + R"("}}})");
}

TEST(InputFiles, SpectrumThatIsAFifoOrADevice) {
  expect_fifo_and_device_refused(spectrum_scene, "reflectance.csv", "CSV file");
}

TEST(InputFiles, SpectrumLargerThanTheLimit) {
  const fs::path dir = scratch_dir();
  make_sparse_file(dir / "reflectance.csv", 65 * kMiB);
  write_text(dir / "scene.json", spectrum_scene("reflectance.csv"));
  expect_refused(dir, "scene.json", "reflectance.csv",
                 "is 65 MiB, larger than the 64 MiB limit for a CSV file");
}

std::string texture_scene(const std::string& file) {
  return minimal_scene(R"("materials": {"grey": {"nodes": {"tex": {"type": "texture", "file": ")" + file +
                       R"("}, "d": {"type": "lambert", "color": {"link": "tex.color"}}}, "output": "d"}})");
}

TEST(InputFiles, TextureThatIsAFifoOrADevice) {
  expect_fifo_and_device_refused(texture_scene, "albedo.png", "texture");
}

TEST(InputFiles, EnvironmentMapThatIsAFifo) {
  const fs::path dir = scratch_dir();
  make_fifo(dir / "sky.hdr");
  write_text(dir / "scene.json",
             minimal_scene("", "", R"("lights": [{"type": "environment", "file": "sky.hdr"}])"));
  expect_refused(dir, "scene.json", "sky.hdr", "the environment map is a FIFO, not a regular file");
}

TEST(InputFiles, OcioConfigThatIsAFifo) {
  const fs::path dir = scratch_dir();
  make_fifo(dir / "config.ocio");
  write_text(dir / "scene.json", minimal_scene());
  const CommandResult r =
      run_tool("ochre", "render scene.json --png out.png --ocio-config config.ocio", dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "config.ocio: the OCIO config is a FIFO, not a regular file")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(InputFiles, ImagesComparedByOchreDiffMustBeRegularFiles) {
  const fs::path dir = scratch_dir();
  make_fifo(dir / "test.exr");
  const CommandResult r = run_tool("ochre-diff", "test.exr /dev/zero", dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "test.exr: the image file is a FIFO, not a regular file")) << r.output;
}

TEST(InputFiles, ReferenceOfOchreConvergeMustBeARegularFile) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", minimal_scene());
  make_fifo(dir / "reference.exr");
  const CommandResult r = run_tool(
      "ochre-converge", "scene.json --reference reference.exr --spp 1 --csv out.csv", dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "reference.exr: the image file is a FIFO")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out.csv"));
}

TEST(InputFiles, ReferenceOfOchreRegressMustBeARegularFile) {
  const fs::path dir = scratch_dir();
  write_text(dir / "suite" / "plane.json", minimal_scene());
  fs::create_directories(dir / "suite" / "references");
  make_fifo(dir / "suite" / "references" / "plane.exr");
  const CommandResult r = run_tool("ochre-regress", "suite", dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "plane.exr: the image file is a FIFO")) << r.output;
}

TEST(InputFiles, MaterialAndPairsOfOchreBrdfMustBeRegularFiles) {
  const fs::path dir = scratch_dir();
  make_fifo(dir / "material.json");
  CommandResult r = run_tool("ochre-brdf", "albedo --material material.json", dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "material.json: the material file is a FIFO")) << r.output;
  write_text(dir / "lambert.json", R"({"type": "lambert", "color": 0.5})");
  r = run_tool("ochre-brdf", "eval --material lambert.json --input /dev/zero --output values.csv", dir, false,
               kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "/dev/zero: the CSV file is a character device")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "values.csv"));
}

}  // namespace
}  // namespace ochre::test::input_files_test
