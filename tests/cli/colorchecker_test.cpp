// The colour-checker validation (docs/cameras.md, "Colour checker"): the 24 ColorChecker patches rendered as
// flat Lambertian patches under a uniform D65 sky and under the torch preset's 1700 K blackbody, through the
// CIE 1931 observer and through each measured camera (white-balanced to D65 by ochre's fit), against an
// independent numpy computation of the same integrals (tools/data/colorchecker_reference.py, whose output is
// tests/data/colorchecker_reference.csv). Goal: Delta E00 < 0.5 for every patch.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/cli_runner.h"
#include "renderer/image/exr_reader.h"
#include "spectra/blackbody_spectrum.h"
#include "spectra/cie.h"
#include "spectra/ciede2000.h"
#include "spectra/color_space.h"
#include "spectra/white_balance.h"
#include "support/test_paths.h"

namespace ochre::test::colorchecker_test {
namespace {

constexpr int kPatchPixels = 16;  // each patch is 16 x 16 pixels; the inner 12 x 12 are averaged

struct Case {
  const char* illuminant;  // reference CSV name
  const char* radiance;    // the environment's spectrum (luminance 1)
  const char* sensor;
};

// reference[illuminant/sensor/patch] = Lab
std::map<std::string, Lab> read_reference(const std::filesystem::path& csv) {
  std::map<std::string, Lab> ref;
  std::ifstream in(csv);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("illuminant,", 0) == 0) continue;
    std::stringstream s(line);
    std::string ill, sensor, patch, L, a, b;
    std::getline(s, ill, ',');
    std::getline(s, sensor, ',');
    std::getline(s, patch, ',');
    std::getline(s, L, ',');
    std::getline(s, a, ',');
    std::getline(s, b, ',');
    ref[ill + "/" + sensor + "/" + patch] = {std::stod(L), std::stod(a), std::stod(b)};
  }
  return ref;
}

std::string checker_scene(const Case& c, int spp) {
  nlohmann::json scene;
  scene["camera"] = {{"type", "orthographic"}, {"size", 4}, {"eye", {0, 0, 5}}, {"target", {0, 0, 0}}};
  if (std::string(c.sensor) != "cie1931")
    scene["camera"]["sensor"] = {{"name", c.sensor}, {"white_balance", nlohmann::json::parse(c.radiance)}};
  scene["film"] = {{"resolution", {6 * kPatchPixels, 4 * kPatchPixels}}};
  scene["integrator"] = {{"spp", spp}, {"max_depth", 1}};
  scene["lights"] = {{{"type", "environment"}, {"radiance", nlohmann::json::parse(c.radiance)}}};
  const std::string csv = (source_dir() / "spectra/data/colorchecker_babelcolor_10nm.csv").string();
  const auto& names = colorchecker_patch_names();
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string name(names[i]);
    scene["materials"][name] = {{"type", "lambert"}, {"color", {{"file", csv}, {"column", name}}}};
    const double x = static_cast<double>(i % 6) - 2.5, y = 1.5 - static_cast<double>(i / 6);
    scene["shapes"].push_back({{"type", "plane"},
                               {"size", {1, 1}},
                               {"material", name},
                               {"transform", {{{"translate", {x, y, 0}}}}}});
  }
  return scene.dump();
}

// Mean linear Rec.709 of the inner pixels of patch i, as XYZ.
XyzD patch_xyz(const ExrImage& image, size_t i) {
  const int px = static_cast<int>(i % 6) * kPatchPixels, py = static_cast<int>(i / 6) * kPatchPixels;
  double sum[3] = {0, 0, 0};
  int n = 0;
  const char* channels[3] = {"R", "G", "B"};
  for (int y = py + 2; y < py + kPatchPixels - 2; ++y)
    for (int x = px + 2; x < px + kPatchPixels - 2; ++x, ++n)
      for (int c = 0; c < 3; ++c)
        sum[c] += (*image.find_channel(channels[c]))[static_cast<size_t>(y) * image.width + x];
  const XYZ xyz = rgb_to_xyz(
      {static_cast<float>(sum[0] / n), static_cast<float>(sum[1] / n), static_cast<float>(sum[2] / n)},
      ColorSpace::LinearRec709);
  return {xyz.x, xyz.y, xyz.z};
}

