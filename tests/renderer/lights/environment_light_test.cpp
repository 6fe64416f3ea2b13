// EnvironmentLight and EnvironmentMap: the (u, v) convention, chi-square of sample() against pdf(),
// normalisation of pdf() over the sphere, RGB texels as RGBIlluminantSpectrum, scale and rotation, the
// scene JSON factory and its errors, and the shared HDR maps (with the distribution's build time).

#include "renderer/lights/environment_light.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "materials/lobes/sampling_check.h"
#include "renderer/image/exr_writer.h"
#include "renderer/lights/light_type.h"
#include "spectra/color_space.h"
#include "spectra/input_error.h"
#include "spectra/rgb_spectrum.h"
#include "support/test_paths.h"

namespace ochre::environment_light_test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 64, kHeight = 32;

// A dim sky (brighter towards +y) with a 3 x 3 texel sun at the image centre, i.e. along -z.
std::vector<RGB> spot_texels() {
  std::vector<RGB> rgb(kWidth * kHeight);
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      const float sky = 0.05f + 0.2f * (1.0f - static_cast<float>(row) / kHeight);
      const bool sun = std::abs(column - kWidth / 2) <= 1 && std::abs(row - kHeight / 2) <= 1;
      rgb[row * kWidth + column] = sun ? RGB{400.0f, 300.0f, 200.0f} : RGB{sky, sky * 1.1f, sky * 1.3f};
    }
  return rgb;
}

fs::path write_map_exr(const fs::path& path, int width, int height, const std::vector<RGB>& rgb) {
  ExrImage image;
  image.width = width;
  image.height = height;
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    std::vector<float> channel;
    for (const RGB& texel : rgb) channel.push_back(texel[c]);
    image.channels.emplace_back(names[c], std::move(channel));
  }
  write_exr(path, image);
  return path;
}

// The scene's "lights" entry `j` built through the light registry, as the loader builds it.
std::unique_ptr<EnvironmentLight> make_light(const nlohmann::json& j, const fs::path& dir,
                                             float radius = 1.0f) {
  const JsonFields f(j, "scene.json: lights[0]");
  const Camera camera = Camera::perspective(camera_basis_look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}), 40, 8, 8);
  BuiltLight built = LightRegistry::builtin().type_of(f).load(f, dir, camera, Vec3d{}, radius);
  return std::unique_ptr<EnvironmentLight>(dynamic_cast<EnvironmentLight*>(built.light.release()));
}

float luminance(const RGB& rgb) {
  return rgb_to_xyz(rgb, ColorSpace::LinearRec709).y;
}

// Upper tail of the chi-square distribution: Q(dof / 2, chi2 / 2).
double chi2_p_value(double chi2, int dof) {
  return regularized_gamma_q(0.5 * dof, 0.5 * chi2);
}

TEST(EnvironmentMap, DirectionUvConvention) {
  auto near = [](Vec2 a, Vec2 b) { return std::abs(a.x - b.x) < 1e-6f && std::abs(a.y - b.y) < 1e-6f; };
  EXPECT_TRUE(near(direction_to_equirect_uv({0, 0, -1}), {0.5f, 0.5f}));   // centre: -z
  EXPECT_TRUE(near(direction_to_equirect_uv({1, 0, 0}), {0.75f, 0.5f}));   // right of centre: +x
  EXPECT_TRUE(near(direction_to_equirect_uv({-1, 0, 0}), {0.25f, 0.5f}));  // left: -x
  EXPECT_TRUE(near(direction_to_equirect_uv({0, 0, 1}), {0.0f, 0.5f}));    // seam: +z
  EXPECT_NEAR(direction_to_equirect_uv({0, 3, 0}).y, 0.0f, 1e-6f);         // top row: +y
  EXPECT_NEAR(direction_to_equirect_uv({0, -1, 0}).y, 1.0f, 1e-6f);        // bottom row: -y
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i < 1000; ++i) {
    const Vec2 uv{uniform(rng), 0.01f + 0.98f * uniform(rng)};
    const Vec2 back = direction_to_equirect_uv(equirect_uv_to_direction(uv));
    ASSERT_TRUE(near(uv, back) || std::abs(std::abs(uv.x - back.x) - 1.0f) < 1e-5f) << uv.x << " " << uv.y;
  }
}

