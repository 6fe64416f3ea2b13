// Outputs never destroy data: an output that is one of the inputs (under any spelling, hard links
// included), a symbolic link, a FIFO, a device or a directory, or two outputs on one file, are refused
// with exit code 2 before any work; with several outputs, either all are written or none is replaced.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli/cli_runner.h"
#include "cli/file_test_support.h"
#include "support/test_paths.h"

namespace ochre::test::output_files_test {
namespace {

namespace fs = std::filesystem;

constexpr int kTimeout = 20;

// A scene with a mesh, a spectrum CSV and a texture beside it, every file old.
struct SceneDir {
  fs::path dir = scratch_dir();
  SceneDir() {
    write_old_file(dir / "mesh.obj",
                   "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                   "f 1/1 2/2 3/3 4/4\n");
    write_old_file(dir / "white.csv", "wavelength,value\n360,0.5\n830,0.5\n");
    write_png(dir / "albedo.png", 4, 4);
    write_old_file(dir / "scene.json",
                   minimal_scene(R"("materials": {"grey": {"type": "lambert", "color": {"file": "white.csv"}},
                                   "tex": {"nodes": {"t": {"type": "texture", "file": "albedo.png"},
                                   "d": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "d"}})",
                                 R"("shapes": [{"type": "mesh", "file": "mesh.obj", "material": "grey"},
                                   {"type": "plane", "material": "tex"}])"));
  }
  // Runs `ochre render scene.json ARGS` and checks the refusal: exit 2, `why` in the message, every
  // input untouched, no temporary.
  void expect_refused(const std::string& args, const std::string& why) const {
    const std::vector<std::string> inputs = {"scene.json", "mesh.obj", "white.csv", "albedo.png"};
    std::vector<FileSnapshot> before;
    for (const std::string& name : inputs) before.push_back(snapshot(dir / name));
    const CommandResult r = run_tool("ochre", "render scene.json " + args, dir, false, kTimeout);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, why)) << args << ": message must say '" << why << "'\n" << r.output;
    for (size_t i = 0; i < inputs.size(); ++i)
      EXPECT_TRUE(snapshot(dir / inputs[i]) == before[i]) << inputs[i] << " was touched by: " << args;
    EXPECT_TRUE(temporaries_in(dir).empty()) << args;
  }
};

TEST(OutputFiles, OutputThatIsTheScene) {
  const SceneDir s;
  s.expect_refused("-o scene.json", "cannot write scene.json: it is the scene file");
  fs::create_directory(s.dir / "sub");
  s.expect_refused("-o sub/../scene.json", "cannot write sub/../scene.json: it is the scene file");
  s.expect_refused("-o ./scene.json", "it is the scene file");
  s.expect_refused("-o " + (s.dir / "scene.json").string(), "it is the scene file");
  fs::create_hard_link(s.dir / "scene.json", s.dir / "same-scene.json");
  s.expect_refused("-o same-scene.json", "cannot write same-scene.json: it is the scene file");
}

TEST(OutputFiles, OutputThatIsAFileTheSceneReads) {
  const SceneDir s;
  s.expect_refused("-o mesh.obj", "cannot write mesh.obj: it is the mesh file");
  s.expect_refused("-o white.csv", "cannot write white.csv: it is the CSV file");
  s.expect_refused("-o out.exr --png albedo.png", "cannot write albedo.png: it is the texture");
  s.expect_refused("-o out.exr --polarization-png sub/../albedo.png", "");  // the directory is missing
  fs::create_directory(s.dir / "sub");
  s.expect_refused("-o out.exr --polarization-png sub/../albedo.png", "it is the texture");
  fs::create_hard_link(s.dir / "mesh.obj", s.dir / "mesh-link.obj");
  s.expect_refused("-o mesh-link.obj", "cannot write mesh-link.obj: it is the mesh file");
  EXPECT_FALSE(fs::exists(s.dir / "out.exr"));
}

TEST(OutputFiles, SceneOutputFieldThatIsItsOwnMesh) {
  const SceneDir s;
  write_old_file(s.dir / "scene.json",
                 minimal_scene("", R"("shapes": [{"type": "mesh", "file": "mesh.obj", "material": "grey"}])",
                               "", R"("output": {"exr": "mesh.obj"})"));
  s.expect_refused("", "mesh.obj: it is the mesh file");
}

