#include "materials/numerics/noise.h"

#include <algorithm>
#include <cmath>

#include "materials/core/vector_clones.h"

namespace ochre {

namespace {

// Chris Wellons' "lowbias32" integer hash (hash-prospector): full avalanche in a few operations.
uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// One avalanche of a multiply-add combination of the lattice coordinates (large odd constants, so
// neighbouring cells differ in many bits before the hash).
uint32_t hash_cell(int x, int y, int z, uint32_t seed) {
  return hash32(static_cast<uint32_t>(x) * 0x8da6b343U + static_cast<uint32_t>(y) * 0xd8163841U +
                static_cast<uint32_t>(z) * 0xcb1ab31fU + seed * 0x9e3779b9U);
}

// Uniform in [0, 1) from the top 24 bits.
float unit_float(uint32_t h) {
  return static_cast<float>(h >> 8) * 0x1p-24f;
}

// One of Perlin's 12 edge gradients (of a cube), dotted with the offset (x, y, z). A table of the
// gradients' components (0 or +-1) instead of a switch: the hash makes the choice unpredictable, and eight
// mispredicted branches per lookup cost more than the multiplications (the products are exact, so the sums
// are those of the switch).
float gradient_dot(uint32_t h, float x, float y, float z) {
  static constexpr float kGradients[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                              {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                              {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};
  const float* g = kGradients[h % 12u];
  return g[0] * x + g[1] * y + g[2] * z;
}

// Perlin's quintic fade 6t^5 - 15t^4 + 10t^3: continuous second derivative across cells.
float fade(float t) {
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

// Linear interpolation (OSL's name for it).
float mix(float a, float b, float t) {
  return a + t * (b - a);
}

float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Integer lattice cell of a coordinate; coordinates beyond the int range (never in a scene of sane
// size) are clamped so that the conversion stays defined.
int cell_of(float x) {
  return static_cast<int>(std::clamp(std::floor(x), -2.0e9f, 2.0e9f));
}

// Two unit vectors perpendicular to `up` and to each other.
void perpendiculars(const Vec3& up, Vec3& a, Vec3& b) {
  const Vec3 helper = std::fabs(up.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 0, 1);
  a = normalize(cross(up, helper));
  b = cross(up, a);
}

// Perlin's improved noise at p (gradient_noise below; fractal_noise inlines it).
float gradient_noise_at(const Vec3& p, uint32_t seed) {
  const int ix = cell_of(p.x), iy = cell_of(p.y), iz = cell_of(p.z);
  const float fx = p.x - std::floor(p.x), fy = p.y - std::floor(p.y), fz = p.z - std::floor(p.z);
  const float u = fade(fx), v = fade(fy), w = fade(fz);
  auto corner = [&](int dx, int dy, int dz) {
    return gradient_dot(hash_cell(ix + dx, iy + dy, iz + dz, seed), fx - float(dx), fy - float(dy),
                        fz - float(dz));
  };
  const float x00 = mix(corner(0, 0, 0), corner(1, 0, 0), u), x10 = mix(corner(0, 1, 0), corner(1, 1, 0), u);
  const float x01 = mix(corner(0, 0, 1), corner(1, 0, 1), u), x11 = mix(corner(0, 1, 1), corner(1, 1, 1), u);
  return mix(mix(x00, x10, v), mix(x01, x11, v), w);
}

}  // namespace

// The eight corners' hashes and gradients are independent: with AVX2 they go through in one or two vector
// instructions each (1.2-1.7x faster on this machine's rock material, the same bits).
OCHRE_VECTOR_CLONES float gradient_noise(const Vec3& p, uint32_t seed) {
  return gradient_noise_at(p, seed);
}

OCHRE_VECTOR_CLONES float fractal_noise(const Vec3& p, const FractalNoise& fractal, uint32_t seed) {
  float sum = 0.0f, norm = 0.0f, amplitude = 1.0f, frequency = 1.0f;
  for (int o = 0; o < fractal.octaves; ++o) {
    sum += amplitude * gradient_noise_at(p * frequency, hash32(seed + static_cast<uint32_t>(o)));
    norm += amplitude;
    amplitude *= fractal.gain;
    frequency *= fractal.lacunarity;
  }
  return norm > 0.0f ? sum / norm : 0.0f;
}

CellDistances cell_noise(const Vec3& p, uint32_t seed) {
  const int ix = cell_of(p.x), iy = cell_of(p.y), iz = cell_of(p.z);
  float d1 = INFINITY, d2 = INFINITY;  // squared distances
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int cx = ix + dx, cy = iy + dy, cz = iz + dz;
        const uint32_t h = hash_cell(cx, cy, cz, seed);
        const Vec3 feature(float(cx) + unit_float(h), float(cy) + unit_float(hash32(h)),
                           float(cz) + unit_float(hash32(h ^ 0x9e3779b9U)));
        const Vec3 d = feature - p;
        const float dd = dot(d, d);
        if (dd < d1) {
          d2 = d1;
          d1 = dd;
        } else if (dd < d2) {
          d2 = dd;
        }
      }
  return {std::sqrt(d1), std::sqrt(d2)};
}

float rock_height(const Vec3& p, const RockNoise& rock) {
  float h = fractal_noise(p * rock.frequency, rock.fractal, rock.seed);
  if (rock.flowstone > 0.0f) {
    Vec3 a, b;
    perpendiculars(rock.up, a, b);
    const float f = rock.flowstone_frequency;
    const Vec3 q(dot(p, a) * f, dot(p, rock.up) * f * 0.125f, dot(p, b) * f);
    const float n = fractal_noise(q, {3, 2.0f, 0.5f}, hash32(rock.seed ^ 0x5bd1e995U));
    const float ridge = std::max(0.0f, 1.0f - 2.5f * std::fabs(n));
    h += rock.flowstone * ridge * ridge;
  }
  if (rock.cracks > 0.0f) {
    // Cracks meander: the cell lookup is offset by low-frequency noise.
    const Vec3 q = p * rock.crack_frequency;
    const Vec3 warp(gradient_noise(q * 2.0f, rock.seed + 11u), gradient_noise(q * 2.0f, rock.seed + 12u),
                    gradient_noise(q * 2.0f, rock.seed + 13u));
    const CellDistances c = cell_noise(q + warp * 0.35f, hash32(rock.seed ^ 0x27d4eb2fU));
    h -= rock.cracks * (1.0f - smoothstep(0.0f, rock.crack_width, c.f2 - c.f1));
  }
  return h;
}

}  // namespace ochre
