// Fuzz target: OBJ and PLY import (renderer/shapes/mesh_import.h, renderer/shapes/control_mesh.h) through the
// scene loader. The input is the mesh file: written as mesh.ply when it starts with "ply", else as mesh.obj,
// and loaded by two fixed scenes, one importing triangles (with generated smooth normals) and one refining
// the polygons by one level of Catmull-Clark subdivision. Expected errors: InputError.

#include <array>
#include <map>

#include "fuzz_support.h"
#include "renderer/loader/scene_loader.h"

namespace {

using namespace ochre::fuzz;

std::string scene_text(const std::string& mesh_file, const char* shape_options) {
  return R"({"camera": {"eye": [0, 0, 5]}, "materials": {"m": {"type": "lambert"}},
            "shapes": [{"type": "mesh", "file": ")" +
         mesh_file + R"(", "material": "m", )" + shape_options + "}]}";
}

// The two scenes that load `mesh_file` (written once per mesh file name).
const std::filesystem::path* scenes_for(const std::string& mesh_file) {
  static const std::map<std::string, std::array<std::filesystem::path, 2>> scenes = [] {
    std::map<std::string, std::array<std::filesystem::path, 2>> written;
    for (const std::string name : {"mesh.obj", "mesh.ply"}) {
      written[name] = {
          write_workspace_file(name + "-triangles.json", scene_text(name, R"("smooth_normals": true)")),
          write_workspace_file(
              name + "-subdivided.json",
              scene_text(name, R"("subdivision": {"scheme": "catmull-clark", "level": 1})"))};
    }
    return written;
  }();
  return scenes.at(mesh_file).data();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes = as_text(data, size);
  const std::string mesh_file = bytes.substr(0, 3) == "ply" ? "mesh.ply" : "mesh.obj";
  write_workspace_file(mesh_file, bytes);
  const std::filesystem::path* scenes = scenes_for(mesh_file);
  for (int i = 0; i < 2; ++i) expect_only_input_errors([&] { ochre::load_scene(scenes[i]); });
  return 0;
}
