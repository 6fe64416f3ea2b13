#pragma once
// Deterministic 3D procedural noise for rock surfaces: gradient noise (Perlin 2002, "Improving noise"),
// its fractal sum (fBm), cellular noise (Worley 1996, "A cellular texture basis function") and the
// rock height field built from them (fBm relief, cracks along cell borders, flowstone drapes). Pure
// functions of the position and the seed (integer hashing, no tables, no state), so a displaced mesh or
// a noise texture is the same on every machine, thread count and call order.

#include <cstdint>

#include "materials/core/vec3.h"

namespace ochre {

// Perlin's improved gradient noise: 0 at every lattice point, about [-1, 1] elsewhere (the extremes are
// rare; the standard deviation is about 0.2).
float gradient_noise(const Vec3& p, uint32_t seed);

struct FractalNoise {
  int octaves = 5;          // number of summed layers, 1..16
  float lacunarity = 2.0f;  // frequency ratio of successive layers
  float gain = 0.5f;        // amplitude ratio of successive layers
};

// Sum over octaves o of gain^o gradient_noise(p lacunarity^o), divided by the sum of the amplitudes, so
// the result stays within [-1, 1]. Each octave has its own seed, so octaves do not line up at the origin.
float fractal_noise(const Vec3& p, const FractalNoise& fractal, uint32_t seed);

// Distances from p to the nearest and second-nearest feature points of a cellular pattern with one
// feature point per unit cell.
struct CellDistances {
  float f1 = 0, f2 = 0;
};
CellDistances cell_noise(const Vec3& p, uint32_t seed);

// The rock height field of a displaced cave wall, in units of the displacement scale:
//   h(p) = fbm(p f)                                           relief
//        + flowstone (bands elongated along `up`, ridged)    drapes of calcite
//        - cracks    (1 - smoothstep(0, w, F2 - F1) at p fc)   grooves along the cell borders
// p is in scene units (metres); the result is about [-1 - cracks, 1 + flowstone].
struct RockNoise {
  float frequency = 1.0f;  // f: features of the relief per unit length
  FractalNoise fractal;
  uint32_t seed = 0;
  float cracks = 0.0f;            // depth of the cracks (0: none)
  float crack_frequency = 0.5f;   // fc: crack cells per unit length
  float crack_width = 0.05f;      // w: width of a crack in cell units
  float flowstone = 0.0f;         // height of the flowstone drapes (0: none)
  float flowstone_frequency = 3;  // drapes per unit length across `up` (along it 8 times fewer)
  Vec3 up{0, 1, 0};               // the direction water runs down (unit)
};
float rock_height(const Vec3& p, const RockNoise& rock);

}  // namespace ochre
