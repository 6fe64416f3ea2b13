#include "renderer/lights/flicker_process.h"

#include <cmath>

#include "renderer/sampling/sampler.h"

namespace ochre {

namespace {
// Uniform in (0, 1]: 53 bits of a hash, never 0 (log(0) in Box-Muller).
double hashed_uniform(uint64_t key) {
  return (static_cast<double>(mix64(key) >> 11) + 1.0) * 0x1p-53;
}
}  // namespace

double hashed_standard_normal(uint64_t seed, uint64_t stream, uint64_t index) {
  const uint64_t key = mix64(mix64(seed ^ 0x5eed0f1a3e5ull) + stream * 0x9e3779b97f4a7c15ull) + 2 * index;
  const double u1 = hashed_uniform(key), u2 = hashed_uniform(key + 1);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

OuProcess::OuProcess(uint64_t seed, uint64_t stream, double fps, double corner_hz)
    : seed_(seed),
      stream_(stream),
      a_(std::exp(-2.0 * M_PI * corner_hz / fps)),  // exp(-dt / tau), tau = 1 / (2 pi f_c)
      b_(std::sqrt(1.0 - a_ * a_)),
      x_(hashed_standard_normal(seed, stream, 0)) {}

void OuProcess::advance() {
  ++frame_;
  x_ = a_ * x_ + b_ * hashed_standard_normal(seed_, stream_, frame_);
}

double ou_process_value(uint64_t seed, uint64_t stream, uint64_t frame, double fps, double corner_hz) {
  OuProcess process(seed, stream, fps, corner_hz);
  while (process.frame() < frame) process.advance();
  return process.value();
}

double lognormal_factor(double x, double relative_std) {
  const double s2 = std::log1p(relative_std * relative_std);
  return std::exp(std::sqrt(s2) * x - 0.5 * s2);
}

}  // namespace ochre
