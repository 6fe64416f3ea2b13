#pragma once
// The start of a camera sample (its random numbers, wavelengths and camera ray: a pure function of the seed,
// the pixel and the sample index) and the value the film records for its radiance.

#include <cstdint>

#include "renderer/geometry/ray.h"
#include "renderer/sampling/sampler.h"
#include "renderer/scene/scene.h"
#include "spectra/cie.h"

namespace ochre {

template <class Sampler>
struct CameraSample {
  Sampler sampler;
  SampledWavelengths lambda;
  Ray ray;
};

// Sample `index` of image pixel (x, y) of an image `width` pixels wide.
template <class Sampler>
CameraSample<Sampler> camera_sample(const Scene& scene, uint64_t seed, int x, int y, int width,
                                    uint32_t index) {
  const uint64_t pixel_index =
      static_cast<uint64_t>(y) * static_cast<uint64_t>(width) + static_cast<uint64_t>(x);
  const Sampler sampler(seed, pixel_index, index);
  const float u_lambda = sampler.get_1d(SampleDims::kWavelength);
  const SampledWavelengths lambda = scene.sensor ? scene.sensor->sample_wavelengths(u_lambda)
                                                 : SampledWavelengths::sample_visible(u_lambda);
  const Vec2 jitter = scene.pixel_filter.sample(sampler.get_2d(SampleDims::kPixelJitter));
  return {sampler, lambda,
          scene.camera.generate_ray(static_cast<float>(x) + jitter.x, static_cast<float>(y) + jitter.y)};
}

// The film records XYZ (the CIE observer, `sensor` null) or a camera sensor's R, G, B (docs/cameras.md).
inline XYZ sensor_value(const SensorResponse* sensor, const SampledSpectrum& L,
                        const SampledWavelengths& lambda) {
  return sensor ? sensor->response(L, lambda) : sampled_to_xyz(L, lambda);
}

}  // namespace ochre
