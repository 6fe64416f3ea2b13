#include "renderer/scene/scene.h"

#include <algorithm>

#include "spectra/emission_shape.h"
#include "spectra/non_finite.h"

namespace ochre {

void Scene::build_lights(bool mirror_lights_on) {
  mesh_light.assign(meshes.size(), -1);
  for (size_t m = 0; m < meshes.size(); ++m) {
    const CompiledMaterial& material = *materials[meshes[m].material];
    if (!material.facts().is_emissive) continue;
    auto light = std::make_unique<AreaLight>(meshes[m], material, textures.get(), origin.to_float());
    if (light->power() <= 0.0f) continue;
    if (m < mesh_polarizers.size()) light->polarizer_axis = mesh_polarizers[m];
    if (m < mesh_light_groups.size()) light->group = mesh_light_groups[m];
    mesh_light[m] = static_cast<int>(lights.size());
    lights.push_back(std::move(light));
  }
  environment_light = -1;
  for (size_t i = 0; i < lights.size(); ++i)
    if (lights[i].get() == environment) environment_light = static_cast<int>(i);
  if (mirror_lights_on) mirror_lights.build(meshes, materials, lights.size(), environment_light);
  update_light_selection();
  build_light_groups();
}

bool Scene::rays_find_emission() const {
  if (environment) return true;
  return std::any_of(meshes.begin(), meshes.end(),
                     [&](const Mesh& mesh) { return materials[mesh.material]->facts().is_emissive; });
}

void Scene::build_light_groups() {
  light_groups.clear();
  light_group_of.assign(lights.size(), -1);
  other_light_group = -1;
  bool named = false;
  for (const auto& light : lights) named = named || !light->group.empty();
  for (const std::string& group : mesh_light_groups) named = named || !group.empty();
  if (!named) return;
  for (size_t i = 0; i < lights.size(); ++i) {
    const std::string& name = lights[i]->group;
    if (name.empty()) continue;
    const auto it = std::find(light_groups.begin(), light_groups.end(), name);
    light_group_of[i] = static_cast<int>(it - light_groups.begin());
    if (it == light_groups.end()) light_groups.push_back(name);
  }
  // Every other emitter (a light without a group, an emissive surface too faint to be a light) is in
  // "other", so that the groups sum to the image.
  bool ungrouped = std::find(light_group_of.begin(), light_group_of.end(), -1) != light_group_of.end();
  for (size_t m = 0; m < meshes.size(); ++m)
    ungrouped = ungrouped || (mesh_light[m] < 0 && materials[meshes[m].material]->facts().is_emissive);
  if (ungrouped) {
    other_light_group = static_cast<int>(light_groups.size());
    light_groups.push_back(kOtherLightGroup);
    for (int& g : light_group_of)
      if (g < 0) g = other_light_group;
  }
}

std::vector<std::string> Scene::light_group_emission() const {
  std::vector<std::optional<std::vector<double>>> shapes(light_groups.size());
  std::vector<bool> none(light_groups.size(), false);
  if (other_light_group >= 0) none[static_cast<size_t>(other_light_group)] = true;
  for (size_t i = 0; i < lights.size() && i < light_group_of.size(); ++i) {
    if (light_group_of[i] < 0) continue;  // no groups
    const size_t g = static_cast<size_t>(light_group_of[i]);
    if (none[g]) continue;
    const Spectrum* spectrum = lights[i]->emission_spectrum();
    std::optional<std::vector<double>> shape;
    if (spectrum) shape = emission_shape(*spectrum);
    if (!shape || (shapes[g] && !same_emission_shape(*shapes[g], *shape)))
      none[g] = true;
    else
      shapes[g] = std::move(shape);
  }
  std::vector<std::string> texts(light_groups.size());
  for (size_t g = 0; g < texts.size(); ++g)
    if (!none[g] && shapes[g]) texts[g] = format_emission_shape(*shapes[g]);
  return texts;
}

void Scene::set_frame(uint64_t frame, double fps, uint64_t seed) {
  for (const FlameLight& flame : flames) apply_flame_state(flame, flame_state(flame, seed, frame, fps));
  update_light_selection();
}

void Scene::light_pmfs(const Vec3& p, LightPmfs& out) const {
  const size_t n = lights.size();
  float total = 0.0f;
  for (size_t i = 0; i < n; ++i) {
    out[i] = std::clamp(finite_or_limit(lights[i]->importance(p)), 0.0f, 1e30f);  // NaN and below 0: 0
    total += out[i];
  }
  // A quarter by the importance here, three quarters by power (all of it when no light claims the point): the
  // best of the shares measured on the rock benchmark scene (docs/performance.md, lever f).
  const float local = total > 0.0f ? 0.25f / total : 0.0f;
  const float global = total > 0.0f ? 0.75f : 1.0f;
  for (size_t i = 0; i < n; ++i) out[i] = out[i] * local + global * light_selection.pmf(i);
}

void Scene::update_light_selection() {
  std::vector<double> power(lights.size());
  // An emitter whose radiance overflows has an infinite (or NaN) power estimate; the selection needs finite
  // weights (NaN counts as 0: such a light is only found by rays that hit it).
  for (size_t i = 0; i < lights.size(); ++i) power[i] = finite_or_limit(lights[i]->power());
  light_selection = Distribution1D(power);
  mirror_lights.update_selection(light_selection);
}

}  // namespace ochre
