// One exit-code rule for every program (docs/cli.md, "Exit codes"; tools/cli/program.h): -h/--help and
// --version exit 0 (--version prints "PROGRAM VERSION"); an unknown option, a missing input file and a NaN or
// negative number where a count or a finite value is expected exit 2 with "PROGRAM: error: ..." naming the
// option or the file, writing nothing; a check the user asked for that does not pass exits 4 (ochre-diff's
// thresholds, ochre-regress's scenes, ochre-brdf chi2, `ochre merge --check`). Exit 3 (`ochre render
// --time-limit`) is tested in checkpoint_test.cpp, the end by a signal in signals_test.cpp.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "cli/regress_suite.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::exit_codes_test {
namespace {

namespace fs = std::filesystem;

// A program: an executable and, for those that have them, one of its subcommands, with the options it
// requires (so that the one under test is the only thing wrong with a command line).
struct Program {
  std::string tool, command, required;
  std::string line(const std::string& args) const { return command.empty() ? args : command + " " + args; }
  std::string name() const { return command.empty() ? tool : tool + " " + command; }
};

const std::vector<Program>& programs() {
  static const std::vector<Program> list = {
      {"ochre", "render", "scene.json"},
      {"ochre", "merge", "part.exr"},
      {"ochre", "export-mesh", "scene.json -o out.ply"},
      {"ochre-diff", "", "a.exr b.exr"},
      {"ochre-regress", "", "suite"},
      {"ochre-converge", "", "scene.json --reference auto --spp 1"},
      {"ochre-bench", "", ""},
      {"ochre-brdf", "eval", "--material mat.json --input pairs.csv --output out.csv"},
      {"ochre-brdf", "albedo", "--material mat.json"},
      {"ochre-brdf", "plot", "--material mat.json --output out.png"},
      {"ochre-brdf", "chi2", "--material mat.json"},
      {"ochre-vgroove", "bihemispherical", "--material Au --alpha 90"},
      {"ochre-vgroove", "directional", "--material Au --alpha 90 --theta 0 --phi 0"},
      {"ochre-vgroove", "tables", ""},
      {"ochre-vgroove", "maps", "--material Au --alpha 90 -o out.png"},
      {"ochre-vgroove", "profile", "--material Au --alpha 90 -o out.csv"},
      {"ochre-vgroove", "compare", "--material Au"},
      {"ochre-fit", "powder", "--synthesize out.csv"},
      {"ochre-halfspace", "", ""},
  };
  return list;
}

std::vector<std::string> tools() {
  std::vector<std::string> names;
  for (const Program& p : programs())
    if (names.empty() || names.back() != p.tool) names.push_back(p.tool);
  return names;
}

// project(ochre VERSION x.y.z) of CMakeLists.txt, the one source of the version.
std::string project_version() {
  std::ifstream in(source_dir() / "CMakeLists.txt");
  std::stringstream text;
  text << in.rdbuf();
  std::smatch m;
  const std::string cmake = text.str();
  if (!std::regex_search(cmake, m, std::regex(R"(project\(ochre VERSION ([0-9.]+))"))) return "";
  return m[1];
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The names of the files in `dir`.
std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

// The inputs the cases below share, in a scratch directory: a small scene, a material, and nothing else.
fs::path fixture_dir() {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", scene_with("/integrator/spp", "2"));
  write_text(dir / "mat.json", R"({"type": "lambert", "color": 0.5})");
  return dir;
}

// Runs `tool args` in `dir` and expects bad input: exit 2, "TOOL: error:" and every one of `named` in the
// message, and no file added to the directory.
void expect_bad_input(const std::string& tool, const std::string& args, const fs::path& dir,
                      const std::vector<std::string>& named) {
  const std::set<std::string> before = files_in(dir);
  const CommandResult r = run_tool(tool, args, dir);
  const std::string what = tool + " " + args;
  EXPECT_EQ(r.exit_code, 2) << what << "\n" << r.output;
  EXPECT_TRUE(contains(r.output, tool + ": error: ")) << what << ": the message names the program\n"
                                                      << r.output;
  for (const std::string& name : named)
    EXPECT_TRUE(contains(r.output, name)) << what << ": the message names " << name << "\n" << r.output;
  EXPECT_EQ(files_in(dir), before) << what << ": nothing is written on exit 2";
}

TEST(ExitCodes, HelpExitsZero) {
  for (const std::string& tool : tools()) {
    const CommandResult r = run_tool(tool, "--help", {}, true);
    EXPECT_EQ(r.exit_code, 0) << tool << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "Usage:")) << tool << "\n" << r.output;
    const CommandResult h = run_tool(tool, "-h", {}, true);
    EXPECT_EQ(h.exit_code, 0) << tool << " -h\n" << h.output;
  }
  for (const Program& p : programs()) {
    if (p.command.empty()) continue;
    const CommandResult r = run_tool(p.tool, p.line("--help"), {}, true);
    EXPECT_EQ(r.exit_code, 0) << p.name() << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "Usage:")) << p.name() << "\n" << r.output;
  }
}

