// The `powder` closure compiled from JSON: its lobe is the model with the pigment table's albedo, the
// inputs and options reach it, rho overrides the Mie albedo, two grain populations mix, and bad
// parameters are errors naming them.

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

#include "materials/graph/compiled_material.h"
#include "materials/graph/material_compiler.h"
#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"
#include "materials/lobes/powder/pigment_table.h"
#include "materials/lobes/powder/powder_model.h"
#include "support/spectrum_lanes.h"
#include "support/test_paths.h"

namespace ochre::test::powder_closure_test {
namespace {

class Files : public ResourceResolver {
 public:
  explicit Files(std::filesystem::path base = "/") : base_(std::move(base)) {}
  std::filesystem::path resolve(const std::string& path) const override { return base_ / path; }
  int texture(const std::filesystem::path&, const std::string&, int&) override {
    throw std::runtime_error("no textures here");
  }

 private:
  std::filesystem::path base_;
};

const SampledWavelengths& wavelengths() {
  static const SampledWavelengths lambda = SampledWavelengths::fixed(lanes({450.0f, 550.0f, 650.0f, 700.0f}));
  return lambda;
}

SampledSpectrum evaluate(const std::string& json, const Vec3& wo, const Vec3& wi,
                         ResourceResolver&& resolver = Files()) {
  const auto material = compile_material(nlohmann::json::parse(json), "m", "scene.json", resolver);
  ShadingContext ctx;
  ctx.lambda = &wavelengths();
  LobeArena arena;
  Closure closure;
  material->evaluate(ctx, arena, closure);
  EXPECT_EQ(closure.lobe_count(), 1) << json;
  return closure.eval(wo, wi, wavelengths());
}

const Vec3 kWo = normalize(Vec3(0.3f, 0.1f, 0.8f));
const Vec3 kWi = normalize(Vec3(-0.5f, 0.2f, 0.4f));

float model(const PowderParams<float>& p, float lambda_nm, float rho, float tau, const Vec3& wi,
            const Vec3& wo) {
  return powder_brdf(p, PowderWavelength<float>{lambda_nm * 1e-3f, rho, tau}, wi, wo);
}

TEST(PowderNode, DefaultsAreTheDefaultHematitePowder) {
  const SampledSpectrum f = evaluate(R"({"type": "powder"})", kWo, kWi);
  const auto table = PigmentTable::named("hematite", PowderTau::kPaper);
  for (int i = 0; i < 4; ++i) {
    const float l = wavelengths()[i];
    EXPECT_FLOAT_EQ(f[i],
                    model(PowderParams<float>{}, l, table->albedo(l, 0.05f), table->tau_o(l), kWi, kWo));
  }
  // Fine hematite is red: more light at 650-700 nm than at 450-550 nm.
  EXPECT_GT(f[3], 2.0f * f[1]);
}

TEST(PowderNode, InputsAndOptionsReachTheModel) {
  const std::string json =
      R"({"type": "powder", "volume_amplitude": 1.7, "g": 0.3, "kappa": 0.6, "radius": 0.12,
      "surface_amplitude": 1e-5, "correlation_length": 1.5, "thickness": 40, "ladder_decay": "alpha",
      "normalisation": "printed", "pigment": "hematite_o", "tau": "two_thirds"})";
  const SampledSpectrum f = evaluate(json, kWo, kWi);
  PowderParams<float> p;
  p.volume_amplitude = 1.7f, p.g = 0.3f, p.kappa = 0.6f, p.surface_amplitude = 1e-5f,
  p.correlation_length = 1.5f;
  p.thickness = 40.0f, p.ladder_decay = PowderLadderDecay::kWithAlpha,
  p.normalisation = PowderNormalisation::kPrinted;
  const auto table = PigmentTable::named("hematite_o", PowderTau::kTwoThirds);
  for (int i = 0; i < 4; ++i) {
    const float l = wavelengths()[i];
    EXPECT_FLOAT_EQ(f[i], model(p, l, table->albedo(l, 0.12f), 2.0f / 3.0f, kWi, kWo));
  }
}

TEST(PowderNode, RhoOverridesTheMieAlbedo) {
  const SampledSpectrum f = evaluate(R"({"type": "powder", "rho": 0.9})", kWo, kWi);
  const auto table = PigmentTable::named("hematite", PowderTau::kPaper);
  for (int i = 0; i < 4; ++i)
    EXPECT_FLOAT_EQ(
        f[i], model(PowderParams<float>{}, wavelengths()[i], 0.9f, table->tau_o(wavelengths()[i]), kWi, kWo));
}

TEST(PowderNode, TwoGrainPopulationsMix) {
  const std::string json = R"({"nodes": {
      "fine": {"type": "powder", "radius": 0.03}, "coarse": {"type": "powder", "radius": 0.7},
      "out": {"type": "mix", "a": {"link": "fine"}, "b": {"link": "coarse"}, "factor": 0.25}}, "output": "out"})";
  const auto material =
      compile_material(nlohmann::json::parse(json), "m", "scene.json", *std::make_unique<Files>());
  ShadingContext ctx;
  ctx.lambda = &wavelengths();
  LobeArena arena;
  Closure closure;
  material->evaluate(ctx, arena, closure);
  ASSERT_EQ(closure.lobe_count(), 2);
  const SampledSpectrum mixed = closure.eval(kWo, kWi, wavelengths());
  const SampledSpectrum fine = evaluate(R"({"type": "powder", "radius": 0.03})", kWo, kWi);
  const SampledSpectrum coarse = evaluate(R"({"type": "powder", "radius": 0.7})", kWo, kWi);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(mixed[i], 0.75f * fine[i] + 0.25f * coarse[i], 1e-6f * fine[i]);
}

TEST(PowderNode, PigmentFromACsvOfNAndK) {
  const auto dir = scratch_dir();
  std::ofstream(dir / "grain.csv") << "wavelength_nm,n,k\n300,1.6,0.01\n900,1.6,0.01\n";
  const SampledSpectrum f =
      evaluate(R"({"type": "powder", "pigment_file": "grain.csv"})", kWo, kWi, Files(dir));
  for (int i = 0; i < 4; ++i) {
    const float l = wavelengths()[i];
    const float rho = static_cast<float>(grain_albedo(1.6, 0.01, 0.05, l * 1e-3));
    EXPECT_NEAR(f[i], model(PowderParams<float>{}, l, rho, static_cast<float>(powder_tau_o(1.6)), kWi, kWo),
                2e-3f * f[i]);
  }
}

TEST(PowderNode, BadParametersAreNamed) {
  auto message = [](const std::string& json) {
    try {
      evaluate(json, kWo, kWi);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(R"({"type": "powder", "pigment": "malachite"})").find("pigment"), std::string::npos);
  EXPECT_NE(message(R"({"type": "powder", "pigment_file": "missing.csv"})").find("missing.csv"),
            std::string::npos);
  EXPECT_NE(message(R"({"type": "powder", "kappa": -1})").find("kappa"), std::string::npos);
  EXPECT_NE(message(R"({"type": "powder", "g": 1.5})").find("g"), std::string::npos);
  EXPECT_NE(message(R"({"type": "powder", "ladder": "fixed"})").find("ladder"), std::string::npos);
}

}  // namespace
}  // namespace ochre::test::powder_closure_test
