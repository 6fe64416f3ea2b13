// Checkpoints and resume (docs/distributed.md, "Checkpoints"): a render stopped by SIGTERM or SIGINT, or
// at --time-limit, writes a checkpoint at a sample boundary; `ochre render --resume` finishes it with the
// bits of an uninterrupted render. Bad checkpoints and options are refused with exit code 2.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "cli/file_test_support.h"
#include "cli/process_control.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::checkpoint_test {
namespace {

namespace fs = std::filesystem;

std::string scene(const std::string& name) {
  return fmt::format("'{}'", (source_dir() / "scenes/cornell-box" / name).string());
}

// A copy of the Cornell box (in `dir`) that traces one path per camera sample with roulette from depth 5,
// whatever the pilot of integrator.branches and rr_depth "auto" would choose: --spp then counts camera
// samples, so the image of N samples done is the render of --spp N
// (docs/architecture.md#automatic-branch-count).
std::string one_path_cornell(const fs::path& dir) {
  const fs::path copy = dir / "box";
  fs::copy(source_dir() / "scenes/cornell-box", copy, fs::copy_options::recursive);
  std::ifstream in(copy / "cornell-box.json");
  nlohmann::json j = nlohmann::json::parse(in);
  j["integrator"]["branches"] = 1;
  j["integrator"]["rr_depth"] = 5;
  std::ofstream(copy / "cornell-box.json") << j.dump(1);
  return fmt::format("'{}'", (copy / "cornell-box.json").string());
}

// All the layers a checkpoint must carry exactly: AOVs, Stokes, spectral bins (per Stokes component).
const std::string kLayers = "--resolution 48x32 --aovs --stokes --spectral-bins 2";
const std::string kPolarized = "cornell-box-polarized.json";

void render_reference(const fs::path& dir, const std::string& args) {
  const CommandResult r = run_ochre("render " + scene(kPolarized) + " " + args + " -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
}

// Runs `ochre ARGS --time-limit T` for T = base, 2 base, 4 base, ... until the limit stops the render after
// some samples (exit 3 with CHECKPOINT written): on a loaded machine the first limit may pass before any
// sample finishes, which writes nothing (docs/cli.md), and is not what these tests are about.
CommandResult stop_at_a_time_limit(const std::string& args, const fs::path& dir, const fs::path& checkpoint,
                                   double base) {
  CommandResult r;
  for (double limit = base; limit <= 16 * base; limit *= 2) {
    r = run_ochre(fmt::format("{} --time-limit {}", args, limit), dir);
    if (r.exit_code != 3 || fs::exists(dir / checkpoint)) return r;
  }
  return r;
}

void expect_stopped_by_signal_then_resumed(int signal_number) {
  const fs::path dir = scratch_dir();
  render_reference(dir, kLayers + " --spp 600 -o single.exr --png single.png");
  write_old_file(dir / "out.exr", "the previous EXR");
  const FileSnapshot before = snapshot(dir / "out.exr");
  const pid_t pid = start_tool(dir, "ochre",
                               "render " + scene(kPolarized) + " " + kLayers +
                                   " --spp 600 -o out.exr --png out.png --checkpoint-interval 0.2 --preview");
  ASSERT_TRUE(wait_until(pid, [&] { return fs::exists(dir / "out.checkpoint.exr"); }))
      << "no checkpoint seen";
  ASSERT_EQ(::kill(pid, signal_number), 0);
  const int status = wait_for(pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "ochre must end by the signal, status " << status;
  EXPECT_EQ(WTERMSIG(status), signal_number);
  EXPECT_TRUE(temporaries_in(dir).empty());
  EXPECT_TRUE(snapshot(dir / "out.exr") == before) << "the final EXR is written only when complete";
  EXPECT_TRUE(fs::exists(dir / "out.png")) << "--preview refreshes the display image with each checkpoint";
  const ExrImage checkpoint = read_exr(dir / "out.checkpoint.exr");
  const std::string& coverage = checkpoint.string_attributes.at("ochre.coverage");
  EXPECT_NE(coverage, "0,0,48,32:0:600") << "stopped before the end";

  const CommandResult resumed = run_ochre("render --resume out.checkpoint.exr", dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_TRUE(contains(resumed.output, "resuming out.checkpoint.exr: samples 0:")) << resumed.output;
  EXPECT_TRUE(same_exr_pixels(dir / "single.exr", dir / "out.exr"));
  EXPECT_FALSE(fs::exists(dir / "out.checkpoint.exr")) << "a finished render removes its checkpoint";
  EXPECT_TRUE(temporaries_in(dir).empty());
}

TEST(Checkpoint, SigtermMidRenderThenResumeGivesTheUninterruptedBits) {
  expect_stopped_by_signal_then_resumed(SIGTERM);
}

TEST(Checkpoint, SigintMidRenderThenResumeGivesTheUninterruptedBits) {
  expect_stopped_by_signal_then_resumed(SIGINT);
}

// --time-limit: exit 3 with the image of the samples done (that of a render with that many samples) and a
// checkpoint; resuming (again under a limit, then without) finishes the render.
TEST(Checkpoint, TimeLimitStopsWithAValidImageAndACheckpoint) {
  const fs::path dir = scratch_dir();
  const std::string box = one_path_cornell(dir);
  const std::string args = "render " + box + " --resolution 64x64 --spp 4000 -o out.exr --png out.png";
  const CommandResult stopped = stop_at_a_time_limit(args, dir, "out.checkpoint.exr", 1.5);
  ASSERT_EQ(stopped.exit_code, 3) << stopped.output;
  EXPECT_TRUE(
      contains(stopped.output, "time limit reached; continue with: ochre render --resume out.checkpoint.exr"))
      << stopped.output;
  const ExrImage image = read_exr(dir / "out.exr");
  const std::string range = image.string_attributes.at("ochre.sampleRange");  // "0-N"
  const int done = std::stoi(range.substr(2));
  ASSERT_GT(done, 0);
  ASSERT_LT(done, 4000);
  const CommandResult lower = run_ochre("render " + box + " --resolution 64x64 --spp " +
                                            std::to_string(done) + " -o lower.exr --png lower.png -q",
                                        dir);
  ASSERT_EQ(lower.exit_code, 0) << lower.output;
  EXPECT_TRUE(same_exr_pixels(dir / "lower.exr", dir / "out.exr"));
  ASSERT_TRUE(fs::exists(dir / "out.checkpoint.exr"));
  EXPECT_TRUE(temporaries_in(dir).empty());
}

// A part stopped at its time limit writes only its checkpoint (which merges with --partial meanwhile);
// resumed under a limit again, then without, it finishes and merges to the single render's bits.
TEST(Checkpoint, TimeLimitedResumesOfAPartFinishAndMerge) {
  const fs::path dir = scratch_dir();
  const std::string cornell = scene("cornell-box.json") + " --resolution 40x24 --spp 2000 -q";
  ASSERT_EQ(run_ochre("render " + cornell + " -o single.exr --png single.png", dir).exit_code, 0);
  ASSERT_EQ(run_ochre("render " + cornell + " --part 0/2 -o p0.exr", dir).exit_code, 0);
  // 1 s, of which 0.5 s are reserved for writing: far less than the part needs, enough for some samples
  // (a limit that leaves no sample done writes nothing, docs/cli.md).
  const CommandResult stopped =
      stop_at_a_time_limit("render " + cornell + " --part 1/2 -o p1.exr", dir, "p1.checkpoint.exr", 1);
  ASSERT_EQ(stopped.exit_code, 3) << stopped.output;
  EXPECT_FALSE(fs::exists(dir / "p1.exr")) << "a part's partial sums are written when complete";
  ASSERT_TRUE(fs::exists(dir / "p1.checkpoint.exr"));
  EXPECT_EQ(run_ochre("merge p0.exr p1.checkpoint.exr --partial -o preview.exr -q", dir).exit_code, 0);
  const int again = run_ochre("render --resume p1.checkpoint.exr -q --time-limit 1.5", dir).exit_code;
  EXPECT_TRUE(again == 0 || again == 3) << again;
  if (again == 3) {
    ASSERT_EQ(run_ochre("render --resume p1.checkpoint.exr -q", dir).exit_code, 0);
  }
  EXPECT_FALSE(fs::exists(dir / "p1.checkpoint.exr"));
  ASSERT_EQ(run_ochre("merge p0.exr p1.exr -o merged.exr -q", dir).exit_code, 0);
  EXPECT_TRUE(same_exr_pixels(dir / "single.exr", dir / "merged.exr"));
}

// Renders `scene` (in dir) whole to single.exr, whose summary must say `summary`; then again, stopped at a
// time limit, whose checkpoint must record `attribute` = `value`; then resumes it (`resumed`: that run) and
// expects the whole render's bits.
void resume_to_the_whole_render(const fs::path& dir, const std::string& scene, const std::string& summary,
                                const std::string& attribute, const std::string& value,
                                CommandResult& resumed) {
  const CommandResult single = run_ochre("render " + scene + " -o single.exr", dir);
  ASSERT_EQ(single.exit_code, 0) << single.output;
  EXPECT_TRUE(contains(single.output, summary)) << single.output;
  const CommandResult stopped =
      stop_at_a_time_limit("render " + scene + " -o out.exr -q", dir, "out.checkpoint.exr", 1.5);
  ASSERT_EQ(stopped.exit_code, 3) << stopped.output;
  EXPECT_EQ(read_exr(dir / "out.checkpoint.exr").string_attributes.at(attribute), value);
  resumed = run_ochre("render --resume out.checkpoint.exr", dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_TRUE(same_exr_pixels(dir / "single.exr", dir / "out.exr"));
}

// Two lights: the pilot's choice to sample both at every vertex (light_selection "auto") is recorded in the
// checkpoint, and the resumed render takes it from there (no pilot of its own): the uninterrupted bits.
TEST(Checkpoint, ResumeKeepsTheChosenLightSampling) {
  const fs::path dir = scratch_dir();
  std::ofstream(dir / "two_lights.json") << R"({
      "camera": {"type": "orthographic", "size": 4, "eye": [0, 0, 5], "target": [0, 0, 0]},
      "film": {"resolution": [32, 32]},
      "integrator": {"spp": 8192, "max_depth": 3},
      "materials": {"m": {"type": "lambert", "color": 0.5}},
      "lights": [{"type": "point", "position": [0, 0, 1], "intensity": 10},
                 {"type": "environment", "radiance": 0.2}],
      "shapes": [{"type": "plane", "size": [100, 100], "material": "m"}]
    })";
  CommandResult resumed;
  ASSERT_NO_FATAL_FAILURE(resume_to_the_whole_render(
      dir, "two_lights.json", "all 2 lights sampled at each vertex", "ochre.lightSelection", "all", resumed));
  EXPECT_FALSE(contains(resumed.output, "pilot")) << "the checkpoint's choices are taken, not made again";
}

// A guided render (integrator.guiding on): the resumed render trains its guide again, from the same whole
// render's settings (the branches and roulette it takes from the checkpoint change nothing there), and ends
// with the uninterrupted bits.
TEST(Checkpoint, GuidedRenderResumesToTheSameBits) {
  const fs::path dir = scratch_dir();
  std::ofstream(dir / "guided.json") << R"({
      "camera": {"type": "perspective", "fov": 40, "eye": [0, -4, 2], "target": [0, 0, 0.5]},
      "film": {"resolution": [32, 32]},
      "integrator": {"spp": 4096, "max_depth": 4, "guiding": "on"},
      "materials": {"m": {"type": "lambert", "color": 0.7}},
      "lights": [{"type": "point", "position": [1, -1, 3], "intensity": 10},
                 {"type": "environment", "radiance": 0.05}],
      "shapes": [{"type": "plane", "size": [20, 20], "material": "m"},
                 {"type": "sphere", "center": [0, 0, 0.5], "radius": 0.5, "material": "m"}]
    })";
  CommandResult resumed;
  resume_to_the_whole_render(dir, "guided.json", "path guiding: guided by", "ochre.guiding", "on", resumed);
}

// A resumed render keeps the checkpoint interval it was started with (recorded in the checkpoint) unless
// its command line gives another. The rendering seconds a checkpoint records add up over the resumes, and
// `ochre info` estimates the time left from them.
TEST(Checkpoint, ResumeKeepsTheCheckpointIntervalAndAddsUpTheRenderingTime) {
  const fs::path dir = scratch_dir();
  const std::string args =
      "render " + one_path_cornell(dir) + " --resolution 32x16 --spp 100000 -o out.exr -q";
  ASSERT_EQ(
      stop_at_a_time_limit(args + " --checkpoint-interval 1h30m", dir, "out.checkpoint.exr", 1).exit_code, 3);
  auto interval = [&] {
    return read_exr(dir / "out.checkpoint.exr").string_attributes.at("ochre.checkpoint.interval");
  };
  EXPECT_EQ(interval(), "5400s");
  auto seconds = [&] {
    return std::stod(read_exr(dir / "out.checkpoint.exr").string_attributes.at("ochre.checkpoint.seconds"));
  };
  const double first = seconds();
  const std::string held = read_exr(dir / "out.checkpoint.exr").string_attributes.at("ochre.coverage");
  EXPECT_GT(first, 0.0);
  const CommandResult info = run_ochre("info out.checkpoint.exr", dir);
  EXPECT_EQ(info.exit_code, 0) << info.output;
  EXPECT_TRUE(contains(info.output, "out.checkpoint.exr: checkpoint, region 0,0,32,16 of 32x16, samples 0:"))
      << info.output;
  EXPECT_TRUE(contains(info.output, " of 0:100000 (")) << info.output;
  EXPECT_TRUE(contains(info.output, " s of rendering, about ")) << info.output;
  ASSERT_EQ(
      stop_at_a_time_limit("render --resume out.checkpoint.exr -q", dir, "out.checkpoint.exr", 1).exit_code,
      3);
  EXPECT_EQ(interval(), "5400s");
  if (read_exr(dir / "out.checkpoint.exr").string_attributes.at("ochre.coverage") != held) {
    EXPECT_GT(seconds(), first) << "the seconds of the first run and of the resumed one";
  } else {  // the resumed run's limit passed before a sample finished: the checkpoint was kept as it was
    EXPECT_EQ(seconds(), first);
  }
  ASSERT_EQ(stop_at_a_time_limit("render --resume out.checkpoint.exr -q --checkpoint-interval 2m", dir,
                                 "out.checkpoint.exr", 1)
                .exit_code,
            3);
  EXPECT_EQ(interval(), "120s");
  // Without an interval the note is empty, and a resume has none.
  const fs::path other = scratch_dir();  // a new scratch folder: the scene copy goes there too
  const std::string other_args =
      "render " + one_path_cornell(other) + " --resolution 32x16 --spp 100000 -o out.exr -q";
  ASSERT_EQ(stop_at_a_time_limit(other_args, other, "out.checkpoint.exr", 1).exit_code, 3);
  EXPECT_EQ(read_exr(other / "out.checkpoint.exr").string_attributes.at("ochre.checkpoint.interval"), "");
}

class BadResume : public ::testing::Test {
 protected:
  void SetUp() override {
    const CommandResult r =
        stop_at_a_time_limit("render '" + (copy / "cornell-box.json").string() +
                                 "' --resolution 32x16 --spp 100000 -o out.exr --png out.png",
                             dir, "out.checkpoint.exr", 1);
    ASSERT_EQ(r.exit_code, 3) << r.output;
    ASSERT_TRUE(fs::exists(dir / "out.checkpoint.exr"));
    before = snapshot(dir / "out.exr");
  }
  void expect_refused(const std::string& args, const std::string& message) {
    const CommandResult r = run_ochre("render " + args, dir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(contains(r.output, message)) << "expected: " << message << "\ngot: " << r.output;
    EXPECT_TRUE(snapshot(dir / "out.exr") == before);
    EXPECT_TRUE(temporaries_in(dir).empty());
  }
  fs::path dir = scratch_dir();
  fs::path copy = [this] {
    fs::copy(source_dir() / "scenes/cornell-box", dir / "scene", fs::copy_options::recursive);
    return dir / "scene";
  }();
  FileSnapshot before;
};

TEST_F(BadResume, AMissingCheckpoint) {
  expect_refused("--resume nothere.exr", "nothere.exr: no such file");
}

TEST_F(BadResume, APartIsNotACheckpoint) {
  ASSERT_EQ(run_ochre("render '" + (copy / "cornell-box.json").string() +
                          "' --resolution 32x16 --spp 2 --part 0/2 -o part.exr -q",
                      dir)
                .exit_code,
            0);
  expect_refused("--resume part.exr", "part.exr: ochre.checkpoint.target: missing: not a checkpoint");
}

TEST_F(BadResume, SettingsThatChangeTheImage) {
  expect_refused("--resume out.checkpoint.exr --spp 5",
                 "--spp: a resumed render keeps the settings of its checkpoint");
  expect_refused("--resume out.checkpoint.exr --aovs", "--aovs: a resumed render keeps the settings");
  expect_refused("--resume out.checkpoint.exr --part 0/2", "--part: a resumed render keeps the settings");
}

TEST_F(BadResume, AReferencedFileChangedSinceTheCheckpoint) {
  std::ofstream(copy / "spectra/red.csv", std::ios::app) << "701,0.6\n";
  expect_refused("--resume out.checkpoint.exr", "out.checkpoint.exr: ochre.sceneHash: '");
  expect_refused("--resume out.checkpoint.exr",
                 "the scene or a file it references changed since the checkpoint");
}

// The checkpoint's header is read strictly: a value ochre render would not write is refused, naming the
// checkpoint and the field.
TEST_F(BadResume, HeaderValuesAreCheckedNotPartlyParsed) {
  const fs::path checkpoint = dir / "out.checkpoint.exr";
  ASSERT_TRUE(copy_with_string_attribute(checkpoint, dir / "exposure.exr", "ochre.display.exposure", "x"));
  expect_refused("--resume exposure.exr",
                 "exposure.exr: ochre.display.exposure: expected a number in [-64, 64], got 'x'");
  ASSERT_TRUE(copy_with_string_attribute(checkpoint, dir / "sampler.exr", "ochre.sampler", "bogus"));
  expect_refused("--resume sampler.exr",
                 "sampler.exr: ochre.sampler: unknown value 'bogus' (known: independent, sobol)");
  ASSERT_TRUE(copy_with_string_attribute(checkpoint, dir / "mode.exr", "ochre.polarization", "oXX"));
  expect_refused("--resume mode.exr",
                 "mode.exr: ochre.polarization: unknown value 'oXX' (known: auto, off, intensity, stokes)");
}

TEST_F(BadResume, ADamagedCheckpoint) {
  std::ifstream in(dir / "out.checkpoint.exr", std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  std::ofstream(dir / "cut.exr", std::ios::binary) << bytes.substr(0, bytes.size() * 2 / 3);
  // Where the cut falls depends on the compressed size of the sums: in the pixel data, or (for a small
  // file) already in the header and offset table, which the EXR reader reports itself.
  expect_refused("--resume cut.exr", "cut.exr: ");
  const CommandResult r = run_ochre("render --resume cut.exr", dir);
  EXPECT_TRUE(contains(r.output, "cut.exr: cannot read the sums") ||
              contains(r.output, "cut.exr: not a readable EXR file"))
      << r.output;
}

TEST(CheckpointOptions, MalformedDurationsAndAMissingSceneAreRefused) {
  const fs::path dir = scratch_dir();
  for (const std::string& args :
       {std::string("--time-limit 0"), std::string("--time-limit 5x"),
        std::string("--checkpoint-interval -3"), std::string("--checkpoint-interval 1h30")}) {
    const CommandResult r = run_ochre("render " + scene("cornell-box.json") + " -o out.exr " + args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "expected a duration such as 90, 90s, 10m, 1h30m")) << r.output;
  }
  const CommandResult r = run_ochre("render -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.output, "render: give a scene file (or --resume CHECKPOINT)")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
}

}  // namespace
}  // namespace ochre::test::checkpoint_test