TEST(ExitCodes, VersionExitsZeroAndPrintsTheProgramAndVersion) {
  const std::string version = project_version();
  ASSERT_FALSE(version.empty());
  for (const std::string& tool : tools()) {
    const CommandResult r = run_tool(tool, "--version", {}, true);
    EXPECT_EQ(r.exit_code, 0) << tool << "\n" << r.output;
    EXPECT_EQ(r.output, tool + " " + version + "\n") << tool;
  }
}

TEST(ExitCodesBadInput, UnknownOption) {
  const fs::path dir = scratch_dir();
  for (const Program& p : programs())
    expect_bad_input(p.tool, p.line(p.required + " --no-such-option 1"), dir, {"--no-such-option"});
  // A missing subcommand or an unknown one is a usage error too.
  for (const std::string tool : {"ochre", "ochre-brdf", "ochre-vgroove", "ochre-fit"}) {
    expect_bad_input(tool, "", dir, {"subcommand"});
    expect_bad_input(tool, "frobnicate", dir, {});
  }
}

TEST(ExitCodesBadInput, MissingInputFile) {
  const fs::path dir = fixture_dir();
  struct Case {
    std::string tool, args, named;
  };
  const std::vector<Case> cases = {
      {"ochre", "render missing.json -o out.exr --png out.png", "missing.json"},
      {"ochre", "merge missing.exr -o out.exr", "missing.exr"},
      {"ochre", "merge missing.exr --check", "missing.exr"},
      {"ochre", "export-mesh missing.json -o out.ply", "missing.json"},
      {"ochre-diff", "missing.exr scene.json --heatmap heat.png", "missing.exr"},
      {"ochre-regress", "missing-suite --junit out.xml --output-dir out", "missing-suite"},
      {"ochre-converge", "missing.json --reference auto --spp 1 --csv out.csv", "missing.json"},
      {"ochre-converge", "scene.json --reference missing.exr --spp 1 --csv out.csv", "missing.exr"},
      {"ochre-bench", "missing.json --seconds 0.05", "missing.json"},
      {"ochre-brdf", "eval --material missing.json --input pairs.csv --output out.csv", "missing.json"},
      {"ochre-brdf", "eval --material mat.json --input missing.csv --output out.csv", "missing.csv"},
      {"ochre-brdf", "albedo --material missing.json --output out.csv", "missing.json"},
      {"ochre-brdf", "plot --material missing.json --output out.png", "missing.json"},
      {"ochre-brdf", "chi2 --material missing.json --output out.csv", "missing.json"},
      {"ochre-fit", "powder --data missing.csv -o out.json", "missing.csv"},
      {"ochre-fit", "powder --synthesize out.csv --geometry missing.csv", "missing.csv"},
      // ochre-vgroove and ochre-halfspace read no file: an output in a missing folder instead.
      {"ochre-vgroove", "maps --material Au --alpha 90 --size 8 -o missing-dir/out.png", "missing-dir"},
      {"ochre-halfspace", "--c 0.5 --mu 1 --phi 0 --paths 10 --output missing-dir/out.csv", "missing-dir"},
  };
  for (const Case& c : cases) expect_bad_input(c.tool, c.args, dir, {c.named});
}

