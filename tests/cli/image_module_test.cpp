// The image library module (renderer/image/image_library.h): `ochre` loads OpenImageIO only when it reads or
// writes an image through it. With OCHRE_IMAGE_MODULE pointing nowhere, a render to EXR of a scene
// without textures works (the module was never needed), and a command that needs it stops before any
// work with a message naming the module and the variable, leaving no output behind.

#include <gtest/gtest.h>

#include <filesystem>

#include "cli/cli_runner.h"
#include "cli/file_test_support.h"
#include "support/test_paths.h"

namespace ochre::test::image_module_test {
namespace {

namespace fs = std::filesystem;

// Runs `ochre ARGS` in dir with the module looked for at a path that does not exist.
CommandResult run_without_module(const std::string& args, const fs::path& dir) {
  return run_shell(
      "OCHRE_PROGRESS=none OCHRE_IMAGE_MODULE=" + (dir / "missing" / "libochre_oiio.so").string() + " " +
          (bin_dir() / "ochre").string() + " " + args + " 2>&1",
      dir);
}

TEST(ImageModule, ExrRenderWithoutTexturesNeverLoadsIt) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", minimal_scene());
  const CommandResult r = run_without_module("render scene.json -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(dir / "out.exr")) << r.output;
}

TEST(ImageModule, PngOutputWithoutItStopsBeforeTheRender) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", minimal_scene());
  const CommandResult r = run_without_module("render scene.json -o out.exr --png out.png", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "ochre: error: cannot load")) << r.output;
  EXPECT_TRUE(contains(r.output, "libochre_oiio.so")) << r.output;
  EXPECT_TRUE(contains(r.output, "OCHRE_IMAGE_MODULE")) << r.output;
  EXPECT_FALSE(contains(r.output, "rendered")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  EXPECT_FALSE(fs::exists(dir / "out.png"));
  EXPECT_TRUE(temporaries_in(dir).empty());
}

TEST(ImageModule, TextureWithoutItNamesTheTextureAndTheModule) {
  const fs::path dir = scratch_dir();
  write_png(dir / "albedo.png", 4, 4);  // written by this test process, which loads the module
  write_text(dir / "scene.json",
             minimal_scene(R"("materials": {"tex": {"nodes": {"t": {"type": "texture", "file": "albedo.png"},
                              "d": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "d"}})",
                           R"("shapes": [{"type": "plane", "material": "tex"}])"));
  const CommandResult r = run_without_module("render scene.json -o out.exr", dir);
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "albedo.png")) << r.output;
  EXPECT_TRUE(contains(r.output, "libochre_oiio.so")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
}

TEST(ImageModule, FoundBesideTheExecutableByDefault) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", minimal_scene());
  const CommandResult r = run_ochre("render scene.json -o out.exr --png out.png", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(dir / "out.png")) << r.output;
}

}  // namespace
}  // namespace ochre::test::image_module_test
