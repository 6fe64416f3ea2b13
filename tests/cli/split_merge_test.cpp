// Split renders (ochre render --sample-range / --part / --region) merged with ochre merge give the image of
// one render bit for bit, for the beauty, AOV, Stokes and spectral layers; bad parts are refused with the
// file and the field named, exit code 2 and no output written (docs/distributed.md).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "cli/file_test_support.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::split_merge_test {
namespace {

namespace fs = std::filesystem;

const std::string kCornell = "scenes/cornell-box/cornell-box.json";
const std::string kPolarized = "scenes/cornell-box/cornell-box-polarized.json";

std::string scene_path(const std::string& scene) {
  return fmt::format("'{}'", (source_dir() / scene).string());
}

// Renders `scene` with `args` in dir; expects success.
void render(const fs::path& dir, const std::string& scene, const std::string& args) {
  const CommandResult r = run_ochre("render " + scene_path(scene) + " " + args, dir);
  ASSERT_EQ(r.exit_code, 0) << args << "\n" << r.output;
}

CommandResult merge(const fs::path& dir, const std::string& args) {
  return run_ochre("merge " + args, dir);
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

const std::string kSmall = "--resolution 40x28 --spp 12 -q";

// Merges `parts` in dir into merged.exr and expects the bits of single.exr.
void expect_merge_gives_the_single_render(const fs::path& dir, const std::string& parts) {
  const CommandResult r = merge(dir, parts + " -o merged.exr");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(same_exr_pixels(dir / "single.exr", dir / "merged.exr"));
}

TEST(SplitMerge, SampleRangesMergeToTheSingleRenderWithAovsAndSpectralLayers) {
  const fs::path dir = scratch_dir();
  const std::string layers = kSmall + " --aovs --spectral-bins 5";
  render(dir, kCornell, layers + " -o single.exr --png single.png");
  render(dir, kCornell, layers + " --sample-range 0:5 -o a.exr");
  render(dir, kCornell, layers + " --sample-range 5:7 -o b.exr --threads 1");
  render(dir, kCornell, layers + " --sample-range 7:12 -o c.exr");
  const CommandResult r = merge(dir, "c.exr a.exr b.exr -o merged.exr --png merged.png");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(same_exr_pixels(dir / "single.exr", dir / "merged.exr"));
  EXPECT_EQ(read_bytes(dir / "single.png"), read_bytes(dir / "merged.png"));
  EXPECT_TRUE(temporaries_in(dir).empty());
}

TEST(SplitMerge, PartsMergeToTheSingleRenderWithStokesAndSpectralStokesLayers) {
  const fs::path dir = scratch_dir();
  const std::string layers = kSmall + " --stokes --spectral-bins 3";
  render(dir, kPolarized, layers + " -o single.exr --png single.png");  // not the scene's PNG path
  for (int i = 0; i < 3; ++i)
    render(dir, kPolarized, layers + " --part " + std::to_string(i) + "/3 -o p" + std::to_string(i) + ".exr");
  expect_merge_gives_the_single_render(dir, "p0.exr p1.exr p2.exr");
}

TEST(SplitMerge, RegionsMergeByPlacementAlsoCombinedWithSampleRanges) {
  const fs::path dir = scratch_dir();
  render(dir, kCornell, kSmall + " --aovs -o single.exr --png single.png");
  render(dir, kCornell, kSmall + " --aovs --region 0,0,17,11 -o r0.exr");
  render(dir, kCornell, kSmall + " --aovs --region 17,0,40,11 -o r1.exr");
  render(dir, kCornell, kSmall + " --aovs --region 0,11,40,28 --sample-range 0:3 -o r2.exr");
  render(dir, kCornell, kSmall + " --aovs --region 0,11,40,28 --sample-range 3:12 -o r3.exr");
  expect_merge_gives_the_single_render(dir, "r3.exr r1.exr r0.exr r2.exr");
}

TEST(SplitMerge, GridTilesTimesSampleRangesMergeToTheSingleRender) {
  const fs::path dir = scratch_dir();
  render(dir, kCornell, kSmall + " -o single.exr --png single.png");
  std::string parts;
  for (int t = 0; t < 6; ++t)
    for (int p = 0; p < 2; ++p) {
      const std::string name = fmt::format("t{}p{}.exr", t, p);
      render(dir, kCornell, fmt::format("{} --tile {}/3x2 --part {}/2 -o {}", kSmall, t, p, name));
      parts += " " + name;
    }
  expect_merge_gives_the_single_render(dir, parts);
}

// A camera sensor's film holds the sensor's R, G, B: the merge turns them into the output the render would
// write (white-balance matrix or camera RGB) and applies the display white balance, from the parts alone.
TEST(SplitMerge, CameraSensorRendersMergeToTheSingleRender) {
  for (const char* output : {"white_balanced", "camera_rgb"}) {
    const fs::path dir = scratch_dir();
    write_text(dir / "sensor.json", fmt::format(R"({{
      "camera": {{"eye": [0, 0, 3], "target": [0, 0, 0],
                  "sensor": {{"name": "nokia_n900", "output": "{}", "white_balance": {{"blackbody": 3000}}}}}},
      "film": {{"resolution": [24, 16]}},
      "integrator": {{"spp": 8}},
      "output": {{"white_balance": {{"blackbody": 3000}}}},
      "materials": {{"red": {{"type": "lambert", "color": [0.6, 0.2, 0.1]}}}},
      "lights": [{{"type": "point", "position": [0, 1, 2], "intensity": {{"blackbody": 3000, "scale": 5}}}}],
      "shapes": [{{"type": "sphere", "radius": 0.8, "material": "red"}}]}})",
                                                output));
    for (const char* args :
         {"-o single.exr --png single.png", "--sample-range 0:3 -o a.exr", "--sample-range 3:8 -o b.exr"}) {
      const CommandResult r = run_ochre(std::string("render sensor.json -q ") + args, dir);
      ASSERT_EQ(r.exit_code, 0) << output << " " << args << "\n" << r.output;
    }
    const CommandResult r = merge(dir, "b.exr a.exr -o merged.exr --png merged.png");
    ASSERT_EQ(r.exit_code, 0) << output << "\n" << r.output;
    EXPECT_TRUE(same_exr_pixels(dir / "single.exr", dir / "merged.exr")) << output;
    EXPECT_EQ(read_bytes(dir / "single.png"), read_bytes(dir / "merged.png")) << output;
    EXPECT_EQ(read_exr(dir / "single.exr").string_attributes.at("ochre.sensorOutput"),
              read_exr(dir / "merged.exr").string_attributes.at("ochre.sensorOutput"));
  }
}

