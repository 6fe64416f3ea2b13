#include "tools/ochre/export_mesh_command.h"

#include <fmt/format.h>

#include <iostream>

#include "renderer/geometry/ply_writer.h"
#include "renderer/scene/scene.h"
#include "renderer/util/atomic_file.h"
#include "spectra/input_error.h"
#include "tools/cli/program.h"

namespace ochre {

namespace {

std::string mesh_names(const std::vector<Mesh>& meshes) {
  std::string names;
  for (const Mesh& mesh : meshes) names += (names.empty() ? "" : ", ") + fmt::format("'{}'", mesh.name);
  return names;
}

// The mesh the command names (or the only one); InputError listing the scene's meshes otherwise.
const Mesh& chosen_mesh(const ExportMeshCommand& command, const Scene& scene) {
  const std::vector<Mesh>& meshes = scene.meshes;
  if (command.shape.empty()) {
    if (meshes.size() == 1) return meshes.front();
    throw InputError(fmt::format("{}: {} meshes ({}): name one with --shape", command.scene, meshes.size(),
                                 mesh_names(meshes)));
  }
  const Mesh* found = nullptr;
  for (const Mesh& mesh : meshes) {
    if (mesh.name != command.shape) continue;
    if (found)
      throw InputError(fmt::format("{}: --shape '{}': several meshes have that name (name the shapes apart)",
                                   command.scene, command.shape));
    found = &mesh;
  }
  if (!found)
    throw InputError(fmt::format("{}: --shape '{}': no mesh of that name (the scene's meshes: {})",
                                 command.scene, command.shape, mesh_names(meshes)));
  return *found;
}

}  // namespace

int run_export_mesh(const ExportMeshCommand& command) {
  check_output_writable(command.output);  // before the scene's load, which may take a while
  const LoadedScene loaded = load_scene(command.scene, command.overrides);
  for (const std::string& warning : loaded.scene->warnings)
    std::cerr << "ochre: warning: " << warning << "\n";
  const Mesh& mesh = chosen_mesh(command, *loaded.scene);
  write_ply(mesh, loaded.scene->origin, command.output);
  if (!command.quiet)
    std::cerr << fmt::format("ochre: wrote {}: mesh '{}', {} vertices, {} triangles{}{}{}\n", command.output,
                             mesh.name, mesh.vertex_count(), mesh.triangle_count(),
                             mesh.normals.empty() ? "" : ", normals", mesh.uvs.empty() ? "" : ", uvs",
                             mesh.colours.empty() ? "" : ", colours");
  return kExitDone;
}

}  // namespace ochre
