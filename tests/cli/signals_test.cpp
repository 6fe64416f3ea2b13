// SIGINT and SIGTERM during a render or while its outputs are written, or while ochre-vgroove draws the
// panels of a grid: the process ends by the signal (a shell shows 130 or 143), no temporary "*.tmp-*"
// file or directory is left, and existing outputs are intact.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "cli/cli_runner.h"
#include "cli/file_test_support.h"
#include "cli/process_control.h"
#include "support/test_paths.h"

namespace ochre::test::signals_test {
namespace {

namespace fs = std::filesystem;

struct Outputs {
  fs::path dir = scratch_dir();
  FileSnapshot exr, png;
  Outputs() {
    write_old_file(dir / "out.exr", "the previous EXR");
    write_old_file(dir / "out.png", "the previous PNG");
    exr = snapshot(dir / "out.exr");
    png = snapshot(dir / "out.png");
  }
  bool untouched() const { return snapshot(dir / "out.exr") == exr && snapshot(dir / "out.png") == png; }
};

void expect_signal_during_render_is_clean(int signal_number) {
  const Outputs o;
  // 32 x 32 x 100000 samples: far longer than the test waits.
  std::string scene = minimal_scene();
  scene.replace(scene.find("[8, 8]"), 6, "[32, 32]");
  scene.replace(scene.find("\"spp\": 1"), 8, "\"spp\": 100000");
  write_text(o.dir / "scene.json", scene);
  const pid_t pid = start_tool(o.dir, "ochre", "render scene.json -o out.exr --png out.png");
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  ASSERT_EQ(::kill(pid, signal_number), 0);
  const int status = wait_for(pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "ochre must end by the signal, status " << status;
  EXPECT_EQ(WTERMSIG(status), signal_number);
  EXPECT_TRUE(temporaries_in(o.dir).empty());
  EXPECT_TRUE(o.untouched());
}

TEST(Signals, SigintDuringARender) {
  expect_signal_during_render_is_clean(SIGINT);
}

TEST(Signals, SigtermDuringARender) {
  expect_signal_during_render_is_clean(SIGTERM);
}

// The signal arrives once a temporary output exists, i.e. while the outputs are written.
void expect_signal_during_writing_is_clean(int signal_number) {
  const Outputs o;
  std::string scene = minimal_scene();
  scene.replace(scene.find("[8, 8]"), 6, "[512, 512]");
  write_text(o.dir / "scene.json", scene);
  const pid_t pid =
      start_tool(o.dir, "ochre", "render scene.json -o out.exr --png out.png --spectral-bins 32 --aovs");
  ASSERT_TRUE(wait_until(pid, [&] { return !temporaries_in(o.dir).empty(); })) << "no temporary output seen";
  ASSERT_EQ(::kill(pid, signal_number), 0);
  const int status = wait_for(pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "ochre must end by the signal, status " << status;
  EXPECT_EQ(WTERMSIG(status), signal_number);
  EXPECT_TRUE(temporaries_in(o.dir).empty());
  // Normally nothing was replaced; should the signal have come during the final renames, it waited for
  // them: both files are then new, never one new and one old.
  const bool exr_old = snapshot(o.dir / "out.exr") == o.exr, png_old = snapshot(o.dir / "out.png") == o.png;
  EXPECT_EQ(exr_old, png_old);
}

TEST(Signals, SigintWhileTheOutputsAreWritten) {
  expect_signal_during_writing_is_clean(SIGINT);
}

TEST(Signals, SigtermWhileTheOutputsAreWritten) {
  expect_signal_during_writing_is_clean(SIGTERM);
}

// The grid's panels go to a scratch directory beside the output: the signal removes it with its files.
TEST(Signals, SigtermWhileOchreVGrooveDrawsTheGridPanels) {
  const Outputs o;
  const pid_t pid = start_tool(o.dir, "ochre-vgroove",
                               "maps --material Au,Ag,Cu,Si --alpha 30,60,90 --size 256 -o out.png");
  const fs::path scratch = o.dir / fmt::format("out.png.panels.tmp-{}", pid);
  ASSERT_TRUE(wait_until(pid, [&] { return fs::exists(scratch / "colour_0.png"); }))
      << "the first panel was not seen";
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  const int status = wait_for(pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "ochre-vgroove must end by the signal, status " << status;
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_FALSE(fs::exists(scratch));
  EXPECT_TRUE(temporaries_in(o.dir).empty());
  EXPECT_TRUE(o.untouched());
}

}  // namespace
}  // namespace ochre::test::signals_test
