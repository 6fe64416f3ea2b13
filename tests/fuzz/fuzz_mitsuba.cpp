// Fuzz target: the Mitsuba 3 XML import (renderer/loader/mitsuba/mitsuba_import.h) on XML text, written to
// scene.xml in the fuzz workspace (so that it may name quad.obj, colours.ply, checker.ppm, sky.exr, ... and
// include itself), translated and loaded, then a 4 x 4 render at 1 sample per pixel on one thread. The
// import's sizes are fixed (a sphere's 96 subdivisions, a disk's 128 segments), so no input is skipped.
// Expected errors: InputError, GraphError, ImageError.

#include "fuzz_support.h"
#include "renderer/film/film.h"
#include "renderer/integrator/render.h"
#include "renderer/loader/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path file =
      ochre::fuzz::write_workspace_file("scene.xml", ochre::fuzz::as_text(data, size));
  ochre::fuzz::expect_only_input_errors([&] {
    ochre::SceneOverrides small;
    small.width = 4;
    small.height = 4;
    small.spp = 1;
    small.threads = 1;
    const ochre::LoadedScene scene = ochre::load_scene(file, small);
    ochre::Film film(scene.job.settings.width, scene.job.settings.height);
    ochre::render(*scene.scene, scene.job, film);
  });
  return 0;
}
