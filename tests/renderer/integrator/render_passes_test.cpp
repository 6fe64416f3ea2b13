// Renders in passes stop at clean sample boundaries and sum to the bits of one render.
#include "renderer/integrator/render_passes.h"

#include <gtest/gtest.h>

#include "renderer/integrator/branch_choice.h"
#include "renderer/loader/scene_loader.h"
#include "support/test_paths.h"

namespace ochre::render_passes_test {
namespace {

LoadedScene small_cornell() {
  SceneOverrides o;
  o.width = 20;
  o.height = 12;
  o.spp = 9;
  LoadedScene scene = load_scene(test::source_dir() / "scenes/cornell-box/cornell-box.json", o);
  scene.job = resolve_branches(*scene.scene, scene.job);  // sample ranges count camera samples
  return scene;
}

void expect_same_film(const Film& a, const Film& b) {
  for (size_t k = 0; k < a.accumulator_names().size(); ++k)
    for (size_t p = 0; p < static_cast<size_t>(a.width()) * a.height(); ++p)
      ASSERT_TRUE(a.accumulator(k, p) == b.accumulator(k, p)) << a.accumulator_names()[k] << " pixel " << p;
}

TEST(RenderPasses, AStopRequestEndsAtAPassBoundaryThatResumesBitForBit) {
  const auto scene = small_cornell();
  const PixelRect rect{3, 2, 17, 11};
  Film whole(rect.width(), rect.height()), passes(rect.width(), rect.height());
  render_range(*scene.scene, scene.job, whole, rect, {2, 9});
  int asked = 0;
  PassSchedule one_sample_passes;
  one_sample_passes.pass_seconds = 1e-9;
  const PassResult first = render_in_passes(
      *scene.scene, scene.job, passes, rect, {2, 9}, one_sample_passes, {},
      [](uint32_t, const RenderStats&) { FAIL() << "no interval"; }, [&] { return ++asked > 2; });
  EXPECT_EQ(first.stop, PassStop::stop_requested);
  EXPECT_EQ(first.next, 4u);  // two passes of one sample
  EXPECT_EQ(passes.sample_count(0, 0), first.next - 2);
  const PassResult rest = render_in_passes(*scene.scene, scene.job, passes, rect, {first.next, 9}, {}, {}, {},
                                           [] { return false; });
  EXPECT_EQ(rest.stop, PassStop::finished);
  EXPECT_EQ(rest.next, 9u);
  expect_same_film(whole, passes);
}

TEST(RenderPasses, APassedDeadlineRendersNothing) {
  const auto scene = small_cornell();
  Film film(20, 12);
  PassSchedule schedule;
  schedule.deadline = PassSchedule::Clock::now() - std::chrono::seconds(1);
  const PassResult r = render_in_passes(*scene.scene, scene.job, film, {0, 0, 20, 12}, {0, 9}, schedule, {},
                                        {}, [] { return false; });
  EXPECT_EQ(r.stop, PassStop::deadline);
  EXPECT_EQ(r.next, 0u);
  EXPECT_EQ(film.sample_count(5, 5), 0u);
}

TEST(RenderPasses, CheckpointsComeAtIntervalsAndNeverAfterTheLastPass) {
  const auto scene = small_cornell();
  Film film(20, 12);
  PassSchedule schedule;
  schedule.checkpoint_interval = 1e-9;  // after every pass
  schedule.pass_seconds = 1e-9;         // one sample per pass
  std::vector<uint32_t> at;
  const PassResult r = render_in_passes(
      *scene.scene, scene.job, film, {0, 0, 20, 12}, {0, 9}, schedule, {},
      [&](uint32_t next, const RenderStats& so_far) {
        at.push_back(next);
        EXPECT_EQ(so_far.samples, 20u * 12u * next);
      },
      [] { return false; });
  EXPECT_EQ(r.next, 9u);
  EXPECT_EQ(at, (std::vector<uint32_t>{1, 2, 3, 4, 5, 6, 7, 8}));
}

}  // namespace
}  // namespace ochre::render_passes_test