TEST(OutputFiles, OutputThatIsTheOcioConfig) {
  const SceneDir s;
  fs::copy_file(source_dir() / "renderer" / "ocio" / "config.ocio", s.dir / "config.ocio");
  const FileSnapshot config = snapshot(s.dir / "config.ocio");
  s.expect_refused("--png config.ocio --ocio-config config.ocio",
                   "cannot write config.ocio: it is the OCIO config");
  EXPECT_TRUE(snapshot(s.dir / "config.ocio") == config);
}

TEST(OutputFiles, OutputThatIsASymbolicLink) {
  const SceneDir s;
  write_old_file(s.dir / "target.exr", "keep me");
  fs::create_symlink("target.exr", s.dir / "link.exr");
  s.expect_refused("-o link.exr", "cannot write link.exr: it is a symbolic link to target.exr");
  EXPECT_TRUE(fs::is_symlink(s.dir / "link.exr"));
  EXPECT_EQ(snapshot(s.dir / "target.exr").bytes, "keep me");
}

TEST(OutputFiles, OutputThatIsAFifoADeviceOrADirectory) {
  const SceneDir s;
  make_fifo(s.dir / "pipe.exr");
  s.expect_refused("-o pipe.exr", "cannot write pipe.exr: it is a FIFO, not a regular file");
  EXPECT_EQ(fs::status(s.dir / "pipe.exr").type(), fs::file_type::fifo);
  s.expect_refused("-o /dev/null", "cannot write /dev/null: it is a character device, not a regular file");
  EXPECT_EQ(fs::status("/dev/null").type(), fs::file_type::character);
  fs::create_directory(s.dir / "dir.exr");
  s.expect_refused("-o dir.exr", "cannot write dir.exr: it is a directory");
}

TEST(OutputFiles, TwoOutputsOnOneFile) {
  const SceneDir s;
  s.expect_refused("-o out.exr --png out.exr", "cannot write out.exr: it is also given as output out.exr");
  s.expect_refused("-o out.exr --png a.png --polarization-png ./a.png",
                   "cannot write a.png: it is also given as output ./a.png");
  EXPECT_FALSE(fs::exists(s.dir / "out.exr"));
  EXPECT_FALSE(fs::exists(s.dir / "a.png"));
}

TEST(OutputFiles, OneUnwritableOutputLeavesTheOthersUntouched) {
  const SceneDir s;
  write_old_file(s.dir / "out.exr", "old exr");
  write_old_file(s.dir / "out.png", "old png");
  const FileSnapshot exr = snapshot(s.dir / "out.exr"), png = snapshot(s.dir / "out.png");
  s.expect_refused("-o out.exr --png out.png --polarization-png missing/p.png",
                   "cannot write missing/p.png: directory missing does not exist");
  write_old_file(s.dir / "file", "a file, not a directory");
  s.expect_refused("-o out.exr --png file/out.png", "cannot write file/out.png: file is not a directory");
  EXPECT_TRUE(snapshot(s.dir / "out.exr") == exr);
  EXPECT_TRUE(snapshot(s.dir / "out.png") == png);
}

TEST(OutputFiles, AllOutputsAreWrittenTogether) {
  const SceneDir s;
  write_old_file(s.dir / "out.exr", "old exr");
  write_old_file(s.dir / "out.png", "old png");
  const CommandResult r =
      run_tool("ochre", "render scene.json -o out.exr --png out.png --polarization-png pol.png", s.dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(snapshot(s.dir / "out.exr").bytes, "old exr");
  EXPECT_NE(snapshot(s.dir / "out.png").bytes, "old png");
  EXPECT_TRUE(fs::exists(s.dir / "pol.png"));
  EXPECT_TRUE(temporaries_in(s.dir).empty());
}

TEST(OutputFiles, HeatMapOfOchreDiffThatIsAnInput) {
  const SceneDir s;
  ASSERT_EQ(run_tool("ochre", "render scene.json -o a.exr", s.dir).exit_code, 0);
  ASSERT_EQ(run_tool("ochre", "render scene.json -o b.exr --seed 3", s.dir).exit_code, 0);
  const FileSnapshot a = snapshot(s.dir / "a.exr");
  CommandResult r = run_tool("ochre-diff", "a.exr b.exr --heatmap a.exr", s.dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "cannot write a.exr: it is the image file a.exr")) << r.output;
  EXPECT_TRUE(snapshot(s.dir / "a.exr") == a);
  fs::create_symlink("b.exr", s.dir / "heat.png");
  r = run_tool("ochre-diff", "a.exr b.exr --heatmap heat.png", s.dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "cannot write heat.png: it is a symbolic link")) << r.output;
  EXPECT_TRUE(temporaries_in(s.dir).empty());
}

