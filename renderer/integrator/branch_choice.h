#pragma once
// integrator.branches "auto": how many continuations each camera sample gets from its first vertex
// (docs/architecture.md#automatic-branch-count). A deterministic pilot traces a few camera samples of a grid
// of pixels, each with two continuations, and measures how much of a path's variance comes from the part
// the branches share (camera ray, first vertex, its light sample, the wavelengths and the place in the
// pixel) and how much from a continuation, and what each costs in rays. Splitting theory gives the best
// count: with V0, c0 the shared part's variance and cost and V1, c1 a continuation's, k continuations cost
// c0 + k c1 and leave V0 + V1 / k, whose product is least at k = sqrt((V1 / V0) (c0 / c1)).
// The same pilot, run again with roulette from depth 3, weighs that against the default start (5): ending
// paths early saves their cost and adds variance to V1, so it pays in dark, closed scenes such as the cave
// and more with branches (their deep bounces are averaged). integrator.rr_depth "auto" (the default) lets it
// choose. In a scene of 2 to 8 lights it runs once more with every light sampled at each vertex (a shadow ray
// per light, no noise from choosing one), which the variance and the rays it counts weigh against one light
// per vertex: integrator.light_selection "auto" (the default). The pilot's numbers come from a seed of its
// own: the choice depends on the scene and the settings, never on the render's seed, thread count or split.

#include <string>

#include "renderer/integrator/guide_training.h"
#include "renderer/scene/render_settings.h"
#include "renderer/scene/scene.h"

namespace ochre {

struct BranchChoice {
  int branches = 1;
  int rr_depth = RenderSettings::kDefaultRouletteDepth;     // where Russian roulette starts
  LightSelection light_selection = LightSelection::kLocal;  // one light per vertex, or every light
  bool piloted = false;                                     // a pilot ran (else `reason` says why not)
  double shared_variance = 0;  // V0 / (V0 + V1): the share of a path's relative variance the branches share
                               // (V0 at the upper end of its uncertainty)
  double shared_cost = 0;      // c0: rays of the shared part per camera sample (and the sample's own work)
  double branch_cost = 0;      // c1: rays per continuation
  double optimum = 1;          // sqrt((V1 / V0) (c0 / c1)) with the default roulette start
  double predicted_gain = 1;   // time to a given error with 1 branch from the default start over the choice
  double seconds = 0;          // the pilot's time
  std::string reason;          // one line for the render's summary
  GuideTraining guide;         // the path guide's training, where guiding is on (resolve_branches)
};

// The branch count, roulette start and light sampling for a render of `scene` with `job`'s settings (each
// chosen where it is auto, as set otherwise; with branches auto spp counts paths per pixel). The count is a
// power of two that divides spp and leaves at least 4 camera samples, 16 at most; in a noise-threshold render
// at least 32 (its pixels decide at 16, 32, ... camera samples: one decision before the maximum). Renders too
// small for the pilot to be a small part of them keep 1 branch and the default start.
BranchChoice choose_branches(const Scene& scene, const RenderJob& job);

// Guiding is on but its guide not yet trained (resolve_branches trains it).
inline bool needs_guide(const RenderSettings& s) {
  return s.guiding == GuidingSetting::kOn && !s.guide;
}

// Whether a job has work left to resolve_branches: choices for the pilot (branches, rr_depth or
// light_selection auto) or a guide to train.
inline bool has_automatic_choices(const RenderSettings& s) {
  return s.branches == RenderSettings::kAutoBranches || s.rr_depth == RenderSettings::kAutoRoulette ||
         s.light_selection == LightSelection::kAuto || needs_guide(s);
}

// `job` ready to render: with branches auto, the chosen count set and spp and sample_begin turned from paths
// into camera samples; with rr_depth auto, the chosen start; with light_selection auto, `local` or `all`
// (`choice`, if given, receives the choice); other jobs come back as they are. Throws std::invalid_argument
// when sample_begin is not a whole number of camera samples.
RenderJob resolve_branches(const Scene& scene, RenderJob job, BranchChoice* choice = nullptr);

}  // namespace ochre
