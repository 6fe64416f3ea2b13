// Fuzz target: the scene loader (renderer/loader/scene_loader.h) on scene JSON text, mutated byte-wise and by
// json_mutator.h, then a 4 x 4 render at 1 sample per pixel on one thread. The text is written to
// scene.json in the fuzz workspace, so the scene may name the workspace's resource files (quad.obj,
// cube_quads.obj, colours.ply, two_triangles.gltf, checker.ppm, sky.exr, red.csv; see fuzz_support.h).
//
// Bounded work: the film is overridden to 4 x 4 pixels, 1 spp, 1 thread; inputs asking for more than
// 64 sphere subdivisions, 4096 disk segments or subdivision level 3 are skipped before loading (the
// loader accepts up to 4096, 2^20 and 8: valid, but too slow to fuzz). Expected errors: InputError,
// GraphError, ImageError.

#include <nlohmann/json.hpp>

#include "fuzz_support.h"
#include "json_mutator.h"
#include "renderer/film/film.h"
#include "renderer/integrator/render.h"
#include "renderer/loader/scene_loader.h"

namespace {

// The largest value the target lets each size-like key reach, wherever it appears.
bool within_fuzz_bounds(const nlohmann::json& j) {
  static const std::pair<const char*, double> kLimits[] = {
      {"subdivisions", 64}, {"segments", 4096}, {"level", 3}};
  if (j.is_array()) {
    for (const auto& element : j)
      if (!within_fuzz_bounds(element)) return false;
  }
  if (!j.is_object()) return true;
  for (const auto& [key, value] : j.items()) {
    for (const auto& [limited, limit] : kLimits)
      if (key == limited && value.is_number() && !(value.get<double>() <= limit)) return false;
    if (!within_fuzz_bounds(value)) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text = ochre::fuzz::as_text(data, size);
  const auto json =
      nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false, /*ignore_comments=*/true);
  if (!json.is_discarded() && !within_fuzz_bounds(json)) return 0;
  const std::filesystem::path file = ochre::fuzz::write_workspace_file("scene.json", text);
  ochre::fuzz::expect_only_input_errors([&] {
    ochre::SceneOverrides small;
    small.width = 4;
    small.height = 4;
    small.spp = 1;
    small.threads = 1;
    const ochre::LoadedScene scene = ochre::load_scene(file, small);
    ochre::Film film(scene.job.settings.width, scene.job.settings.height);
    if (scene.job.outputs.stokes) film.enable_stokes();
    ochre::render(*scene.scene, scene.job, film);
  });
  return 0;
}

OCHRE_FUZZ_JSON_MUTATOR
