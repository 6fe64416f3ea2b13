#pragma once
// Loads a scene into a Scene: a JSON scene file (docs/scene-format.md), a Mitsuba 3 XML scene (a file
// ending in .xml, translated into the same JSON by renderer/loader/mitsuba/mitsuba_import.h,
// docs/mitsuba-import.md), or the JSON as a value already parsed (a Python dict). Every problem in the scene
// or in a file it names throws InputError with the file and the field at fault; nothing is rendered or
// written before the whole scene has loaded.

#include <filesystem>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <vector>

#include "renderer/scene/render_settings.h"
#include "renderer/scene/scene.h"

namespace ochre {

struct SceneOverrides {
  std::optional<uint32_t> spp;
  std::optional<int> threads;
  std::optional<uint64_t> seed;
  std::optional<int> width, height;
  std::optional<PolarizationSetting> polarization;
  std::optional<SamplerKind> sampler;
  std::optional<int> branches;                    // integrator.branches (ochre-converge variants)
  std::optional<int> rr_depth;                    // integrator.rr_depth (a resumed checkpoint's)
  std::optional<LightSelection> light_selection;  // integrator.light_selection (a resumed checkpoint's)
  std::optional<GuidingSetting> guiding;          // integrator.guiding (--guiding, a resumed checkpoint's)
  std::optional<double> noise_threshold;          // integrator.noise_threshold; 0 turns it off
  // Mitsuba XML scenes only: values of $name parameters, before the scene's own <default>s.
  std::vector<std::pair<std::string, std::string>> parameters;
  std::optional<std::string> preset;  // a named variant from the scene's "presets" (docs/scene-format.md)
};

// A scene file loaded: what is rendered (the scene, unchanged after loading but for its frame state) and how
// (the render job: the file's settings and outputs with the overrides applied).
struct LoadedScene {
  std::unique_ptr<Scene> scene;
  RenderJob job;
};

LoadedScene load_scene(const std::filesystem::path& file, const SceneOverrides& overrides = {});

// The render job of a scene file only: its film, integrator and output settings (includes and the preset
// applied; an XML scene translated) with the overrides applied, checked as load_scene checks them. No
// camera, material, shape or light is loaded, so this is cheap whatever the scene's size: for checking a
// command line against a scene before any work (ochre render --check-settings, docs/cli.md).
RenderJob load_render_job(const std::filesystem::path& file, const SceneOverrides& overrides = {});

// A scene given as JSON: `name` names it in every message ("scene.json", "<dict>"); relative paths in it
// resolve against the directory of `scene_path` (scene.file).
LoadedScene load_scene_json(const nlohmann::json& root, const std::string& name,
                            const std::filesystem::path& scene_path, const SceneOverrides& overrides = {});

}  // namespace ochre
