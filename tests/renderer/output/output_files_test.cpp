// check_output_files (renderer/output/output_files.h): no output replaces an input, a link, a device, a FIFO
// or a directory, and no two outputs are one file, whatever the spelling of the paths.

#include "renderer/output/output_files.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <string>

#include "spectra/input_error.h"
#include "support/test_paths.h"

namespace ochre::output_files_test {
namespace {

namespace fs = std::filesystem;

std::string error_of(const std::vector<fs::path>& outputs, const InputFileLog& inputs) {
  try {
    check_output_files(outputs, inputs);
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

// A directory with scene.json and mesh.obj, both read (recorded) as inputs.
struct Inputs {
  fs::path dir = test::scratch_dir();
  InputFileLog log;
  Inputs() {
    std::ofstream(dir / "scene.json") << "{}";
    std::ofstream(dir / "mesh.obj") << "v 0 0 0\n";
    const InputFileLog::Recording recording(log);
    check_regular_input(dir / "scene.json", kSceneFileInput);
    check_regular_input(dir / "mesh.obj", kMeshFileInput);
  }
};

TEST(OutputFiles, NewFilesBesideTheInputsAreAccepted) {
  const Inputs in;
  EXPECT_EQ(error_of({in.dir / "out.exr", in.dir / "out.png"}, in.log), "");
}

TEST(OutputFiles, AnInputIsRefusedUnderAnySpelling) {
  const Inputs in;
  const std::string scene = (in.dir / "scene.json").string();
  EXPECT_EQ(error_of({in.dir / "scene.json"}, in.log),
            "cannot write " + scene + ": it is the scene file " + scene + ", an input of this command");
  fs::create_directory(in.dir / "sub");
  const fs::path dotted = in.dir / "sub" / ".." / "." / "mesh.obj";
  EXPECT_EQ(error_of({dotted}, in.log), "cannot write " + dotted.string() + ": it is the mesh file " +
                                            (in.dir / "mesh.obj").string() + ", an input of this command");
  fs::create_hard_link(in.dir / "mesh.obj", in.dir / "other-name.obj");
  EXPECT_NE(error_of({in.dir / "other-name.obj"}, in.log).find("it is the mesh file"), std::string::npos);
  // A directory symlink on the way is resolved too.
  fs::create_directory_symlink(in.dir, in.dir / "alias");
  EXPECT_NE(error_of({in.dir / "alias" / "scene.json"}, in.log).find("it is the scene file"),
            std::string::npos);
}

TEST(OutputFiles, RelativeAndAbsoluteSpellingsOfAnInputMatch) {
  const Inputs in;
  const fs::path relative = fs::relative(in.dir / "scene.json");
  EXPECT_NE(error_of({relative}, in.log).find("it is the scene file"), std::string::npos) << relative;
}

TEST(OutputFiles, TwoOutputsOnOneFileAreRefused) {
  const Inputs in;
  fs::create_directory(in.dir / "sub");
  EXPECT_EQ(error_of({in.dir / "a.png", in.dir / "b.exr", in.dir / "sub" / ".." / "a.png"}, in.log),
            "cannot write " + (in.dir / "sub" / ".." / "a.png").string() + ": it is also given as output " +
                (in.dir / "a.png").string() + "; two outputs cannot be one file");
}

TEST(OutputFiles, LinksDevicesFifosAndDirectoriesAreRefused) {
  const Inputs in;
  std::ofstream(in.dir / "target.exr") << "keep";
  fs::create_symlink("target.exr", in.dir / "link.exr");
  EXPECT_EQ(error_of({in.dir / "link.exr"}, in.log),
            "cannot write " + (in.dir / "link.exr").string() +
                ": it is a symbolic link to target.exr; outputs replace only regular files (give the "
                "target's path to overwrite it)");
  ASSERT_EQ(::mkfifo((in.dir / "pipe.exr").c_str(), 0600), 0);
  EXPECT_EQ(error_of({in.dir / "pipe.exr"}, in.log),
            "cannot write " + (in.dir / "pipe.exr").string() + ": it is a FIFO, not a regular file");
  EXPECT_EQ(error_of({"/dev/null"}, in.log),
            "cannot write /dev/null: it is a character device, not a regular file");
  EXPECT_EQ(error_of({in.dir}, in.log), "cannot write " + in.dir.string() + ": it is a directory");
}

}  // namespace
}  // namespace ochre::output_files_test