// The white the Lab values are relative to: the illuminant's (observer) or D65 (white-balanced cameras).
XyzD lab_white(const Case& c) {
  SpectrumPtr white = d65();
  if (std::string(c.sensor) == "cie1931" && std::string(c.illuminant) == "torch")
    white = normalized_to_unit_luminance(std::make_shared<BlackbodySpectrum>(1700.0f));
  const XYZ w = spectrum_to_xyz(*white);
  return {w.x, w.y, w.z};
}

// Renders one case and returns the largest Delta E00 against the reference (and prints every patch's).
double max_delta_e(const Case& c, const std::map<std::string, Lab>& reference, int spp, double* mean) {
  const auto dir = scratch_dir();
  write_text(dir / "checker.json", checker_scene(c, spp));
  const CommandResult r = run_ochre("render checker.json -o checker.exr -q", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const ExrImage image = read_exr(dir / "checker.exr");
  const XyzD white = lab_white(c);
  double worst = 0.0, total = 0.0;
  std::string line = fmt::format("{:6} {:17}", c.illuminant, c.sensor);
  const auto& names = colorchecker_patch_names();
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string key = fmt::format("{}/{}/{}", c.illuminant, c.sensor, names[i]);
    const auto ref = reference.find(key);
    EXPECT_NE(ref, reference.end()) << key;
    if (ref == reference.end()) continue;
    const double de = ciede2000(xyz_to_lab(patch_xyz(image, i), white), ref->second);
    worst = std::max(worst, de);
    total += de;
    line += fmt::format(" {:.2f}", de);
  }
  *mean = total / static_cast<double>(names.size());
  std::cout << line << fmt::format("  mean {:.3f} max {:.3f}\n", *mean, worst);
  return worst;
}

const Case kCases[] = {
    {"D65", R"({"name": "D65"})", "cie1931"},
    {"torch", R"({"blackbody": 1700})", "cie1931"},
    {"D65", R"({"name": "D65"})", "canon_5d_mark_ii"},
    {"torch", R"({"blackbody": 1700})", "canon_5d_mark_ii"},
    {"D65", R"({"name": "D65"})", "nokia_n900"},
    {"torch", R"({"blackbody": 1700})", "nokia_n900"},
};

TEST(ColorChecker, RenderedPatchesMatchTheIndependentIntegrals) {
  const auto reference = read_reference(source_dir() / "tests/data/colorchecker_reference.csv");
  ASSERT_EQ(reference.size(), 6u * 24u);
  for (const Case& c : kCases) {
    double mean = 0.0;
    EXPECT_LT(max_delta_e(c, reference, 64, &mean), 0.5) << c.illuminant << " " << c.sensor;
  }
}

// The shipped reference is what tools/data/colorchecker_reference.py computes from spectra/data (when the
// system Python has numpy).
TEST(ColorChecker, ReferenceIsUpToDate) {
  if (std::system("/usr/bin/python3 -c 'import numpy' > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "no /usr/bin/python3 with numpy";
  const auto dir = scratch_dir();
  const std::string command =
      fmt::format("cd '{}' && /usr/bin/python3 tools/data/colorchecker_reference.py spectra/data '{}'",
                  source_dir().string(), (dir / "reference.csv").string());
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const auto fresh = read_reference(dir / "reference.csv");
  const auto shipped = read_reference(source_dir() / "tests/data/colorchecker_reference.csv");
  ASSERT_EQ(fresh.size(), shipped.size());
  for (const auto& [key, lab] : fresh) {
    EXPECT_NEAR(lab.L, shipped.at(key).L, 1e-4) << key;
    EXPECT_NEAR(lab.a, shipped.at(key).a, 1e-4) << key;
    EXPECT_NEAR(lab.b, shipped.at(key).b, 1e-4) << key;
  }
}

}  // namespace
}  // namespace ochre::test::colorchecker_test
