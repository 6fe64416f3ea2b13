// Light groups (docs/lights.md, "Light groups"): a layer per group whose sum is the image, groups that
// merge across split parts bit for bit, a group's layer the light of its own emitters, and bad group names
// refused naming the field.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::light_groups_test {
namespace {

namespace fs = std::filesystem;

// A wall lit by a torch (group "torch"), a point lamp ("lamp"), a glowing sphere ("orb") and a dim sky
// without a group ("other").
std::string wall_scene(
    const std::string& lamp_group = R"(, "group": "lamp")",
    const std::string& torch =
        R"({"type": "flame", "preset": "torch", "position": [0.3, 1.2, 0.5], "group": "torch"},)") {
  return fmt::format(R"({{
  "camera": {{"eye": [0, 1, 4], "target": [0, 1, 0], "fov": 50}},
  "film": {{"resolution": [24, 16]}},
  "integrator": {{"spp": 64}},
  "materials": {{"rock": {{"type": "lambert", "color": [0.6, 0.5, 0.4]}},
                "glow": {{"type": "emission", "color": [1, 0.8, 0.5], "strength": 2}}}},
  "lights": [{}
             {{"type": "point", "position": [-1, 2, 1], "intensity": 3{}}},
             {{"type": "environment", "radiance": 0.05}}],
  "shapes": [{{"type": "plane", "size": [6, 4], "material": "rock", "transform": [{{"translate": [0, 1, 0]}}]}},
             {{"type": "sphere", "radius": 0.2, "material": "glow", "light_group": "orb",
              "transform": [{{"translate": [1, 0.5, 0.5]}}]}}]
}})",
                     torch, lamp_group);
}

TEST(LightGroups, TheGroupsSumToTheImage) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", wall_scene());
  const CommandResult r = run_ochre("render scene.json -o out.exr -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage image = read_exr(dir / "out.exr");
  EXPECT_EQ(image.string_attributes.at("ochre.lightGroups"), "torch,lamp,orb,other");
  for (const char* c : {"R", "G", "B"}) {
    const std::vector<float>& beauty = exr_channel(image, c);
    for (size_t i = 0; i < beauty.size(); ++i) {
      double sum = 0;
      for (const char* group : {"torch", "lamp", "orb", "other"})
        sum += exr_channel(image, fmt::format("group.{}.{}", group, c))[i];
      // Float rounding of four sums of the same samples (docs/lights.md: 1e-6 of the largest value).
      EXPECT_NEAR(sum, beauty[i], 1e-6 * 12.0) << c << " pixel " << i;
    }
  }
  // Each group holds light: none is empty.
  for (const char* group : {"torch", "lamp", "orb", "other"})
    EXPECT_GT(mean_of(exr_channel(image, fmt::format("group.{}.G", group))), 1e-3) << group;
}

TEST(LightGroups, SplitPartsMergeBitForBit) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", wall_scene());
  ASSERT_EQ(run_ochre("render scene.json -o whole.exr -q", dir).exit_code, 0);
  for (const std::string& split : {std::string("--part {}/2"), std::string("--tile {}/2x1")}) {
    for (int i = 0; i < 2; ++i)
      ASSERT_EQ(
          run_ochre(fmt::format("render scene.json -q -o p{}.exr ", i) + fmt::format(fmt::runtime(split), i),
                    dir)
              .exit_code,
          0);
    ASSERT_EQ(run_ochre("merge p0.exr p1.exr -o merged.exr -q", dir).exit_code, 0);
    EXPECT_TRUE(same_exr_pixels(dir / "whole.exr", dir / "merged.exr")) << split;
  }
  ASSERT_EQ(run_ochre("render scene.json -o one.exr -q --threads 1", dir).exit_code, 0);
  EXPECT_TRUE(same_exr_pixels(dir / "whole.exr", dir / "one.exr"));
}

// A group's layer is the light of its emitters: the lamp's layer against a render of the lamp alone (other
// noise, the same expectation), over the whole image.
TEST(LightGroups, AGroupIsTheLightOfItsEmitters) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", wall_scene());
  ASSERT_EQ(run_ochre("render scene.json -o all.exr -q --spp 512", dir).exit_code, 0);
  const std::string lamp_only = R"({
  "camera": {"eye": [0, 1, 4], "target": [0, 1, 0], "fov": 50},
  "film": {"resolution": [24, 16]}, "integrator": {"spp": 512},
  "materials": {"rock": {"type": "lambert", "color": [0.6, 0.5, 0.4]}},
  "lights": [{"type": "point", "position": [-1, 2, 1], "intensity": 3}],
  "shapes": [{"type": "plane", "size": [6, 4], "material": "rock", "transform": [{"translate": [0, 1, 0]}]}]
})";
  write_text(dir / "lamp.json", lamp_only);
  ASSERT_EQ(run_ochre("render lamp.json -o lamp.exr -q --seed 5", dir).exit_code, 0);
  const ExrImage all = read_exr(dir / "all.exr"), lamp = read_exr(dir / "lamp.exr");
  for (const char* c : {"R", "G", "B"}) {
    const double group = mean_of(exr_channel(all, fmt::format("group.lamp.{}", c))),
                 alone = mean_of(exr_channel(lamp, c));
    EXPECT_NEAR(group / alone, 1.0, 0.01) << c << ": " << group << " vs " << alone;
  }
}

TEST(LightGroups, WithoutGroupsThereAreNoLayers) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", scene_with("/integrator/spp", "4"));
  ASSERT_EQ(run_ochre("render scene.json -o out.exr -q", dir).exit_code, 0);
  const ExrImage image = read_exr(dir / "out.exr");
  EXPECT_EQ(image.string_attributes.count("ochre.lightGroups"), 0u);
  for (const auto& [name, values] : image.channels) EXPECT_NE(name.rfind("group.", 0), 0u) << name;
}

TEST(LightGroups, BadGroupsAreRefused) {
  expect_rejected(
      {"reserved", wall_scene(R"(, "group": "other")"), {"lights[1].group", "'other' is the group"}});
  expect_rejected({"spaces", wall_scene(R"(, "group": "a lamp")"), {"lights[1].group", "not a group name"}});
  expect_rejected({"empty", wall_scene(R"(, "group": "")"), {"lights[1].group", "not a group name"}});
  expect_rejected({"not a string", wall_scene(R"(, "group": 3)"), {"lights[1].group"}});
  expect_rejected({"dark shape",
                   scene_with("/shapes/0/light_group", R"("wall")"),
                   {"shapes[0].light_group", "does not emit"}});
  std::string many;
  for (int i = 0; i < 16; ++i)
    many +=
        fmt::format(R"({{"type": "point", "position": [{}, 2, 1], "intensity": 1, "group": "g{}"}},)", i, i);
  expect_rejected({"too many", wall_scene("", many), {"18 light groups (with \"other\"", "at most 16"}});
}

}  // namespace
}  // namespace ochre::test::light_groups_test
