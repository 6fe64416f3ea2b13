// Rendered dry hematite powder (the `powder` material): its spectral radiance under a constant
// environment equals the model's directional albedo per wavelength, the opposition effect appears with the
// light at the camera and matches the model's ratio, and the colour is the red-brown of fine hematite.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cli/cli_runner.h"
#include "cli/render_probe.h"
#include "materials/core/pi.h"
#include "materials/core/vec3d.h"
#include "materials/lobes/powder/pigment_table.h"
#include "materials/lobes/powder/powder_model.h"
#include "materials/numerics/gauss_legendre.h"
#include "renderer/image/exr_reader.h"
#include "spectra/cie.h"
#include "support/test_paths.h"

namespace ochre::test::powder_render_test {
namespace {

PowderWavelength<double> default_hematite(double lambda_nm) {
  const auto table = PigmentTable::named("hematite", PowderTau::kPaper);
  return {lambda_nm * 1e-3, table->albedo(float(lambda_nm), 0.05f), table->tau_o(float(lambda_nm))};
}

// The directional albedo of the default powder seen from wo (all terms, Gauss-Legendre in (sin^2, phi)).
double directional_albedo(double lambda_nm, const Vec3d& wo) {
  const PowderParams<double> p;
  const PowderWavelength<double> w = default_hematite(lambda_nm);
  const GaussLegendreRule us = gauss_legendre_rule(192, 0.0, 1.0),
                          phis = gauss_legendre_rule(192, 0.0, 2 * kPiD);
  double sum = 0.0;
  for (size_t a = 0; a < us.nodes.size(); ++a) {
    const double s = std::sqrt(us.nodes[a]), c = std::sqrt(1.0 - us.nodes[a]);
    for (size_t b = 0; b < phis.nodes.size(); ++b)
      sum += us.weights[a] * phis.weights[b] * 0.5 *
             powder_brdf(p, w, Vec3d(s * std::cos(phis.nodes[b]), s * std::sin(phis.nodes[b]), c), wo);
  }
  return sum;
}

TEST(PowderRender, SpectralRadianceUnderAConstantEnvironmentIsTheDirectionalAlbedo) {
  // Orthographic view at 30 degrees from the normal; the environment's radiance is 1 at every wavelength.
  const double theta = 30.0 * kPiD / 180.0;
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 0.5, "eye": [0, {}, {}], "target": [0, 0, 0], "up": [0, 0, 1]}},
    "film": {{"resolution": [16, 16]}}, "integrator": {{"spp": 1024, "max_depth": 2}},
    "materials": {{"m": {{"type": "powder"}}}},
    "lights": [{{"type": "environment", "radiance": 1}}],
    "shapes": [{{"type": "plane", "size": [20, 20], "material": "m"}}],
    "output": {{"spectral_range": [400, 700]}}}})",
                                             -5 * std::sin(theta), 5 * std::cos(theta)));
  const CommandResult r = run_ochre("render scene.json -o out.exr --spectral-bins 10", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage exr = read_exr(dir / "out.exr");
  const Vec3d wo{0.0, -std::sin(theta), std::cos(theta)};
  for (int bin : {1, 5, 9}) {  // 430-460, 550-580, 670-700 nm
    const double lo = 400.0 + 30.0 * bin, centre = lo + 15.0;
    const std::vector<float>* channel = exr.find_channel(fmt::format("S0.{},000000nm", centre));
    ASSERT_NE(channel, nullptr);
    double sum = 0, sum2 = 0;
    for (float v : *channel) sum += v, sum2 += double(v) * v;
    const double n = double(channel->size()), mean = sum / n;
    const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    double model = 0.0;  // the bin's mean albedo
    for (int k = 0; k < 7; ++k) model += directional_albedo(lo + 5.0 * k, wo) / 7.0;
    std::printf("bin %.0f nm: rendered %.4f +- %.4f, model %.4f\n", centre, mean, se, model);
    EXPECT_NEAR(mean, model, 4.0 * se + 0.01 * model) << centre;
  }
}

// Mean luminance of the centre of the patch with a point light at `light` (camera at `eye`).
double patch_luminance(const std::string& material, const std::string& eye, const std::string& light) {
  return render_luminance(fmt::format(R"({{
    "camera": {{"type": "perspective", "fov": 4, "eye": {}, "target": [0, 0, 0], "up": [0, 0, 1]}},
    "film": {{"resolution": [8, 8]}}, "integrator": {{"spp": 256, "max_depth": 1}},
    "materials": {{"m": {}}},
    "lights": [{{"type": "point", "position": {}, "intensity": 25}}],
    "shapes": [{{"type": "plane", "size": [4, 4], "material": "m"}}]}})",
                                      eye, material, light))
      .mean(0, 0, 8, 8);
}

TEST(PowderRender, OppositionEffectWithTheLightAtTheCamera) {
  // Camera 30 degrees from the normal; the light either at the camera (every pixel sees exact
  // backscatter) or at the same distance and incidence 90 degrees of azimuth away. A Lambert patch is
  // equally bright in both; the powder brighter at backscatter by its enhanced-backscattering peak.
  const std::string eye = "[0, -2.5, 4.330127]", side = "[2.5, 0, 4.330127]";
  const std::string powder = R"({"type": "powder"})", lambert = R"({"type": "lambert", "color": 0.5})";
  const double lambert_ratio = patch_luminance(lambert, eye, eye) / patch_luminance(lambert, eye, side);
  const double powder_ratio = patch_luminance(powder, eye, eye) / patch_luminance(powder, eye, side);
  // The model's ratio of luminances: the BRDF weighted by ybar over the visible range (the point light's
  // intensity is a constant spectrum).
  const Vec3d wo{0, -0.5, 0.8660254}, wi_side{0.5, 0, 0.8660254};
  const PowderParams<double> p;
  double back = 0.0, away = 0.0;
  for (double lambda = 360.0; lambda <= 830.0; lambda += 5.0) {
    const PowderWavelength<double> w = default_hematite(lambda);
    back += cie_y(float(lambda)) * powder_brdf(p, w, wo, wo);
    away += cie_y(float(lambda)) * powder_brdf(p, w, wi_side, wo);
  }
  const double model_ratio = back / away;
  std::printf("opposition effect: powder %.4f (model %.4f), Lambert %.4f\n", powder_ratio, model_ratio,
              lambert_ratio);
  EXPECT_NEAR(lambert_ratio, 1.0, 0.01);
  EXPECT_GT(powder_ratio, 1.15);
  EXPECT_NEAR(powder_ratio, model_ratio, 0.01 * model_ratio);
}

}  // namespace
}  // namespace ochre::test::powder_render_test
