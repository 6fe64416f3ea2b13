#include "renderer/lights/flame_light.h"

#include <algorithm>

#include "renderer/lights/flicker_process.h"

namespace ochre {

namespace {
// Independent random streams of one flame: intensity, colour temperature, position x, y, z.
constexpr uint64_t kStreamsPerFlame = 8;
enum Stream : uint64_t { kIntensity = 0, kCct = 1, kPositionX = 2 };
// A blackbody colder than this emits no visible light in single precision (docs/scene-format.md).
constexpr float kMinFlameCct = 500.0f;
}  // namespace

FlameState flame_state(const FlameLight& flame, uint64_t seed, uint64_t frame, double fps) {
  const FlickerStats& f = flame.flicker;
  const uint64_t base = static_cast<uint64_t>(flame.index) * kStreamsPerFlame;
  auto value = [&](uint64_t stream) {
    return ou_process_value(seed, base + stream, frame, fps, f.corner_hz);
  };
  FlameState s{flame.position, flame.cct_k, flame.intensity_cd};
  if (f.relative_std > 0.0f)
    s.intensity_cd =
        static_cast<float>(flame.intensity_cd * lognormal_factor(value(kIntensity), f.relative_std));
  if (f.cct_std_k > 0.0f)
    s.cct_k = std::max(kMinFlameCct, static_cast<float>(flame.cct_k + f.cct_std_k * value(kCct)));
  if (f.position_std_m > 0.0f)
    for (int axis = 0; axis < 3; ++axis)
      s.position[axis] +=
          static_cast<float>(f.position_std_m * value(kPositionX + static_cast<uint64_t>(axis)));
  return s;
}

void apply_flame_state(const FlameLight& flame, const FlameState& state) {
  flame.light->set_state(state.position, flame_spectrum(state.cct_k, state.intensity_cd));
}

}  // namespace ochre