TEST(OutputFiles, CsvOfOchreConvergeThatIsTheScene) {
  const SceneDir s;
  CommandResult r = run_tool("ochre-converge", "scene.json --reference auto --spp 1 --csv scene.json", s.dir,
                             false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "cannot write scene.json: it is the scene file")) << r.output;
  EXPECT_FALSE(contains(r.output, "reference: auto")) << "refused before any render\n" << r.output;
  r = run_tool("ochre-converge", "scene.json --reference auto --spp 1 --csv white.csv", s.dir, false,
               kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "cannot write white.csv: it is the CSV file")) << r.output;
  r = run_tool("ochre-converge", "scene.json --reference auto --spp 1 --csv a.csv --plot a.csv", s.dir, false,
               kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "it is also given as output a.csv")) << r.output;
  EXPECT_FALSE(fs::exists(s.dir / "a.csv"));
  // A plot into a missing directory is named as given, not as the CSV derived from it.
  r = run_tool("ochre-converge", "scene.json --reference auto --spp 1 --plot missing/p.png", s.dir, false,
               kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "cannot write missing/p.png")) << r.output;
  EXPECT_FALSE(contains(r.output, "reference: auto")) << "refused before any render\n" << r.output;
}

TEST(OutputFiles, OutputOfOchreBrdfThatIsAnInput) {
  const fs::path dir = scratch_dir();
  write_old_file(dir / "lambert.json", R"({"type": "lambert", "color": 0.5})");
  write_old_file(dir / "pairs.csv", "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,lambda_nm\n0,0,1,0,0,1,550\n");
  const FileSnapshot material = snapshot(dir / "lambert.json"), pairs = snapshot(dir / "pairs.csv");
  CommandResult r =
      run_tool("ochre-brdf", "eval --material lambert.json --input pairs.csv --output pairs.csv", dir, false,
               kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "cannot write pairs.csv: it is the CSV file")) << r.output;
  r = run_tool("ochre-brdf", "albedo --material lambert.json --samples 100 --output lambert.json", dir, false,
               kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "cannot write lambert.json: it is the material file")) << r.output;
  EXPECT_TRUE(snapshot(dir / "lambert.json") == material);
  EXPECT_TRUE(snapshot(dir / "pairs.csv") == pairs);
}

TEST(OutputFiles, JunitReportOfOchreRegressThatIsAScene) {
  const fs::path dir = scratch_dir();
  write_old_file(dir / "suite" / "plane.json", minimal_scene());
  const FileSnapshot scene = snapshot(dir / "suite" / "plane.json");
  const CommandResult r = run_tool("ochre-regress", "suite --junit suite/plane.json", dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "cannot write suite/plane.json: it is the scene file")) << r.output;
  EXPECT_TRUE(snapshot(dir / "suite" / "plane.json") == scene);
}

