#pragma once
// A flame in a scene (`"type": "flame"`, docs/lights.md): a sphere light with a blackbody spectrum whose
// intensity, colour temperature and position flicker from frame to frame of a sequence
// (renderer/lights/flicker_process.h). A single render (no --frames) shows the flame at its mean.

#include <cstdint>

#include "renderer/lights/light_presets.h"
#include "renderer/lights/sphere_light.h"

namespace ochre {

struct FlameLight {
  SphereLight* light = nullptr;  // owned by Scene::lights
  int index = 0;                 // among the scene's flames: chooses the random streams
  Vec3 position;                 // mean position
  float cct_k = 1700.0f;         // mean colour temperature
  float intensity_cd = 1.0f;     // mean luminous intensity
  FlickerStats flicker;
};

// Where a flame is, how bright and how hot at frame `frame` (0-based) of a sequence at `fps` frames per
// second, for the render seed `seed`.
struct FlameState {
  Vec3 position;
  float cct_k;
  float intensity_cd;
};
FlameState flame_state(const FlameLight& flame, uint64_t seed, uint64_t frame, double fps);

// Sets the sphere light of `flame` to `state`.
void apply_flame_state(const FlameLight& flame, const FlameState& state);

}  // namespace ochre
