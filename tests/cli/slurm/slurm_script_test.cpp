// ochre-slurm without a cluster (docs/distributed.md, "Slurm"): sbatch, squeue and scontrol are stubs on PATH
// that record their calls, and the batch scripts ochre-slurm writes are run by hand as Slurm would run them
// (SLURM_ARRAY_TASK_ID, SLURM_CPUS_PER_TASK). Options that cannot work are refused before anything is
// submitted (exit 2, no sbatch call, no job folder); the tasks of a frame job render and merge to the bits of
// `ochre render --frames`, with the frame numbers the renderer writes; --status reads the parts' state,
// samples and time left from crafted job folders.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <regex>
#include <string>

#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "cli/torch_scene.h"
#include "support/test_paths.h"

namespace ochre::test::slurm_script_test {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) {
  return fmt::format("'{}'", path.string());
}

void write_executable(const fs::path& path, const std::string& text) {
  write_text(path, text);
  fs::permissions(path, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec);
}

class SlurmScript : public ::testing::Test {
 protected:
  void SetUp() override {
    write_text(work / "scene.json", kTorchScene);
    fs::create_directories(stubs);
    // sbatch: records its arguments, prints job ids 100, 101, ...
    write_executable(stubs / "sbatch", fmt::format(R"(#!/bin/sh
echo "$*" >> {0}
if [ -f {1} ]; then echo "sbatch: error: refused by the stub" >&2; exit 1; fi
echo $((99 + $(wc -l < {0})))
)",
                                                   quoted(calls()), quoted(stubs / "sbatch-fails")));
    // squeue: prints what the test put in squeue.out (the lines of `-o '%F %K %T %i'`).
    write_executable(stubs / "squeue",
                     fmt::format("#!/bin/sh\ncat {} 2>/dev/null\nexit 0\n", quoted(stubs / "squeue.out")));
    write_executable(stubs / "scontrol", fmt::format("#!/bin/sh\necho \"MaxArraySize            = $(cat {} "
                                                     "2>/dev/null || echo 1001)\"\n",
                                                     quoted(stubs / "max-array-size")));
  }

  fs::path calls() const { return stubs / "sbatch-calls"; }
  std::string sbatch_calls() const { return fs::exists(calls()) ? read_file_contents(calls()) : ""; }

  // Runs ochre-slurm ARGS in the work folder with the stubs first on PATH.
  CommandResult ochre_slurm(const std::string& args, const std::string& environment = "") const {
    return run_shell(fmt::format("{} PATH={}:\"$PATH\" {} {} 2>&1", environment, quoted(stubs),
                                 quoted(bin_dir() / "ochre-slurm"), args),
                     work);
  }

  // A refusal: exit 2, the message holds `expected`, no sbatch call, no job folder.
  void expect_refused(const std::string& args, const std::string& expected) const {
    SCOPED_TRACE(args);
    const CommandResult r = ochre_slurm("scene.json --dir job " + args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;
    EXPECT_EQ(sbatch_calls(), "") << "nothing may be submitted";
    EXPECT_FALSE(fs::exists(work / "job")) << "no job folder may be left";
  }

  // Runs task `task` of the job in `dir` as Slurm would (render-part.sh with the array index set).
  CommandResult run_task(const std::string& dir, int task, const std::string& environment = "") const {
    return run_shell(fmt::format("SLURM_ARRAY_TASK_ID={} {} {}/render-part.sh 2>&1", task, environment, dir),
                     work);
  }

  fs::path work = scratch_dir();
  fs::path stubs = work / "stubs";
};