TEST(SplitMerge, MergedSumsMergeAgainWithFurtherParts) {
  const fs::path dir = scratch_dir();
  render(dir, kCornell, kSmall + " -o single.exr --png single.png");
  for (int i = 0; i < 4; ++i)
    render(dir, kCornell, kSmall + " --part " + std::to_string(i) + "/4 -o p" + std::to_string(i) + ".exr");
  ASSERT_EQ(merge(dir, "p0.exr p2.exr --sums s02.exr").exit_code, 0);
  ASSERT_EQ(merge(dir, "s02.exr p3.exr --sums s023.exr").exit_code, 0);
  expect_merge_gives_the_single_render(dir, "s023.exr p1.exr");
  const CommandResult check = merge(dir, "--check s02.exr p3.exr");
  EXPECT_EQ(check.exit_code, 4);  // a check that did not pass (docs/cli.md, "Exit codes")
  EXPECT_TRUE(contains(check.output, "missing: samples 3:6 of every pixel")) << check.output;
}

// A merge of the first half of the samples, asked for with --partial, is the image of a render with half
// the samples; without --partial the missing samples are an error and nothing is written.
TEST(SplitMerge, PartialMergeIsTheLowerSampleImageAndNeedsTheFlag) {
  const fs::path dir = scratch_dir();
  render(dir, kCornell, "--resolution 40x28 --spp 6 -q -o half.exr --png half.png");
  render(dir, kCornell, kSmall + " --sample-range 0:4 -o a.exr");
  render(dir, kCornell, kSmall + " --sample-range 4:6 -o b.exr");
  write_old_file(dir / "merged.exr", "previous");
  const FileSnapshot before = snapshot(dir / "merged.exr");
  const CommandResult refused = merge(dir, "a.exr b.exr -o merged.exr");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_TRUE(contains(refused.output, "missing: samples 6:12 of every pixel")) << refused.output;
  EXPECT_TRUE(snapshot(dir / "merged.exr") == before);
  const CommandResult r = merge(dir, "a.exr b.exr --partial -o merged.exr");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(same_exr_pixels(dir / "half.exr", dir / "merged.exr"));
}

