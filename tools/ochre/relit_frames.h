#pragma once
// `ochre render --frames N --relight` (docs/cli.md, "Frame sequences"; docs/lights.md, "Relit flicker
// sequences"): a flicker sequence from one render. Each flame sits in a light group of its own; the scene is
// rendered once with the flames at their mean, and each frame is that render relit with the flames'
// intensities (and colour temperatures) at the frame's time. Exact for the intensity (a group's layer is
// linear in its light's intensity), as exact as the spectral bins for a colour temperature
// (renderer/output/relight.h); a flame's position flicker cannot be relit and is left out (a warning says
// so).

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/output/relight.h"
#include "renderer/scene/scene.h"

namespace ochre {

// The spectral bins a relit sequence gets when a flame's colour temperature flickers and none are asked for.
inline constexpr int kRelitFrameBins = 16;

// Puts each flame of `scene` in a light group of its own: "flameK" (K its place among the scene's flames,
// from 1) unless it names one. A flame whose group holds another light is an InputError naming the group.
// Updates `job`'s outputs (the groups, their emission shapes, and kRelitFrameBins spectral bins when a
// flame's colour temperature flickers and the outputs have none). Returns the warnings to show (position
// flicker).
std::vector<std::string> prepare_relit_flames(Scene& scene, RenderJob& job);

// The changes of the flames' groups that turn the render of the flames at their mean into frame `frame`
// (0-based) at `fps` for the render seed `seed`: each flame's intensity at the frame over its mean, and its
// colour temperature when that flickers.
std::vector<GroupChange> flame_frame_changes(const Scene& scene, uint64_t frame, double fps, uint64_t seed);

}  // namespace ochre
