#pragma once
// `ochre export-mesh SCENE -o OUT.ply` (docs/cli.md, "ochre export-mesh"): writes one mesh of a scene as the
// renderer renders it (subdivided, displaced, transformed: world coordinates, vertex normals, uvs and
// colours where it has them) as a binary PLY file, for other programs (Blender: docs/blender.md). Returns 0,
// or 2 (bad input: the scene, an unknown or ambiguous shape, an output that cannot be written; nothing is
// written then).

#include <string>

#include "renderer/loader/scene_loader.h"

namespace ochre {

struct ExportMeshCommand {
  std::string scene;
  SceneOverrides overrides;  // the preset and -D parameters only
  std::string shape;         // the mesh's name; may be empty when the scene has one mesh
  std::string output;
  bool quiet = false;
};

int run_export_mesh(const ExportMeshCommand& command);

}  // namespace ochre