// Every way a set of parts can be wrong: exit 2, a message naming the file and the field, no output.
class BadParts : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int i = 0; i < 2; ++i)
      render(dir, kCornell, kSmall + " --part " + std::to_string(i) + "/2 -o p" + std::to_string(i) + ".exr");
    write_old_file(dir / "out.exr", "previous");
    before = snapshot(dir / "out.exr");
  }
  void expect_refused(const std::string& parts, const std::string& message) {
    const CommandResult r = merge(dir, parts + " -o out.exr");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(contains(r.output, message)) << "expected: " << message << "\ngot: " << r.output;
    EXPECT_TRUE(snapshot(dir / "out.exr") == before);
    EXPECT_TRUE(temporaries_in(dir).empty());
  }
  // A copy of p1.exr with `from` replaced by `to` (same length) in its bytes.
  void edit_copy(const std::string& name, const std::string& from, const std::string& to) {
    ASSERT_EQ(from.size(), to.size());
    std::string bytes = read_bytes(dir / "p1.exr");
    const size_t at = bytes.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    bytes.replace(at, from.size(), to);
    std::ofstream(dir / name, std::ios::binary) << bytes;
  }
  // A copy of p1.exr whose string attribute `name` holds `value` (of the old value's length).
  void edit_attribute(const std::string& copy, const std::string& name, const std::string& value) {
    ASSERT_TRUE(copy_with_string_attribute(dir / "p1.exr", dir / copy, name, value));
  }
  fs::path dir = scratch_dir();
  FileSnapshot before;
};

// The header fields the merge applies are read strictly: a value ochre render would not write is refused,
// naming the part file and the field (never partly parsed: "3abc" is not 3).
TEST_F(BadParts, HeaderValuesAreCheckedNotPartlyParsed) {
  render(dir, kCornell, kSmall + " --part 1/2 --exposure 12.5 -o p1.exr");
  edit_attribute("exposure.exr", "ochre.display.exposure", "3abc");
  expect_refused("--partial exposure.exr",
                 "exposure.exr: ochre.display.exposure: expected a number in [-64, 64], got '3abc'");
  edit_attribute("huge.exr", "ochre.display.exposure", "1e99");
  expect_refused("--partial huge.exr",
                 "huge.exr: ochre.display.exposure: expected a number in [-64, 64], got '1e99'");
  edit_attribute("sampler.exr", "ochre.sampler", "bogus");
  expect_refused("--partial sampler.exr",
                 "sampler.exr: ochre.sampler: unknown value 'bogus' (known: independent, sobol)");
  edit_attribute("space.exr", "ochre.colorspace", "rec710");
  expect_refused("--partial space.exr",
                 "space.exr: ochre.colorspace: unknown value 'rec710' (known: rec709, acescg)");
  edit_attribute("seed.exr", "ochre.seed", "x");
  expect_refused("--partial seed.exr", "seed.exr: ochre.seed: expected an integer in [0, 2^64), got 'x'");
}

TEST_F(BadParts, OverlappingParts) {
  render(dir, kCornell, kSmall + " --sample-range 4:8 -o overlap.exr");
  expect_refused("p0.exr p1.exr overlap.exr",
                 "overlap: p0.exr and overlap.exr both hold samples 4:6 of region 0,0,40,28");
}