// ochre-vgroove reads no file: its outputs are checked for links, devices, FIFOs and each other.
TEST(OutputFiles, OutputsOfOchreVGroove) {
  const fs::path dir = scratch_dir();
  write_old_file(dir / "target.png", "keep me");
  fs::create_symlink("target.png", dir / "link.png");
  make_fifo(dir / "pipe.png");
  const FileSnapshot target = snapshot(dir / "target.png");
  const std::string maps = "maps --material glass --alpha 45 --size 8 ";
  const std::string profile = "profile --material Si --alpha 45 --step 10 ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {maps + "-o m.png --counts ./m.png", "cannot write ./m.png: it is also given as output m.png"},
      {maps + "-o link.png", "cannot write link.png: it is a symbolic link to target.png"},
      {maps + "-o m.png --counts pipe.png", "cannot write pipe.png: it is a FIFO, not a regular file"},
      {maps + "-o /dev/null", "cannot write /dev/null: it is a character device, not a regular file"},
      {profile + "-o p.csv --png p.csv", "cannot write p.csv: it is also given as output p.csv"},
      {profile + "-o link.png", "cannot write link.png: it is a symbolic link to target.png"},
  };
  for (const auto& [args, why] : cases) {
    const CommandResult r = run_tool("ochre-vgroove", args, dir, false, kTimeout);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, why)) << args << ": message must say '" << why << "'\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "m.png")) << args;
    EXPECT_FALSE(fs::exists(dir / "p.csv")) << args;
    EXPECT_TRUE(temporaries_in(dir).empty()) << args;
  }
  EXPECT_TRUE(fs::is_symlink(dir / "link.png"));
  EXPECT_TRUE(snapshot(dir / "target.png") == target);
  EXPECT_EQ(fs::status(dir / "pipe.png").type(), fs::file_type::fifo);
}

// A copy of ochre-vgroove in an installed tree whose plot script fails (the tools look in
// share/ochre/scripts first, tools/cli/tool_files.h): the plot fails after the other outputs were written.
fs::path vgroove_with_failing_plot(const fs::path& root) {
  fs::create_directories(root / "bin");
  fs::copy_file(bin_dir() / "ochre-vgroove", root / "bin" / "ochre-vgroove");
  fs::permissions(root / "bin" / "ochre-vgroove", fs::perms::owner_all);
  // The image library module, where an installed tree has it (renderer/image/image_library.h).
  fs::create_directories(root / "lib" / "ochre");
  fs::copy_file(bin_dir() / ".." / "lib" / "ochre" / "libochre_oiio.so",
                root / "lib" / "ochre" / "libochre_oiio.so");
  write_text(root / "share" / "ochre" / "scripts" / "plot_vgroove.py", "import sys\nsys.exit(1)\n");
  return root / "bin" / "ochre-vgroove";  // absolute: run_tool's bin_dir() / tool is then this path
}

TEST(OutputFiles, OchreVGrooveWritesItsOutputsAllOrNothing) {
  const fs::path dir = scratch_dir();
  write_old_file(dir / "m.png", "old map");
  write_old_file(dir / "c.png", "old counts");
  CommandResult r =
      run_tool("ochre-vgroove", "maps --material glass --alpha 45 --size 8 -o m.png --counts c.png", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(snapshot(dir / "m.png").bytes, "old map");
  EXPECT_NE(snapshot(dir / "c.png").bytes, "old counts");

  const fs::path tool = vgroove_with_failing_plot(dir / "tree");
  write_old_file(dir / "p.csv", "old profile");
  const FileSnapshot csv = snapshot(dir / "p.csv");
  r = run_tool(tool.string(), "profile --material Si --alpha 45 --step 10 -o p.csv --png p.png", dir);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(contains(r.output, "p.csv and p.png not written")) << r.output;
  EXPECT_TRUE(snapshot(dir / "p.csv") == csv) << "the CSV is replaced only with its plot";
  EXPECT_FALSE(fs::exists(dir / "p.png"));

  const FileSnapshot map = snapshot(dir / "m.png"), counts = snapshot(dir / "c.png");
  r = run_tool(tool.string(), "maps --material glass,Au --alpha 45 --size 8 -o m.png --counts c.png", dir);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(snapshot(dir / "m.png") == map);
  EXPECT_TRUE(snapshot(dir / "c.png") == counts);
  EXPECT_TRUE(temporaries_in(dir).empty()) << "no temporary and no panel directory is left";
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 4) << "m, c, p.csv, tree";
}

