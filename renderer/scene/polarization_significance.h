#pragma once
// How much tracing polarization can change the intensities of a scene's render (docs/polarization.md,
// "Automatic mode"). With unpolarized lights and a camera that measures intensity, the Mueller product along
// a path changes the intensity only through chains of polarizing interactions: the light leaving a vertex
// is partly polarized (the closure's polarizance, |M[1..3][0]| / M00) and the next vertex toward the camera
// weighs polarized light unequally (its diattenuation, |M[0][1..3]| / M00); their product bounds the
// relative change of that path's contribution. A rough dielectric film over a diffuse base (the default
// cave) has both near 1 % (the film reflects a few percent of the light), so its render changes by ~1e-4 or
// less; a rough gold surface has both near 10 %.

#include "renderer/scene/polarization_mode.h"
#include "renderer/scene/scene.h"

namespace ochre {

// Estimated from the scene's meshes: each polarizing material evaluated at 64 points of the meshes that use
// it (fixed seed: the same figures on every run) for 16 pairs of cosine-distributed directions each, the
// Mueller elements summed over the pairs and the wavelengths before the ratios are taken. Materials that do
// not polarize count 0. Milliseconds.
PolarizationSignificance polarization_significance(const Scene& scene);

}  // namespace ochre