TEST_F(SlurmScript, RefusesOptionsThatCannotWorkBeforeSubmittingAnything) {
  expect_refused("--frames 3 --resume job/parts/part-0.0001.checkpoint.exr", "--resume");
  expect_refused("--frames 0", "--frames: must be a whole number between 1 and 1000000 (got '0')");
  expect_refused("--frames 2 --first-frame 999999999", "--frames: the last frame 1000000000 would exceed");
  expect_refused("--parts 2 --fps 30", "--fps: needs --frames");
  expect_refused("--frames 2 --fps 0", "--fps: must be a number in (0, 10000]");
  expect_refused("--frames 2 --fps abc", "--fps");
  expect_refused("--frames 2 --parts 2 --noise-threshold 0.05", "--parts 2: not with --noise-threshold 0.05");
  expect_refused("--frames 2 --parts 5", "--parts 5: more parts than the 4 samples per pixel");
  expect_refused("--parts 8 --spp 6", "--parts 8: more parts than the 6 samples per pixel");
  expect_refused("--tiles 25x1", "--tiles 25x1: more columns or rows than the 24x16 image has pixels");
  expect_refused("--parts 2 --sppp 8", "the render options are refused");
  expect_refused("--parts 2 --check-settings", "--check-settings");
  expect_refused("--frames 2 --part 0/2", "--part: ochre-slurm chooses the parts");
  expect_refused("--parts 2 --polarization-png pol.png", "--polarization-png: not with ochre-slurm");
  write_text(stubs / "max-array-size", "4");
  expect_refused("--frames 3 --parts 2",
                 "6 tasks (3 frames x 1x1 tiles x 2 parts): this Slurm's arrays end at index 3");
  fs::remove(stubs / "max-array-size");

  // The scene's own noise threshold, found by `ochre render --check-settings`.
  write_text(work / "adaptive.json", std::regex_replace(kTorchScene, std::regex(R"("spp": 4)"),
                                                        R"("spp": 64, "noise_threshold": 0.05)"));
  const CommandResult r = ochre_slurm("adaptive.json --parts 2 --dir job");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--parts 2: a noise-threshold render (noise threshold 0.05"), std::string::npos)
      << r.output;
  EXPECT_EQ(sbatch_calls(), "");
  EXPECT_FALSE(fs::exists(work / "job"));
  EXPECT_EQ(ochre_slurm("adaptive.json --tiles 2x1 --dir tiled").exit_code, 0) << "tiles split it";

  // The options of a job are the folder's: --resubmit and --status take none.
  const CommandResult again = ochre_slurm("--resubmit tiled --frames 2");
  EXPECT_EQ(again.exit_code, 2) << again.output;
  EXPECT_NE(again.output.find("--frames: not with --resubmit"), std::string::npos) << again.output;
}

TEST_F(SlurmScript, ASubmissionThatFailsLeavesNoFolder) {
  write_text(stubs / "sbatch-fails", "");
  const CommandResult r = ochre_slurm("scene.json --frames 2 --dir job");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("sbatch failed"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(work / "job"));
}

// The tasks of a 2-frame x 2-part job, run by hand, and its merge script give the bits of `ochre render
// --frames 2`, in files numbered as the renderer numbers them; tasks render on $SLURM_CPUS_PER_TASK threads.
TEST_F(SlurmScript, FrameTasksMergeToTheSequenceWithTheRenderersNames) {
  ASSERT_EQ(run_ochre("render scene.json --frames 2 --first-frame 9 --fps 30 -o seq.exr -q", work).exit_code,
            0);
  const CommandResult submitted = ochre_slurm(
      "scene.json --frames 2 --first-frame 9 --fps 30 --parts 2 --dir job -o out.v2/final.exr --png "
      "out.v2/final.png");
  ASSERT_EQ(submitted.exit_code, 2) << "the output folder does not exist: " << submitted.output;
  fs::create_directories(work / "out.v2");
  const CommandResult r = ochre_slurm(
      "scene.json --frames 2 --first-frame 9 --fps 30 --parts 2 --dir job -o out.v2/final.exr --png "
      "out.v2/final.png -- --time=5");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(sbatch_calls().find("--array=0-3 "), std::string::npos) << sbatch_calls();
  EXPECT_NE(sbatch_calls().find("--time=5"), std::string::npos) << sbatch_calls();

  const CommandResult task = run_task("job", 1, "SLURM_CPUS_PER_TASK=1");
  ASSERT_EQ(task.exit_code, 0) << task.output;
  EXPECT_NE(task.output.find("on 1 threads"), std::string::npos) << task.output;
  for (int i : {0, 2, 3}) ASSERT_EQ(run_task("job", i).exit_code, 0);
  for (const char* part : {"part-0.0009.exr", "part-1.0009.exr", "part-0.0010.exr", "part-1.0010.exr"})
    EXPECT_TRUE(fs::exists(work / "job/parts" / part)) << part;
  const CommandResult merged = run_shell("job/merge.sh 2>&1", work);
  ASSERT_EQ(merged.exit_code, 0) << merged.output;
  EXPECT_TRUE(same_exr_pixels(work / "seq.0009.exr", work / "out.v2/final.0009.exr"));
  EXPECT_TRUE(same_exr_pixels(work / "seq.0010.exr", work / "out.v2/final.0010.exr"));
  EXPECT_TRUE(fs::exists(work / "out.v2/final.0010.png"));
  const CommandResult again = run_shell("job/merge.sh 2>&1", work);
  EXPECT_NE(again.output.find("frame 9: " + (work / "out.v2/final.0009.exr").string() + " exists"),
            std::string::npos)
      << "merged frames are not merged again: " << again.output;

  // Names as `ochre render --frames` writes them, for names without an extension or with a dot in front.
  int job = 0;
  for (const std::string name : {"noext", ".hidden", "a.b.exr", "x."}) {
    fs::create_directories(work / "r");
    ASSERT_EQ(run_ochre("render scene.json --frames 1 --first-frame 12345 -q -o r/" + name, work).exit_code,
              0);
    const std::string dir = "names-" + std::to_string(job++);
    ASSERT_EQ(
        ochre_slurm("scene.json --frames 1 --first-frame 12345 --dir " + dir + " -o " + dir + "/" + name)
            .exit_code,
        0);
    ASSERT_EQ(run_task(dir, 0).exit_code, 0);
    ASSERT_EQ(run_shell(dir + "/merge.sh >/dev/null 2>&1", work).exit_code, 0);
    for (const auto& entry : fs::directory_iterator(work / "r")) {
      EXPECT_TRUE(fs::exists(work / dir / entry.path().filename())) << entry.path().filename();
    }
    fs::remove_all(work / "r");
  }
}

// --status of a crafted job: a rendered part, a running part with a checkpoint (samples, share, time left),
// a running part without one yet, a pending one; then, with Slurm no longer listing them, a stopped part with
// a checkpoint, a failed one (its log is there) and a missing one. --resubmit is refused while tasks run.
TEST_F(SlurmScript, StatusShowsEveryPartsStateSamplesAndTimeLeft) {
  ASSERT_EQ(ochre_slurm("scene.json --frames 2 --parts 2 --spp 400000 --dir job").exit_code, 0);
  // Crafted parts: frame 1's part 0 (of a cheaper render: only its file and header matter here) and part 1
  // stopped at a time limit, whose checkpoint holds a few of its 200000 samples (a longer limit when not one
  // sample was done in time).
  ASSERT_EQ(
      run_ochre("render scene.json --spp 8 --frames 1 --first-frame 1 --part 0/2 -o job/parts/part-0.exr -q",
                work)
          .exit_code,
      0);
  for (double limit = 1.0; limit <= 8.0 && !fs::exists(work / "job/parts/part-1.0001.checkpoint.exr");
       limit *= 2)
    run_ochre(fmt::format("render scene.json --spp 400000 --frames 1 --first-frame 1 --tile 0/1x1 --part 1/2 "
                          "-o job/parts/part-1.exr --checkpoint job/parts/part-1.0001.checkpoint.exr "
                          "--time-limit {} -q",
                          limit),
              work);
  ASSERT_TRUE(fs::exists(work / "job/parts/part-1.0001.checkpoint.exr"));
  const CommandResult info =
      run_ochre("info job/parts/part-1.0001.checkpoint.exr job/parts/part-0.0001.exr", work);
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_TRUE(std::regex_search(
      info.output,
      std::regex(R"(part-1.0001.checkpoint.exr: checkpoint, frame 1 at 24 fps, region 0,0,24,16 of )"
                 R"(24x16, samples 200000:\d+ of 200000:400000 \(\d+ of 200000 per pixel, [0-9.]+ %\), )"
                 R"([0-9.]+ s of rendering, about \d+ s left)")))
      << info.output;
  EXPECT_NE(info.output.find("part-0.0001.exr: partial sums, frame 1 at 24 fps, region 0,0,24,16 of 24x16, "
                             "samples 0:4 (4 per pixel)"),
            std::string::npos)
      << info.output;

  write_text(stubs / "squeue.out",
             "100 1 RUNNING 100_1\n100 2 RUNNING 100_2\n100 3 PENDING 100_3\n101 N/A PENDING 101\n");
  const CommandResult status = ochre_slurm("--status job");
  ASSERT_EQ(status.exit_code, 0) << status.output;
  EXPECT_TRUE(std::regex_search(status.output, std::regex(R"(\n +0 +1 +0  rendered +4 of 4 +100 %  -\n)")))
      << status.output;
  EXPECT_TRUE(std::regex_search(
      status.output, std::regex(R"(\n +1 +1 +1  running +\d+ of 200000 +[0-9.]+ %  \d+:\d\d:\d\d\n)")))
      << status.output;
  EXPECT_TRUE(std::regex_search(status.output, std::regex(R"(\n +2 +2 +0  running +- +-  -\n)")))
      << status.output;
  EXPECT_TRUE(std::regex_search(status.output, std::regex(R"(\n +3 +2 +1  pending +- +0 %  -\n)")))
      << status.output;
  EXPECT_NE(status.output.find("parts rendered: 1 of 4 (running 2, pending 1)"), std::string::npos)
      << status.output;
  EXPECT_NE(status.output.find("frames merged: 0 of 2"), std::string::npos) << status.output;
  EXPECT_NE(status.output.find("jobs: merge 101 PENDING, report 102 (no longer listed)"), std::string::npos)
      << status.output;

  const CommandResult resubmit = ochre_slurm("--resubmit job");
  EXPECT_EQ(resubmit.exit_code, 2) << resubmit.output;
  EXPECT_NE(resubmit.output.find(" is still "), std::string::npos) << resubmit.output;

  write_text(stubs / "squeue.out", "");
  write_text(work / "job/logs/render-100_2.log", "ochre: error: ...\n");
  const CommandResult later = ochre_slurm("--status job");
  ASSERT_EQ(later.exit_code, 0) << later.output;
  EXPECT_TRUE(std::regex_search(
      later.output,
      std::regex(R"(\n +1 +1 +1  checkpointed +\d+ of 200000 +[0-9.]+ %  \d+:\d\d:\d\d when resumed\n)")))
      << later.output;
  EXPECT_TRUE(std::regex_search(later.output, std::regex(R"(\n +2 +2 +0  failed +- +0 %  -\n)")))
      << later.output;
  EXPECT_TRUE(std::regex_search(later.output, std::regex(R"(\n +3 +2 +1  missing +- +0 %  -\n)")))
      << later.output;

  const CommandResult resubmitted = ochre_slurm("--resubmit job");
  ASSERT_EQ(resubmitted.exit_code, 0) << resubmitted.output;
  EXPECT_NE(sbatch_calls().find("--array=1,2,3 "), std::string::npos) << sbatch_calls();
}

}  // namespace
}  // namespace ochre::test::slurm_script_test