// Samples binned over a texel-aligned grid of world (u, v) cells; the expected count of a cell is the
// integral of pdf(direction) over it, computed from pdf() at texel centres (exact: pdf is constant
// per texel in (u, v), with dw = 2 pi^2 sin(theta) du dv).
TEST(EnvironmentLight, SampleMatchesPdfChiSquare) {
  const fs::path file = write_map_exr(test::scratch_dir() / "spot.exr", kWidth, kHeight, spot_texels());
  // Rotated by 90 degrees, an integer number of texels, so the grid stays texel-aligned in world space.
  const auto light =
      make_light({{"type", "environment"}, {"file", "spot.exr"}, {"rotation", 90}}, file.parent_path());
  constexpr int kBinsU = 32, kBinsV = 16, kSamples = 400000;
  std::vector<double> expected(kBinsU * kBinsV, 0.0), observed(kBinsU * kBinsV, 0.0);
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      const Vec2 uv{(column + 0.5f) / kWidth, (row + 0.5f) / kHeight};
      const double sin_theta = std::sin(M_PI * uv.y);
      const double p =
          light->pdf(equirect_uv_to_direction(uv)) * 2.0 * M_PI * M_PI * sin_theta / (kWidth * kHeight);
      expected[(row * kBinsV / kHeight) * kBinsU + column * kBinsU / kWidth] += p * kSamples;
    }
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f);
  int pdf_mismatches = 0;
  for (int i = 0; i < kSamples; ++i) {
    const auto s = light->sample({}, {uniform(rng), uniform(rng)}, lambda);
    ASSERT_TRUE(s.has_value());
    ASSERT_NEAR(length(s->wi), 1.0f, 1e-5f);
    if (std::abs(s->pdf - light->pdf(s->wi)) > 1e-3f * s->pdf) ++pdf_mismatches;  // only on texel edges
    const Vec2 uv = direction_to_equirect_uv(s->wi);
    const int bu = std::min(static_cast<int>(uv.x * kBinsU), kBinsU - 1);
    const int bv = std::min(static_cast<int>(uv.y * kBinsV), kBinsV - 1);
    observed[bv * kBinsU + bu] += 1.0;
  }
  EXPECT_LT(pdf_mismatches, kSamples / 1000);
  // Pool the cells expecting fewer than 5 samples into one.
  double chi2 = 0.0, pooled_expected = 0.0, pooled_observed = 0.0, total_expected = 0.0;
  int dof = -1;
  for (size_t i = 0; i < expected.size(); ++i) {
    total_expected += expected[i];
    if (expected[i] < 5.0) {
      pooled_expected += expected[i];
      pooled_observed += observed[i];
      continue;
    }
    chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++dof;
  }
  if (pooled_expected > 0.0) {
    chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++dof;
  }
  EXPECT_NEAR(total_expected, kSamples, 1e-3 * kSamples);
  const double p = chi2_p_value(chi2, dof);
  std::printf("[ chi2 ] environment map: chi2 %.1f, %d dof, p = %.3f, pdf mismatches %d / %d\n", chi2, dof, p,
              pdf_mismatches, kSamples);
  EXPECT_GT(p, 1e-3);
}

// Midpoint rule in (cos theta, phi), where dw = d(cos theta) dphi, on a grid not aligned with texels.
double integrate_pdf_over_sphere(const EnvironmentLight& light) {
  constexpr int kMu = 999, kPhi = 1999;
  double sum = 0.0;
  for (int i = 0; i < kMu; ++i) {
    const double mu = -1.0 + 2.0 * (i + 0.5) / kMu;
    const double s = std::sqrt(1.0 - mu * mu);
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2.0 * M_PI * (j + 0.5) / kPhi;
      sum += light.pdf(Vec3(static_cast<float>(s * std::cos(phi)), static_cast<float>(mu),
                            static_cast<float>(s * std::sin(phi))));
    }
  }
  return sum * (2.0 / kMu) * (2.0 * M_PI / kPhi);
}

TEST(EnvironmentLight, PdfIntegratesToOneOverTheSphere) {
  const EnvironmentLight light(std::make_shared<const EnvironmentMap>(kWidth, kHeight, spot_texels()), 1.0f,
                               1.0f, 30.0f);
  const double integral = integrate_pdf_over_sphere(light);
  std::printf("[ pdf ] integral over the sphere: %.5f\n", integral);
  EXPECT_NEAR(integral, 1.0, 5e-3);
}