TEST_F(BadParts, PartsOfADifferentSeed) {
  render(dir, kCornell, kSmall + " --part 1/2 --seed 3 -o seed.exr");
  expect_refused("p0.exr seed.exr", "seed.exr: ochre.seed: '3' differs from '0' in p0.exr");
}

TEST_F(BadParts, PartsWithOtherLayers) {
  render(dir, kCornell, kSmall + " --part 1/2 --aovs -o aovs.exr");
  expect_refused("p0.exr aovs.exr", "aovs.exr: ochre.aovs: '1' differs from '0' in p0.exr");
}

// The content hash covers the scene file and the files it references (here a spectrum CSV).
TEST_F(BadParts, PartsOfAChangedSceneOrReferencedFile) {
  const fs::path copy = dir / "copy";
  fs::copy(source_dir() / "scenes/cornell-box", copy, fs::copy_options::recursive);
  const auto render_copy = [&](const std::string& out) {
    const CommandResult r = run_ochre(
        "render '" + (copy / "cornell-box.json").string() + "' " + kSmall + " --part 1/2 -o " + out, dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
  };
  render_copy("same.exr");  // an unchanged copy elsewhere merges
  ASSERT_EQ(merge(dir, "p0.exr same.exr -o copy.exr").exit_code, 0);
  std::string csv = read_bytes(copy / "spectra/red.csv");
  csv.replace(csv.find("400,0.04"), 8, "400,0.05");
  std::ofstream(copy / "spectra/red.csv") << csv;
  render_copy("csv.exr");
  expect_refused("p0.exr csv.exr", "csv.exr: ochre.sceneHash:");
  expect_refused("p0.exr csv.exr", "the scene or a file it references differs");
}

TEST_F(BadParts, ATruncatedPart) {
  const std::string bytes = read_bytes(dir / "p1.exr");
  std::ofstream(dir / "cut.exr", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  expect_refused("p0.exr cut.exr", "cut.exr: cannot read the sums");
}

TEST_F(BadParts, APartWhoseSumsDoNotMatchItsChecksum) {
  const std::string bytes = read_bytes(dir / "p1.exr");
  const size_t at = bytes.find("ochre.sumsChecksum");
  ASSERT_NE(at, std::string::npos);
  // name, NUL, type "string", NUL, 4-byte size, then the 16 hexadecimal digits.
  const size_t digit = at + std::string("ochre.sumsChecksum").size() + 1 + 7 + 4;
  std::string edited = bytes;
  edited[digit] = edited[digit] == '0' ? '1' : '0';
  std::ofstream(dir / "sum.exr", std::ios::binary) << edited;
  expect_refused("p0.exr sum.exr", "sum.exr: ochre.sumsChecksum: does not match the sums");
}

TEST_F(BadParts, APartWhoseCoverageDoesNotMatchItsSampleCounts) {
  edit_copy("cov.exr", "0,0,40,28:6:12", "0,0,40,28:7:12");
  expect_refused("--partial p0.exr cov.exr",
                 "cov.exr: sums.count: pixel (0, 0) holds 6 samples, but ochre.coverage says 5");
}

TEST_F(BadParts, AMalformedField) {
  edit_copy("field.exr", "0,0,40,28:6:12", "0,0,40,28:9:02");
  expect_refused("p0.exr field.exr", "field.exr: ochre.coverage: expected x0,y0,x1,y1:A:B");
}

TEST_F(BadParts, AnEXRThatIsNotAPart) {
  render(dir, kCornell, kSmall + " -o image.exr --png image.png");
  expect_refused("p0.exr image.exr", "image.exr: ochre.partialSums: missing: not a partial-sum file");
}

TEST_F(BadParts, AMissingPart) {
  expect_refused("p0.exr nothere.exr", "nothere.exr: no such file");
}

TEST_F(BadParts, AMissingPartIsNamedAsMissingSamples) {
  expect_refused("p0.exr", "missing: samples 6:12 of every pixel");
}

TEST(SplitOptions, MalformedOrOutOfRangeValuesAreRefused) {
  const fs::path dir = scratch_dir();
  write_old_file(dir / "out.exr", "previous");
  const FileSnapshot before = snapshot(dir / "out.exr");
  struct Case {
    std::string args, message;
  };
  for (const Case& c : {
           Case{"--sample-range 5:3",
                "--sample-range: expected A:B with integers 0 <= A < B < 2^32, got '5:3'"},
           Case{"--sample-range 4:4", "got '4:4'"},
           Case{"--sample-range -1:4", "got '-1:4'"},
           Case{"--sample-range 1:2:3", "got '1:2:3'"},
           Case{"--sample-range 0:x", "got '0:x'"},
           Case{"--sample-range 0:13", "--sample-range 0:13: beyond the 12 samples per pixel"},
           Case{"--part 2/2", "--part: expected I/N with integers 0 <= I < N, got '2/2'"},
           Case{"--part 0/13", "--part 0/13: more parts than the 12 samples per pixel"},
           Case{"--region 0,0,40", "--region: expected x0,y0,x1,y1"},
           Case{"--region 5,0,5,10", "got '5,0,5,10'"},
           Case{"--region 0,0,41,28", "--region 0,0,41,28: outside the 40x28 image"},
           Case{"--tile 6/3x2",
                "--tile: expected I/CxR with integers C, R >= 1 and 0 <= I < C R, got '6/3x2'"},
           Case{"--tile 0/41x1", "--tile 0/41x1: more columns or rows than the 40x28 image has pixels"},
           Case{"--tile 0/2x2 --region 0,0,2,2", "--region excludes --tile"},
       }) {
    const CommandResult r =
        run_ochre("render " + scene_path(kCornell) + " " + kSmall + " -o out.exr " + c.args, dir);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, c.message)) << c.args << "\n" << r.output;
    EXPECT_TRUE(snapshot(dir / "out.exr") == before) << c.args;
  }
  const CommandResult no_output =
      run_ochre("render " + scene_path(kCornell) + " " + kSmall + " --part 0/2", dir);
  EXPECT_EQ(no_output.exit_code, 2);
  EXPECT_TRUE(contains(no_output.output, "--tile write partial sums: give -o PART.exr")) << no_output.output;
}

