// `ochre render --frames N --fps F` (docs/cli.md#frame-sequences): numbered outputs, every frame a pure
// function of (seed, frame) so that a frame rendered alone equals the same frame of a sequence bit for bit,
// flames that flicker between frames, and bad values of the options refused with exit code 2 and no file.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "cli/torch_scene.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::frame_sequences_test {
namespace {

// The wall lit by a torch and a grease lamp (cli/torch_scene.h).
std::filesystem::path torch_dir() {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", kTorchScene);
  return dir;
}

double mean_red(const ExrImage& image) {
  return mean_of(exr_channel(image, "R"));
}

TEST(FrameSequences, WritesNumberedOutputs) {
  const auto dir = torch_dir();
  const CommandResult r = run_ochre("render scene.json -o out.exr --png out.png --frames 3 --fps 24", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* name : {"out.0001.exr", "out.0002.exr", "out.0003.exr", "out.0001.png", "out.0003.png"})
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.0004.exr"));
  EXPECT_NE(r.output.find("frame 3 of 3"), std::string::npos) << r.output;
}

TEST(FrameSequences, FrameAloneEqualsFrameOfTheSequence) {
  const auto dir = torch_dir();
  ASSERT_EQ(run_ochre("render scene.json -o seq.exr --frames 4 --fps 30 -q", dir).exit_code, 0);
  ASSERT_EQ(run_ochre("render scene.json -o alone.exr --frames 1 --first-frame 3 --fps 30 -q", dir).exit_code,
            0);
  EXPECT_FALSE(std::filesystem::exists(dir / "alone.0001.exr"));
  EXPECT_TRUE(same_rgb_values(read_exr(dir / "alone.0003.exr"), read_exr(dir / "seq.0003.exr")));
  // The flames flicker: consecutive frames differ, and differ from the still render at the mean.
  const ExrImage f2 = read_exr(dir / "seq.0002.exr"), f3 = read_exr(dir / "seq.0003.exr");
  EXPECT_NE(mean_red(f2), mean_red(f3));
  ASSERT_EQ(run_ochre("render scene.json -o still.exr -q", dir).exit_code, 0);
  EXPECT_FALSE(same_rgb_values(read_exr(dir / "still.exr"), f3));
}

TEST(FrameSequences, SeedChangesTheFlicker) {
  const auto dir = torch_dir();
  ASSERT_EQ(run_ochre("render scene.json -o a.exr --frames 1 --first-frame 5 --seed 1 -q", dir).exit_code, 0);
  ASSERT_EQ(run_ochre("render scene.json -o b.exr --frames 1 --first-frame 5 --seed 2 -q", dir).exit_code, 0);
  EXPECT_NE(mean_red(read_exr(dir / "a.0005.exr")), mean_red(read_exr(dir / "b.0005.exr")));
}

// One frame of a sequence is split and checkpointed like a still (the frame is part of the render's
// identity): parts of frame 3 merge to the bits of frame 3 of the sequence, a frame stopped at a time limit
// resumes to them, parts of different frames do not merge, and a split of several frames is refused.
TEST(FrameSequences, OneFrameIsSplitAndCheckpointedLikeAStill) {
  const auto dir = torch_dir();
  const std::string frame3 = "render scene.json --frames 1 --first-frame 3 --fps 30 -q";
  ASSERT_EQ(run_ochre("render scene.json -o seq.exr --frames 3 --fps 30 --spp 64 -q", dir).exit_code, 0);
  ASSERT_EQ(run_ochre(frame3 + " --spp 64 --part 0/2 -o p0.exr", dir).exit_code, 0);
  ASSERT_EQ(run_ochre(frame3 + " --spp 64 --part 1/2 -o p1.exr", dir).exit_code, 0);
  ASSERT_TRUE(std::filesystem::exists(dir / "p0.0003.exr")) << "parts are numbered as the sequence's frames";
  ASSERT_EQ(run_ochre("merge p0.0003.exr p1.0003.exr -o merged.exr -q", dir).exit_code, 0);
  EXPECT_TRUE(same_exr_pixels(dir / "merged.exr", dir / "seq.0003.exr"));
  EXPECT_EQ(read_exr(dir / "p0.0003.exr").string_attributes.at("ochre.frame"), "3 at 30 fps");

  // Parts of different frames are different renders.
  ASSERT_EQ(
      run_ochre("render scene.json --frames 1 --first-frame 2 --fps 30 --spp 64 -q --part 1/2 -o p1.exr", dir)
          .exit_code,
      0);
  const CommandResult mixed = run_ochre("merge p0.0003.exr p1.0002.exr -o mixed.exr", dir);
  EXPECT_EQ(mixed.exit_code, 2) << mixed.output;
  EXPECT_NE(mixed.output.find("ochre.frame"), std::string::npos) << mixed.output;

  // A checkpoint of the frame (a checkpoint file written at once, then resumed to the end).
  ASSERT_EQ(run_ochre(frame3 + " --spp 64 -o ck.exr --checkpoint-interval 1h", dir).exit_code, 0);
  EXPECT_TRUE(same_exr_pixels(dir / "ck.0003.exr", dir / "seq.0003.exr"));
  CommandResult stopped;
  for (double limit = 0.6; limit <= 10; limit *= 2) {
    stopped = run_ochre(frame3 + " --spp 100000 -o long.exr --time-limit " + std::to_string(limit), dir);
    if (stopped.exit_code != 3 || std::filesystem::exists(dir / "long.0003.checkpoint.exr")) break;
  }
  ASSERT_EQ(stopped.exit_code, 3) << stopped.output;
  const ExrImage checkpoint = read_exr(dir / "long.0003.checkpoint.exr");
  EXPECT_EQ(checkpoint.string_attributes.at("ochre.frame"), "3 at 30 fps");
  EXPECT_EQ(checkpoint.string_attributes.at("ochre.checkpoint.exr"), (dir / "long.0003.exr").string());
  // Resumed, it is the same frame's render (a mismatch of identity would be exit 2) and keeps its names.
  const CommandResult resumed =
      run_ochre("render --resume long.0003.checkpoint.exr -q --time-limit 1.5", dir);
  EXPECT_EQ(resumed.exit_code, 3) << resumed.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "long.0003.checkpoint.exr"));
  EXPECT_FALSE(std::filesystem::exists(dir / "long.0003.0003.exr"));

  const CommandResult several = run_ochre("render scene.json --frames 2 --part 0/2 -o p.exr", dir);
  EXPECT_EQ(several.exit_code, 2) << several.output;
  EXPECT_NE(several.output.find("--part: not with --frames 2"), std::string::npos) << several.output;
  EXPECT_NE(several.output.find("--frames 1 --first-frame K"), std::string::npos) << several.output;
}