// The combined lookup an escaping ray uses gives the radiance and the pdf of the separate queries.
TEST(EnvironmentLight, CombinedRadianceAndPdfMatchTheSeparateQueries) {
  const EnvironmentLight light(std::make_shared<const EnvironmentMap>(kWidth, kHeight, spot_texels()), 1.0f,
                               1.0f, 30.0f);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 d = normalize(Vec3{uniform(rng), uniform(rng), uniform(rng)});
    float pdf = -1.0f;
    const SampledSpectrum both = light.radiance(d, lambda, &pdf);
    const SampledSpectrum alone = light.radiance(d, lambda);
    EXPECT_FLOAT_EQ(pdf, light.pdf(d));
    for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_FLOAT_EQ(both[k], alone[k]);
  }
}

// The texel spectra are stored by block-major key: on a map whose size is not a multiple of the block
// (30 x 14, every texel a different colour), the radiance along a texel's centre is that texel's
// RGBIlluminantSpectrum and the pdf is the distribution's density of that texel over 2 pi^2 sin(theta); a
// sample carries the radiance of the texel it reports.
TEST(EnvironmentLight, TexelKeysFindEachTexelsSpectrumAndPdf) {
  constexpr int kW = 30, kH = 14;
  std::vector<RGB> rgb(kW * kH);
  for (int row = 0; row < kH; ++row)
    for (int column = 0; column < kW; ++column)
      rgb[row * kW + column] = {0.1f + 0.03f * column, 0.2f + 0.05f * row, 0.05f + 0.01f * (column + row)};
  const auto map = std::make_shared<const EnvironmentMap>(kW, kH, rgb);
  const EnvironmentLight light(map, 1.0f);
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.4f);
  for (int row = 0; row < kH; ++row)
    for (int column = 0; column < kW; ++column) {
      const Vec2 uv{(column + 0.5f) / kW, (row + 0.5f) / kH};
      const Vec3 d = equirect_uv_to_direction(uv);
      const SampledSpectrum expected = RGBIlluminantSpectrum(rgb[row * kW + column]).sample(lambda);
      float pdf = -1.0f;
      const SampledSpectrum l = light.radiance(d, lambda, &pdf);
      for (int k = 0; k < kSpectrumSamples; ++k)
        ASSERT_NEAR(l[k], expected[k], 1e-5f * expected[k]) << column << "," << row;
      const float expected_pdf =
          map->distribution().pdf(column, row) / (2.0f * kPi * kPi * std::sin(kPi * uv.y));
      ASSERT_NEAR(pdf, expected_pdf, 1e-5f * expected_pdf) << column << "," << row;
      ASSERT_EQ(map->texel_key(d), map->texel_key(column, row));
      ASSERT_EQ(map->texel_index(d), static_cast<size_t>(row * kW + column));
    }
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const EnvironmentMap::Sample m = map->sample({uniform(rng), uniform(rng)});
    const int column = static_cast<int>(m.index % kW), row = static_cast<int>(m.index / kW);
    ASSERT_EQ(m.key, map->texel_key(column, row));
    const auto s = light.sample({}, {uniform(rng), uniform(rng)}, lambda);
    ASSERT_TRUE(s.has_value());
    const SampledSpectrum along = light.radiance(s->wi, lambda);
    // Away from texel edges (where float rounding of the direction may pick the neighbour) they agree.
    const Vec2 uv = direction_to_equirect_uv(s->wi);
    const float fx = uv.x * kW - std::floor(uv.x * kW), fy = uv.y * kH - std::floor(uv.y * kH);
    if (fx < 1e-3f || fx > 1.0f - 1e-3f || fy < 1e-3f || fy > 1.0f - 1e-3f) continue;
    for (int k = 0; k < kSpectrumSamples; ++k) ASSERT_FLOAT_EQ(s->radiance[k], along[k]);
  }
}

// Importance sampling must be unbiased: E[Y(L) / pdf] = integral of Y(L) over the sphere = 4 pi mean Y.
void expect_unbiased(const EnvironmentMap& map, int samples, double tolerance) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  double sum = 0.0;
  for (int i = 0; i < samples; ++i) {
    const EnvironmentMap::Sample s = map.sample({uniform(rng), uniform(rng)});
    if (s.pdf > 0.0f) sum += luminance(map.texel(s.index)) / s.pdf;
  }
  const double estimate = sum / samples, exact = 4.0 * M_PI * map.mean_luminance();
  std::printf("[ unbiased ] integral of Y: estimate %.5g, exact %.5g\n", estimate, exact);
  EXPECT_NEAR(estimate / exact, 1.0, tolerance);
}