// An output path given as an empty string is refused by every program, never read as "not given" (which
// would write a default output over a file there).
TEST(OutputFiles, EmptyOutputPathsAreRefused) {
  const SceneDir s;
  write_old_file(s.dir / "default.exr", "previous");
  for (const std::string& args : {std::string("-o ''"), std::string("-o out.exr --png ''"),
                                  std::string("-o out.exr --polarization-png ''"),
                                  std::string("-o out.exr --checkpoint '' --time-limit 1m")})
    s.expect_refused(args, "expected a path, got an empty string");
  const CommandResult merge = run_tool("ochre", "merge a.exr -o ''", s.dir, false, kTimeout);
  EXPECT_EQ(merge.exit_code, 2) << merge.output;
  EXPECT_TRUE(contains(merge.output, "expected a path, got an empty string")) << merge.output;
  const CommandResult regress = run_tool("ochre-regress", ". --html ''", s.dir, false, kTimeout);
  EXPECT_EQ(regress.exit_code, 2) << regress.output;
  EXPECT_TRUE(contains(regress.output, "expected a path, got an empty string")) << regress.output;
  const CommandResult diff = run_tool("ochre-diff", "a.exr b.exr --heatmap ''", s.dir, false, kTimeout);
  EXPECT_EQ(diff.exit_code, 2) << diff.output;
  EXPECT_TRUE(contains(diff.output, "expected a path, got an empty string")) << diff.output;
}

// An output on the command line decides where every output goes: the scene's own output paths (here
// "output": {"exr": "scene_out.exr", "png": "scene_out.png"}) apply only when none is given.
TEST(OutputFiles, ACommandLineOutputReplacesTheScenesOutputs) {
  const fs::path dir = scratch_dir();
  write_old_file(dir / "scene.json",
                 minimal_scene("", "", "", R"("output": {"exr": "scene_out.exr", "png": "scene_out.png"})"));
  fs::create_directory(dir / "elsewhere");
  const CommandResult r =
      run_tool("ochre", "render scene.json -o elsewhere/out.exr -q", dir, false, kTimeout);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "elsewhere/out.exr"));
  EXPECT_FALSE(fs::exists(dir / "scene_out.exr"));
  EXPECT_FALSE(fs::exists(dir / "scene_out.png")) << "the scene's PNG must not be written beside it";
  EXPECT_FALSE(fs::exists(dir / "elsewhere/out.png"));
  const CommandResult png = run_tool("ochre", "render scene.json --png only.png -q", dir, false, kTimeout);
  ASSERT_EQ(png.exit_code, 0) << png.output;
  EXPECT_TRUE(fs::exists(dir / "only.png"));
  EXPECT_FALSE(fs::exists(dir / "scene_out.exr"));
  // No output on the command line: the scene's own.
  const CommandResult own = run_tool("ochre", "render scene.json -q", dir, false, kTimeout);
  ASSERT_EQ(own.exit_code, 0) << own.output;
  EXPECT_TRUE(fs::exists(dir / "scene_out.exr"));
  EXPECT_TRUE(fs::exists(dir / "scene_out.png"));
}

// A time limit so short that no sample finishes writes nothing: the existing outputs stay as they were
// (an image of no samples would be black).
TEST(OutputFiles, ATimeLimitBeforeAnySampleKeepsTheExistingOutputs) {
  const SceneDir s;
  write_old_file(s.dir / "out.exr", "previous exr");
  write_old_file(s.dir / "out.png", "previous png");
  const FileSnapshot exr = snapshot(s.dir / "out.exr"), png = snapshot(s.dir / "out.png");
  const CommandResult r = run_tool("ochre",
                                   "render scene.json -o out.exr --png out.png --resolution 2000x2000 "
                                   "--spp 1000 --time-limit 0.001",
                                   s.dir, false, kTimeout);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_TRUE(contains(r.output, "time limit reached before any sample finished; nothing written"))
      << r.output;
  EXPECT_TRUE(snapshot(s.dir / "out.exr") == exr);
  EXPECT_TRUE(snapshot(s.dir / "out.png") == png);
  EXPECT_FALSE(fs::exists(s.dir / "out.checkpoint.exr"));
  EXPECT_TRUE(temporaries_in(s.dir).empty());
}

}  // namespace
}  // namespace ochre::test::output_files_test
