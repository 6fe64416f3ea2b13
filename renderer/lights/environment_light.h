#pragma once
// EnvironmentLight: radiance arriving from every direction at infinity, either
//   - constant: one spectrum L(lambda), sampled uniformly over the sphere, or
//   - an HDR lat-long map (environment_map.h): RGB texels (linear Rec.709) turned into illuminant
//     spectra per lookup (RGBIlluminantSpectrum semantics: sigmoid fit of rgb / (2 max) times 2 max
//     times D65 at luminance 1), importance sampled in proportion to luminance x sin(theta).
// Both take a scale (>= 0) that multiplies the radiance. A map also takes a rotation in degrees about
// the world +y axis, right-handed (counter-clockwise seen from above): with +90, what the map shows
// along -z (its centre column) appears along -x, and what it shows along +x appears along -z.
//
// Scene JSON (the "environment" light type, environment_light.cpp):
//   {"type": "environment", "radiance": <spectrum>, "scale": 1}                 constant
//   {"type": "environment", "file": "sky.hdr", "scale": 1, "rotation": 0}       map (path relative to the
//   scene)

#include <filesystem>
#include <memory>
#include <vector>

#include "renderer/json/json_fields.h"
#include "renderer/lights/environment_map.h"
#include "renderer/lights/light.h"
#include "spectra/rgb_sigmoid_polynomial.h"
#include "spectra/spectrum.h"
#include "spectra/wavelength_memo.h"

namespace ochre {

class EnvironmentLight final : public Light {
 public:
  // Constant environment.
  EnvironmentLight(SpectrumPtr radiance, float scene_radius, float scale = 1.0f);
  // Map environment.
  EnvironmentLight(std::shared_ptr<const EnvironmentMap> map, float scene_radius, float scale = 1.0f,
                   float rotation_degrees = 0.0f);

  std::optional<LightSample> sample(const Vec3& ref, const Vec2& u,
                                    const SampledWavelengths& lambda) const override;
  float power() const override;
  float importance(const Vec3& p) const override;
  const Spectrum* emission_spectrum() const override { return radiance_.get(); }  // null for a map

  // Radiance arriving along -direction (a ray escaping the scene along `direction`, any length > 0).
  SampledSpectrum radiance(const Vec3& direction, const SampledWavelengths& lambda) const;
  // Solid-angle pdf of sample() producing `direction`.
  float pdf(const Vec3& direction) const;
  // Both at once (one texel lookup).
  SampledSpectrum radiance(const Vec3& direction, const SampledWavelengths& lambda, float* pdf) const;

  const EnvironmentMap* map() const { return map_.get(); }

 private:
  Vec3 world_to_map(const Vec3& d) const;
  Vec3 map_to_world(const Vec3& d) const;
  SampledSpectrum texel_radiance(size_t key, const SampledWavelengths& lambda) const;

  // Each texel's illuminant spectrum, fitted once at construction (the fit is a trilinear lookup in a
  // 9 MB table: per lookup it cost more cache misses than the rest of the environment's sampling).
  // Stored by the map's texel key (block-major, environment_map.h): a block's 16 spectra fill 4 whole
  // cache lines, so a lookup reads one line, shared with the texel's neighbours in its 4 x 4 block.
  struct TexelSpectrum {
    RGBSigmoidPolynomial poly;
    float m = 0.0f;  // 2 max(rgb); 0 for a black texel (and the padding keys)
  };
  struct alignas(64) BlockSpectra {
    TexelSpectrum texel[Distribution2D::kCellsPerBlock];
  };
  const TexelSpectrum& texel_spectrum(size_t key) const {
    return texel_spectra_[key / Distribution2D::kCellsPerBlock].texel[key % Distribution2D::kCellsPerBlock];
  }
  std::vector<BlockSpectra> texel_spectra_;  // one entry per block of the map's distribution

  SpectrumPtr radiance_;  // constant environment (null for a map)
  std::shared_ptr<const EnvironmentMap> map_;
  SpectrumPtr d65_;                                      // the illuminant of map texels
  uint64_t white_memo_key_ = new_wavelength_memo_key();  // D65 x scale at a path's wavelengths, per thread
  float scene_radius_;
  float scale_;
  double mean_luminance_ = 0.0;  // of the radiance over the sphere, before the scale
  float cos_rotation_ = 1.0f, sin_rotation_ = 0.0f;
};

}  // namespace ochre