TEST(EnvironmentMap, ImportanceSamplingIsUnbiased) {
  expect_unbiased(EnvironmentMap(kWidth, kHeight, spot_texels()), 200000, 0.01);
}

TEST(EnvironmentLight, ConstantMapEqualsConstantEnvironment) {
  for (const RGB rgb : {RGB{1.0f, 1.0f, 1.0f}, RGB{0.3f, 0.6f, 0.2f}, RGB{5.0f, 0.5f, 2.0f}}) {
    const EnvironmentLight constant(std::make_shared<RGBIlluminantSpectrum>(rgb), 2.0f);
    const EnvironmentLight map(std::make_shared<const EnvironmentMap>(8, 4, std::vector<RGB>(32, rgb)), 2.0f);
    for (float u : {0.1f, 0.45f, 0.8f}) {
      const SampledWavelengths lambda = SampledWavelengths::sample_visible(u);
      for (const Vec3 d : {Vec3(0, 1, 0), Vec3(0.3f, -0.2f, 0.9f), Vec3(-1, 0, 0)}) {
        const SampledSpectrum a = constant.radiance(d, lambda), b = map.radiance(d, lambda);
        for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(b[i], a[i], 1e-6f * a[i]) << lambda[i];
      }
    }
    EXPECT_NEAR(map.power(), constant.power(), 2e-3 * constant.power());
  }
  // RGB (1,1,1) is D65 at luminance 1: power = 4 pi^2 r^2.
  const EnvironmentLight white(std::make_shared<const EnvironmentMap>(8, 4, std::vector<RGB>(32, {1, 1, 1})),
                               2.0f);
  EXPECT_NEAR(white.power(), 4.0 * M_PI * M_PI * 4.0, 1e-3 * white.power());
}

TEST(EnvironmentLight, ScaleMultipliesRadianceAndPower) {
  const fs::path file = write_map_exr(test::scratch_dir() / "spot.exr", kWidth, kHeight, spot_texels());
  const auto one = make_light({{"type", "environment"}, {"file", "spot.exr"}}, file.parent_path());
  const auto three =
      make_light({{"type", "environment"}, {"file", "spot.exr"}, {"scale", 3}}, file.parent_path());
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.6f);
  for (const Vec3 d : {Vec3(0, 0, -1), Vec3(0.5f, 0.5f, 0.1f)}) {
    const SampledSpectrum a = one->radiance(d, lambda), b = three->radiance(d, lambda);
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(b[i], 3.0f * a[i], 1e-5f * b[i]);
    EXPECT_EQ(one->pdf(d), three->pdf(d));
  }
  EXPECT_NEAR(three->power(), 3.0f * one->power(), 1e-5f * three->power());
  const auto constant =
      make_light({{"type", "environment"}, {"radiance", 2.0}, {"scale", 0.5}}, file.parent_path());
  EXPECT_NEAR(constant->radiance({0, 1, 0}, lambda)[0], 1.0f, 1e-6f);
}

TEST(EnvironmentLight, RotationTurnsTheMapAboutY) {
  const fs::path file = write_map_exr(test::scratch_dir() / "spot.exr", kWidth, kHeight, spot_texels());
  const auto still = make_light({{"type", "environment"}, {"file", "spot.exr"}}, file.parent_path());
  const auto turned =
      make_light({{"type", "environment"}, {"file", "spot.exr"}, {"rotation", 90}}, file.parent_path());
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.5f);
  // The sun is along -z in the map; +90 degrees about +y (right-handed) carries -z to -x.
  EXPECT_GT(still->radiance({0, 0, -1}, lambda)[0], 100.0f);
  EXPECT_LT(still->radiance({-1, 0, 0}, lambda)[0], 1.0f);
  EXPECT_GT(turned->radiance({-1, 0, 0}, lambda)[0], 100.0f);
  EXPECT_LT(turned->radiance({0, 0, -1}, lambda)[0], 1.0f);
  EXPECT_EQ(turned->pdf({-1, 0, 0}), still->pdf({0, 0, -1}));
  // Sampling follows: the mean sampled direction points at the sun.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  Vec3 mean;
  for (int i = 0; i < 20000; ++i) mean += turned->sample({}, {uniform(rng), uniform(rng)}, lambda)->wi;
  mean = normalize(mean);
  EXPECT_GT(dot(mean, Vec3(-1, 0, 0)), 0.95f) << mean.x << " " << mean.y << " " << mean.z;
  // Power does not depend on the rotation.
  EXPECT_NEAR(turned->power(), still->power(), 1e-6f * still->power());
}

