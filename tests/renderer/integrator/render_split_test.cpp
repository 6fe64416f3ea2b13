// A render split into sample ranges and merged equals the single render bit for bit.
#include <gtest/gtest.h>

#include "renderer/integrator/render.h"
#include "renderer/loader/scene_loader.h"
#include "support/test_paths.h"

namespace ochre::render_split_test {
namespace {

TEST(RenderSplit, MergedSampleRangesEqualOneRender) {
  SceneOverrides o;
  o.width = 24;
  o.height = 24;
  o.spp = 8;
  auto scene = load_scene(test::source_dir() / "scenes/cornell-box/cornell-box.json", o);
  Film whole(24, 24);
  render(*scene.scene, scene.job, whole);

  Film part_a(24, 24), part_b(24, 24);
  scene.job.settings.sample_begin = 0;
  scene.job.settings.spp = 3;
  render(*scene.scene, scene.job, part_a);
  scene.job.settings.sample_begin = 3;
  scene.job.settings.spp = 5;
  scene.job.settings.threads = 1;
  render(*scene.scene, scene.job, part_b);
  part_b.merge(part_a);

  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) {
      const XYZ a = whole.mean(x, y), b = part_b.mean(x, y);
      ASSERT_EQ(a.x, b.x) << x << "," << y;
      ASSERT_EQ(a.y, b.y) << x << "," << y;
      ASSERT_EQ(a.z, b.z) << x << "," << y;
    }
  EXPECT_GT(whole.mean(12, 12).y, 0.0f);
}

}  // namespace
}  // namespace ochre::render_split_test