// integrator.branches auto: the pilot's choice depends on the scene and the settings only, so every part
// renders the same camera samples (sample ranges count them: 64 paths as 32 x 2 branches on this box) and
// the parts merge to the single render's bits.
TEST(SplitMerge, AutoBranchedPartsMergeToTheSingleRender) {
  const fs::path dir = scratch_dir();
  const std::string args = "--resolution 128x128 --spp 64";
  const CommandResult single =
      run_ochre("render " + scene_path(kCornell) + " " + args + " -o single.exr", dir);
  ASSERT_EQ(single.exit_code, 0) << single.output;
  EXPECT_TRUE(
      contains(single.output,
               "32 spp x 2 branches (64 paths per pixel, branches auto), max depth 8, roulette from depth"))
      << single.output;
  EXPECT_TRUE(contains(single.output, "ochre: paths: 2 branches, roulette from depth")) << single.output;
  render(dir, kCornell, args + " -q --part 0/2 -o p0.exr");
  render(dir, kCornell, args + " -q --sample-range 16:24 -o p1.exr --threads 1");
  render(dir, kCornell, args + " -q --sample-range 24:32 -o p2.exr");
  expect_merge_gives_the_single_render(dir, "p0.exr p1.exr p2.exr");
  // Ranges beyond the camera samples are refused, naming the branch count.
  const CommandResult beyond =
      run_ochre("render " + scene_path(kCornell) + " " + args + " --sample-range 30:40 -o p.exr", dir);
  EXPECT_EQ(beyond.exit_code, 2);
  EXPECT_TRUE(contains(beyond.output, "beyond the 32 camera samples per pixel (64 paths as 32 x 2 branches"))
      << beyond.output;
}

}  // namespace
}  // namespace ochre::test::split_merge_test