void expect_input_error(const nlohmann::json& j, const fs::path& dir,
                        const std::vector<std::string>& needles) {
  try {
    make_light(j, dir);
    ADD_FAILURE() << "no error for " << j.dump();
  } catch (const InputError& e) {
    for (const std::string& needle : needles)
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what() << " lacks " << needle;
  }
}

TEST(EnvironmentLight, FactoryErrorsNameTheFileAndTheField) {
  const fs::path dir = test::scratch_dir();
  write_map_exr(dir / "spot.exr", kWidth, kHeight, spot_texels());
  std::ofstream(dir / "broken.hdr") << "not an image";
  expect_input_error({{"type", "environment"}}, dir, {"scene.json: lights[0]", "radiance", "file"});
  expect_input_error({{"type", "environment"}, {"radiance", 1}, {"file", "spot.exr"}}, dir, {"exactly one"});
  expect_input_error({{"type", "environment"}, {"file", "spot.exr"}, {"rotaton", 3}}, dir,
                     {"lights[0].rotaton", "unknown parameter"});
  expect_input_error({{"type", "environment"}, {"file", "spot.exr"}, {"scale", -1}}, dir,
                     {"lights[0].scale"});
  expect_input_error({{"type", "environment"}, {"file", "missing.hdr"}}, dir,
                     {"lights[0].file", "missing.hdr"});
  expect_input_error({{"type", "environment"}, {"file", "broken.hdr"}}, dir,
                     {"lights[0].file", "broken.hdr"});
  std::vector<RGB> nan_texels = spot_texels();
  nan_texels[5].g = NAN;
  write_map_exr(dir / "nan.exr", kWidth, kHeight, nan_texels);
  expect_input_error({{"type", "environment"}, {"file", "nan.exr"}}, dir,
                     {"lights[0].file", "nan.exr", "row 0"});
}

// The shared HDR maps: finite positive power, sample() consistent with pdf(), unbiased, and the time
// to build the sampling distribution.
void check_shared_map(const std::string& name) {
  const fs::path path = test::shared_dir() / "assets/envmaps" / name;
  const auto light =
      make_light({{"type", "environment"}, {"file", name}, {"rotation", 37}}, path.parent_path(), 5.0f);
  const EnvironmentMap& map = *light->map();
  EXPECT_TRUE(std::isfinite(light->power()));
  EXPECT_GT(light->power(), 0.0f);

  std::vector<RGB> texels;
  for (int row = 0; row < map.height(); ++row)
    for (int column = 0; column < map.width(); ++column) texels.push_back(map.texel(column, row));
  const auto start = std::chrono::steady_clock::now();
  const EnvironmentMap rebuilt(map.width(), map.height(), std::move(texels));
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ build ] %s: %d x %d, distribution built in %.1f ms, power %.4g\n", name.c_str(), map.width(),
              map.height(), ms, light->power());

  std::mt19937 rng(17);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.2f);
  int mismatches = 0;
  constexpr int kSamples = 100000;
  for (int i = 0; i < kSamples; ++i) {
    const auto s = light->sample({}, {uniform(rng), uniform(rng)}, lambda);
    if (!s) continue;
    ASSERT_GT(s->pdf, 0.0f);
    const SampledSpectrum l = light->radiance(s->wi, lambda);
    if (std::abs(s->pdf - light->pdf(s->wi)) > 1e-3f * s->pdf ||
        std::abs(l[0] - s->radiance[0]) > 1e-4f * l[0])
      ++mismatches;
  }
  EXPECT_LT(mismatches, kSamples / 500) << name;
  EXPECT_NEAR(integrate_pdf_over_sphere(*light), 1.0, 1e-2) << name;
  expect_unbiased(map, 400000, 0.02);
}

TEST(EnvironmentLight, SharedQuarryHdr) {
  OCHRE_REQUIRE_SHARED();
  check_shared_map("quarry_01_1k.hdr");
}

TEST(EnvironmentLight, SharedMuseumExr) {
  OCHRE_REQUIRE_SHARED();
  check_shared_map("museum.exr");
}

}  // namespace
}  // namespace ochre::environment_light_test
