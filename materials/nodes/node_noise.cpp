// noise(position; pattern, frequency, octaves, lacunarity, gain, seed, width): procedural 3D noise of a
// position (by default the shading point's world position), seamless on any mesh and needing no uvs:
// fractal gradient noise or the crack lines of a cellular pattern (materials/numerics/noise.h).

#include <array>
#include <cmath>

#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_choices.h"
#include "materials/nodes/node_definition.h"
#include "materials/numerics/noise.h"

namespace ochre {

namespace {

enum class NoisePattern { kFbm, kCracks };
constexpr std::array kNoisePatterns{Choice{"fbm", NoisePattern::kFbm},
                                    Choice{"cracks", NoisePattern::kCracks}};

struct NoiseData {
  NoisePattern pattern = NoisePattern::kFbm;
  float frequency = 1.0f;
  FractalNoise fractal;
  uint32_t seed = 0;
  float width = 0.05f;
};

Prepared prepare_noise(const PrepareArgs& args) {
  auto data = std::make_shared<NoiseData>();
  data->pattern = choice_value(args, "pattern", kNoisePatterns);
  data->frequency = args.params.at("frequency").get<float>();
  data->fractal.octaves = args.params.at("octaves").get<int>();
  data->fractal.lacunarity = args.params.at("lacunarity").get<float>();
  data->fractal.gain = args.params.at("gain").get<float>();
  data->seed = static_cast<uint32_t>(args.params.at("seed").get<int>());
  data->width = args.params.at("width").get<float>();
  Prepared p;
  p.payload = data;
  return p;
}

void eval_noise(const NodeArgs& a) {
  const NoiseData& n = a.data<NoiseData>();
  const Vec3 p = a.in_vector(0) * n.frequency;
  if (n.pattern == NoisePattern::kCracks) {
    const CellDistances c = cell_noise(p, n.seed);
    const float t = std::fmin(1.0f, (c.f2 - c.f1) / n.width);  // NaN-free: f2 >= f1, width > 0
    a.set_float(0, 1.0f - t * t * (3.0f - 2.0f * t));
  } else {
    a.set_float(0, 0.5f + 0.5f * fractal_noise(p, n.fractal, n.seed));
  }
}

}  // namespace

NodeDefinition noise_node() {
  NodeDefinition d;
  d.name = "noise";
  d.doc = "Procedural 3D noise of a position: fractal gradient noise or cellular crack lines.";
  d.inputs = {context_input("position", SocketType::kVector, "position",
                            "where the noise is evaluated; default: the shading point's world position")};
  d.params = {
      choice_param(
          "pattern", "fbm", choice_names(kNoisePatterns),
          "fbm: 0.5 + 0.5 x fractal gradient noise; cracks: 1 on the borders of random cells, 0 inside"),
      number_param("frequency", 1.0, 1e-6, 1e6, "features per unit length (the position is scaled by it)"),
      integer_param("octaves", 4, 1, 16, "fbm: layers summed"),
      number_param("lacunarity", 2.0, 1.0, 8.0, "fbm: frequency ratio of successive layers"),
      number_param("gain", 0.5, 0.0, 1.0, "fbm: amplitude ratio of successive layers"),
      integer_param("seed", 0, 0, std::nullopt, "selects an independent pattern"),
      number_param("width", 0.05, 1e-6, 1.0, "cracks: width of a line in cell units")};
  d.outputs = {{"value", SocketType::kFloat, false, "in [0, 1]"}};
  d.prepare = prepare_noise;
  d.eval = eval_noise;
  return d;
}

}  // namespace ochre
