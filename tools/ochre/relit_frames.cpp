#include "tools/ochre/relit_frames.h"

#include <fmt/format.h>

#include <map>

#include "renderer/lights/light_presets.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

// The index in scene.lights of a flame's sphere light.
size_t light_index(const Scene& scene, const FlameLight& flame) {
  for (size_t i = 0; i < scene.lights.size(); ++i)
    if (scene.lights[i].get() == flame.light) return i;
  throw std::logic_error("relit frames: a flame's light is not among the scene's lights");
}

}  // namespace

std::vector<std::string> prepare_relit_flames(Scene& scene, RenderJob& job) {
  if (scene.flames.empty())
    throw InputError(fmt::format("--relight: {} has no flames: nothing flickers (docs/lights.md, \"Flames\")",
                                 scene.file.string()));
  std::vector<std::string> warnings;
  bool cct_flickers = false;
  for (size_t k = 0; k < scene.flames.size(); ++k) {
    const FlameLight& flame = scene.flames[k];
    std::string& group = scene.lights[light_index(scene, flame)]->group;
    if (group.empty()) group = fmt::format("flame{}", k + 1);
    cct_flickers = cct_flickers || flame.flicker.cct_std_k > 0.0f;
    if (flame.flicker.position_std_m > 0.0f)
      warnings.push_back(fmt::format(
          "--relight: flame {} (group '{}') also moves (flicker position_std {} m), which relighting cannot "
          "follow: its frames show it at its mean position (render the frames without --relight for that)",
          k + 1, group, flame.flicker.position_std_m));
  }
  scene.build_light_groups();
  std::map<int, int> lights_in_group;
  for (const int g : scene.light_group_of) ++lights_in_group[g];
  for (size_t k = 0; k < scene.flames.size(); ++k) {
    const size_t i = light_index(scene, scene.flames[k]);
    if (lights_in_group[scene.light_group_of[i]] > 1)
      throw InputError(
          fmt::format("--relight: flame {} shares its light group '{}' with other lights: each flame "
                      "flickers on its own, "
                      "so each needs a group of its own (or none: --relight names it flame{})",
                      k + 1, scene.lights[i]->group, k + 1));
  }
  if (scene.light_groups.size() > kMaxLightGroups)
    throw InputError(fmt::format("--relight: {} light groups with a group per flame; at most {}",
                                 scene.light_groups.size(), kMaxLightGroups));
  job.outputs.light_groups = scene.light_groups;
  job.outputs.light_group_emission = scene.light_group_emission();
  if (cct_flickers && job.outputs.spectral_bins == 0) job.outputs.spectral_bins = kRelitFrameBins;
  return warnings;
}

std::vector<GroupChange> flame_frame_changes(const Scene& scene, uint64_t frame, double fps, uint64_t seed) {
  std::vector<GroupChange> changes;
  for (const FlameLight& flame : scene.flames) {
    const FlameState state = flame_state(flame, seed, frame, fps);
    GroupChange change;
    change.group = scene.lights[light_index(scene, flame)]->group;
    change.scale =
        flame.intensity_cd > 0.0f ? static_cast<double>(state.intensity_cd) / flame.intensity_cd : 1.0;
    if (flame.flicker.cct_std_k > 0.0f) {
      change.spectrum = flame_spectrum(state.cct_k, 1.0f);
      change.spectrum_text = fmt::format("cct={}", state.cct_k);
    }
    changes.push_back(std::move(change));
  }
  return changes;
}

}  // namespace ochre