// Every bad value: exit code 2, a message naming the option, no output written.
TEST(FrameSequences, BadOptionValuesAreRefused) {
  const struct {
    const char* args;
    const char* expected;
  } cases[] = {
      {"--frames 0", "--frames: must be between 1 and"},
      {"--frames -1", "--frames: must be between 1 and 1000000 (got -1)"},
      {"--frames 2 --first-frame -3", "--first-frame: must be between 1 and 999999999 (got -3)"},
      {"--frames 2000000", "--frames: must be between 1 and"},
      {"--frames many", "--frames"},
      {"--frames 2 --fps 0", "--fps: must be a number in (0, 10000]"},
      {"--frames 2 --fps -24", "--fps"},
      {"--frames 2 --fps nan", "--fps"},
      {"--frames 2 --fps inf", "--fps"},
      {"--frames 2 --fps 1e6", "--fps: must be a number in (0, 10000]"},
      {"--frames 2 --fps fast", "--fps"},
      {"--fps 24", "--fps: needs --frames"},
      {"--first-frame 3", "--first-frame: needs --frames"},
      {"--frames 2 --first-frame 0", "--first-frame: must be between 1 and"},
      {"--frames 10 --first-frame 999999995", "would exceed"},
  };
  for (const auto& c : cases) {
    const auto dir = torch_dir();
    const CommandResult r = run_ochre(std::string("render scene.json -o out.exr ") + c.args, dir);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      EXPECT_EQ(entry.path().filename(), "scene.json") << c.args << ": wrote " << entry.path();
  }
}

// A frame's output that cannot be written (a directory in the way) is found before the first frame renders.
TEST(FrameSequences, EveryFrameOutputIsCheckedFirst) {
  const auto dir = torch_dir();
  std::filesystem::create_directory(dir / "out.0002.exr");
  const CommandResult r = run_ochre("render scene.json -o out.exr --frames 3", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("out.0002.exr"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.0001.exr"));
}

}  // namespace
}  // namespace ochre::test::frame_sequences_test
