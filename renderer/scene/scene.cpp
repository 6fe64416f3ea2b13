#include "renderer/scene/scene.h"

#include <algorithm>

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
    mesh_light[m] = static_cast<int>(lights.size());
    lights.push_back(std::move(light));
  }
  environment_light = -1;
  for (size_t i = 0; i < lights.size(); ++i)
    if (lights[i].get() == environment) environment_light = static_cast<int>(i);
  if (mirror_lights_on) mirror_lights.build(meshes, materials, lights.size(), environment_light);
  update_light_selection();
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
