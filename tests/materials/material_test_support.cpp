#include "material_test_support.h"

#include <stdexcept>

#include "support/spectrum_lanes.h"
#include "support/test_paths.h"

namespace ochre::test {

int StubResolver::texture(const std::filesystem::path& file, const std::string& colorspace, int& channels) {
  const auto it = textures_.find(file);
  if (it == textures_.end()) throw std::runtime_error("no such file");
  colorspaces.push_back(colorspace);
  channels = it->second;
  return static_cast<int>(std::distance(textures_.begin(), it));
}

void StubTextures::lookup(int texture_id, const Vec2& uv, float footprint, int first_channel, int nchannels,
                          float* out) const {
  last_uv = uv;
  last_footprint = footprint;
  last_first_channel = first_channel;
  ++lookups;
  for (int k = 0; k < nchannels; ++k) {
    const int c = first_channel + k;
    out[k] = c == 0 ? uv.x : c == 1 ? uv.y : c == 2 ? 0.25f + texture_id : 0.1f * c;
  }
}

std::shared_ptr<const CompiledMaterial> compile(const std::string& json_text, ResourceResolver& resolver) {
  return compile_material(nlohmann::json::parse(json_text), "m", kSceneFile, resolver);
}

std::shared_ptr<const CompiledMaterial> compile(const std::string& json_text) {
  StubResolver resolver;
  return compile(json_text, resolver);
}

const SampledWavelengths& test_wavelengths() {
  static const SampledWavelengths lambda = SampledWavelengths::fixed(lanes({400.0f, 500.0f, 600.0f, 700.0f}));
  return lambda;
}

MaterialEvaluation::MaterialEvaluation() : resolver(scratch_dir()) {}

const Closure& MaterialEvaluation::evaluate(const CompiledMaterial& m) {
  ctx.lambda = &lambda;
  ctx.textures = &textures;
  arena.reset();
  m.evaluate(ctx, arena, closure);
  return closure;
}

const Closure& MaterialEvaluation::evaluate(const std::string& json_text) {
  material = compile(json_text, resolver);
  return evaluate(*material);
}

}  // namespace ochre::test
