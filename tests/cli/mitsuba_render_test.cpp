// `ochre render SCENE.xml`: Mitsuba 3 XML scenes through the command line (docs/cli.md,
// docs/mitsuba-import.md): they render, -D sets their parameters, and bad ones end with exit code 2, a
// message naming the file, line and element, and no output written.
#include <gtest/gtest.h>

#include "cli/cli_runner.h"
#include "cli/file_test_support.h"
#include "support/test_paths.h"

namespace ochre::test::mitsuba_render_test {
namespace {

std::string elements_xml() {
  return (source_dir() / "tests/data/mitsuba/elements.xml").string();
}

TEST(MitsubaRender, XmlSceneRendersWithParameters) {
  const auto dir = scratch_dir();
  const CommandResult r = run_ochre("render " + elements_xml() + " -D spp=1 -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "out.exr"));
  EXPECT_TRUE(contains(r.output, "elements.xml: 24x16, 1 spp, max depth 4")) << r.output;
}

TEST(MitsubaRender, UnusedParameterIsBadInput) {
  const auto dir = scratch_dir();
  const CommandResult r = run_ochre("render " + elements_xml() + " -D sp=1 -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "elements.xml: scene parameter 'sp' is not used by the scene")) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

TEST(MitsubaRender, ParameterNeedsNameAndValue) {
  const CommandResult r = run_ochre("render " + elements_xml() + " -D spp -o out.exr", scratch_dir());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "-D: expected NAME=VALUE, got 'spp'")) << r.output;
}

TEST(MitsubaRender, ParametersOfJsonScenesAreBadInput) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", minimal_scene());
  const CommandResult r = run_ochre("render scene.json -D spp=1 -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "scene.json: scene parameters (spp=...) apply to Mitsuba XML scenes only"))
      << r.output;
}

TEST(MitsubaRender, BadXmlSceneWritesNothing) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.xml", R"(<scene version="3.0.0">
    <sensor type="perspective"/>
    <shape type="sphere"><bsdf type="plastic"/></shape>
</scene>
)");
  write_old_file(dir / "out.exr", "old");
  const FileSnapshot before = snapshot(dir / "out.exr");
  const CommandResult r = run_ochre("render scene.xml -o out.exr --png out.png", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "ochre: error: scene.xml:3: <bsdf type=\"plastic\">: not supported"))
      << r.output;
  EXPECT_TRUE(snapshot(dir / "out.exr") == before);
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
  EXPECT_TRUE(temporaries_in(dir).empty());
}

}  // namespace
}  // namespace ochre::test::mitsuba_render_test
