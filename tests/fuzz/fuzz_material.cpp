// Fuzz target: the material graph compiler (materials/graph/material_compiler.h) on the JSON of one
// material (mutated byte-wise and by json_mutator.h), then the compiled program evaluated at two shading
// points and every lobe of the closure evaluated and sampled once. Textures are stubs (any file name opens,
// with 1 to 4 channels); spectrum files resolve into the fuzz workspace (red.csv is there). Expected errors:
// GraphError.

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "fuzz_support.h"
#include "json_mutator.h"
#include "materials/graph/material_compiler.h"
#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"

namespace {

using namespace ochre;

// Every texture "opens"; its channel count follows from the name so that the fuzzer can reach the
// 1-, 2-, 3- and 4-channel paths of the texture node.
class AnyFileResolver final : public ResourceResolver {
 public:
  std::filesystem::path resolve(const std::string& path) const override { return fuzz::workspace() / path; }
  int texture(const std::filesystem::path& file, const std::string&, int& channels) override {
    channels = 1 + static_cast<int>(file.filename().string().size() % 4);
    return next_id_++;
  }

 private:
  int next_id_ = 0;
};

// Deterministic texel values that depend on the lookup, in [0, 1].
class GradientTextures final : public TextureProvider {
 public:
  void lookup(int texture_id, const Vec2& uv, float, int first_channel, int nchannels,
              float* out) const override {
    for (int k = 0; k < nchannels; ++k)
      out[k] = 0.125f * static_cast<float>((texture_id + first_channel + k) % 8) + 0.01f * (uv.x + uv.y);
  }
};

void exercise(const CompiledMaterial& material) {
  const GradientTextures textures;
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.61f);
  LobeArena arena;
  Closure closure;
  for (const Vec2& uv : {Vec2{0.25f, 0.75f}, Vec2{0.0f, 1.0f}}) {
    ShadingContext ctx;
    ctx.p = {uv.x, uv.y, 0.5f};
    ctx.n = {0, 0, 1};
    ctx.uv = uv;
    ctx.uv_footprint = 0.01f;
    ctx.lambda = &lambda;
    ctx.textures = &textures;
    arena.reset();
    material.evaluate(ctx, arena, closure);
    const Vec3 wo = normalize(Vec3{0.3f, -0.2f, 0.9f}), wi = normalize(Vec3{-0.5f, 0.1f, 0.8f});
    closure.eval(wo, wi, lambda);
    closure.pdf(wo, wi, lambda);
    if (closure.has_polarizing_non_delta_lobes()) closure.eval_mueller(wo, wi, lambda);
    closure.sample(wo, 0.4f, {0.3f, 0.7f}, lambda);
    for (int i = 0; i < closure.lobe_count(); ++i) {
      const Lobe& lobe = *closure.lobe(i).lobe;
      lobe.albedo_hint(wo, lambda);
      lobe.sample(wo, 0.6f, {0.2f, 0.9f}, lambda);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto json = nlohmann::json::parse(fuzz::as_text(data, size), nullptr, /*allow_exceptions=*/false,
                                          /*ignore_comments=*/true);
  if (json.is_discarded()) return 0;  // not JSON: the scene loader rejects it before the compiler
  fuzz::expect_only_input_errors([&] {
    AnyFileResolver resolver;
    exercise(*compile_material(json, "fuzzed", "fuzz.json", resolver));
  });
  return 0;
}

OCHRE_FUZZ_JSON_MUTATOR