TEST(ExitCodesBadInput, NanOrNegativeNumber) {
  const fs::path dir = fixture_dir();
  struct Case {
    std::string tool, args, option;
  };
  const std::vector<Case> cases = {
      {"ochre", "render scene.json -o out.exr --spp -1", "--spp"},
      {"ochre", "render scene.json -o out.exr --seed -1", "--seed"},
      {"ochre", "render scene.json -o out.exr --threads -1", "--threads"},
      {"ochre", "render scene.json -o out.exr --png out.png --exposure nan", "--exposure"},
      {"ochre", "render scene.json -o out.exr --spectral-bins -1", "--spectral-bins"},
      {"ochre", "render scene.json -o out.exr --frames -1", "--frames"},
      {"ochre", "render scene.json -o out.exr --frames 2 --first-frame -1", "--first-frame"},
      {"ochre", "render scene.json -o out.exr --frames 2 --fps nan", "--fps"},
      {"ochre", "merge part.exr -o out.exr --png out.png --exposure nan", "--exposure"},
      {"ochre-diff", "a.exr b.exr --max-rmse nan", "--max-rmse"},
      {"ochre-diff", "a.exr b.exr --max-relmse -1", "--max-relmse"},
      {"ochre-diff", "a.exr b.exr --max-error inf", "--max-error"},
      {"ochre-diff", "a.exr b.exr --max-de nan", "--max-de"},
      {"ochre-diff", "a.exr b.exr --heatmap heat.png --heatmap-scale nan", "--heatmap-scale"},
      {"ochre-regress", "suite --spp -1", "--spp"},
      {"ochre-regress", "suite --update --reference-spp -1", "--reference-spp"},
      {"ochre-regress", "suite --threads -1", "--threads"},
      {"ochre-converge", "scene.json --reference auto --spp -1 --csv out.csv", "--spp"},
      {"ochre-converge", "scene.json --reference auto --spp 1 --threads -1 --csv out.csv", "--threads"},
      {"ochre-converge", "scene.json --reference auto --spp 1 --seed -1 --csv out.csv", "--seed"},
      {"ochre-converge", "scene.json --reference auto --spp 1 --width -4 --csv out.csv", "--width"},
      {"ochre-bench", "scene.json --seconds nan", "--seconds"},
      {"ochre-bench", "scene.json --seconds -1", "--seconds"},
      {"ochre-bench", "scene.json --spp -1", "--spp"},
      {"ochre-bench", "scene.json --seed -1", "--seed"},
      {"ochre-bench", "scene.json --repeat -1", "--repeat"},
      {"ochre-bench", "scene.json --threads -1", "--threads"},
      {"ochre-brdf", "albedo --material mat.json --samples -1 --output out.csv", "--samples"},
      {"ochre-brdf", "albedo --material mat.json --seed -1 --output out.csv", "--seed"},
      {"ochre-brdf", "albedo --material mat.json --lambda nan --output out.csv", "--lambda"},
      {"ochre-brdf", "albedo --material mat.json --angles nan --output out.csv", "--angles"},
      {"ochre-brdf", "plot --material mat.json --lambda nan --output out.png", "--lambda"},
      {"ochre-brdf", "chi2 --material mat.json --samples -1 --output out.csv", "--samples"},
      {"ochre-brdf", "chi2 --material mat.json --alpha nan --output out.csv", "--alpha"},
      {"ochre-brdf", "chi2 --material mat.json --seed -1 --output out.csv", "--seed"},
      {"ochre-vgroove", "bihemispherical --material Au --alpha nan", "--alpha"},
      {"ochre-vgroove", "bihemispherical --material Au --alpha 90 --quadrature -1", "--quadrature"},
      {"ochre-vgroove", "directional --material Au --alpha 90 --theta nan --phi 0", "--theta"},
      {"ochre-vgroove", "directional --material Au --alpha 90 --theta 10 --phi 0 --max-reflections -1",
       "--max-reflections"},
      {"ochre-vgroove", "tables --quadrature -1", "--quadrature"},
      {"ochre-vgroove", "maps --material Au --alpha 90 --size -1 -o out.png", "--size"},
      {"ochre-vgroove", "profile --material Au --alpha 90 --step nan -o out.csv", "--step"},
      {"ochre-vgroove", "compare --material Au --spp -1", "--spp"},
      {"ochre-vgroove", "compare --material Au --seed -1", "--seed"},
      {"ochre-vgroove", "compare --material Au --threads -1", "--threads"},
      {"ochre-fit", "powder --data data.csv --max-theta-i nan -o out.json", "--max-theta-i"},
      {"ochre-fit", "powder --synthesize out.csv --noise nan", "--noise"},
      {"ochre-fit", "powder --synthesize out.csv --noise -0.1", "--noise"},
      {"ochre-fit", "powder --synthesize out.csv --seed -1", "--seed"},
      {"ochre-fit", "powder --synthesize out.csv --lambda nan", "--lambda"},
      {"ochre-halfspace", "--paths -1 --output out.csv", "--paths"},
      {"ochre-halfspace", "--seed -1 --output out.csv", "--seed"},
      {"ochre-halfspace", "--max-collisions -1 --output out.csv", "--max-collisions"},
      {"ochre-halfspace", "--threads -1 --output out.csv", "--threads"},
      {"ochre-halfspace", "--c nan --output out.csv", "--c"},
      {"ochre-halfspace", "--mu -0.5 --output out.csv", "--mu"},
      {"ochre-halfspace", "--phi nan --output out.csv", "--phi"},
  };
  for (const Case& c : cases) expect_bad_input(c.tool, c.args, dir, {c.option});
}

TEST(ExitCodesFailedCheck, ExitsFour) {
  const fs::path dir = fixture_dir();
  // ochre-diff: a threshold exceeded.
  write_text(dir / "brighter.json", scene_with("/materials/grey/color", "0.8"));
  ASSERT_EQ(run_ochre("render scene.json -o a.exr -q", dir).exit_code, 0);
  ASSERT_EQ(run_ochre("render brighter.json -o b.exr -q", dir).exit_code, 0);
  CommandResult r = run_tool("ochre-diff", "a.exr b.exr --max-rmse 1e-4", dir);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_TRUE(contains(r.output, "threshold exceeded: rmse")) << r.output;
  EXPECT_EQ(run_tool("ochre-diff", "a.exr a.exr --max-rmse 0", dir).exit_code, 0);

  // ochre merge --check: samples missing.
  ASSERT_EQ(run_ochre("render scene.json --part 0/2 -o p0.exr -q", dir).exit_code, 0);
  ASSERT_EQ(run_ochre("render scene.json --part 1/2 -o p1.exr -q", dir).exit_code, 0);
  r = run_ochre("merge --check p0.exr", dir);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_TRUE(contains(r.output, "missing: samples 1:2")) << r.output;
  EXPECT_EQ(run_ochre("merge --check p0.exr p1.exr", dir).exit_code, 0);

  // ochre-brdf chi2: the sampler rejected. At an overall significance of 1 - 1e-9 a correct sampler fails
  // too (its p-value would have to exceed 1 - 1e-9); at the default 0.01 it passes.
  r = run_tool("ochre-brdf", "chi2 --material mat.json --incidence 30 --samples 20000 --alpha 0.999999999",
               dir);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_TRUE(contains(r.output, "FAIL")) << r.output;
  r = run_tool("ochre-brdf", "chi2 --material mat.json --incidence 30 --samples 20000", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;

  // ochre-regress: a scene failed.
  perturbed_suite(dir);
  r = run_regress("suite --output-dir regress-out", dir);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_TRUE(contains(r.output, "FAILED")) << r.output;
}

}  // namespace
}  // namespace ochre::test::exit_codes_test
