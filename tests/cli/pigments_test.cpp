// Colour sanity of the pigment library (scenes/pigments/, docs/materials/pigments.md): each pigment, a flat
// patch seen along its normal under a uniform D65 sky of luminance 1 (scenes/pigments/swatches.json), has
// the CIELAB colour of its family: red pigments hue 0-60 degrees, yellow 60-100, blacks low L*, coarse
// hematite purple (hue 300-360 or 0-20, low chroma), the pale extenders light and weakly coloured; and in
// the near infrared the iron oxides turn light while charcoal stays black. The measured tables are printed
// (docs/materials/pigments.md lists them).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

#include "cli/cli_runner.h"
#include "renderer/image/exr_reader.h"
#include "spectra/ciede2000.h"
#include "support/test_paths.h"

namespace ochre::test::pigments_test {
namespace {

namespace fs = std::filesystem;

struct Measured {
  double L, a, b, hue, chroma;
};

using Family = std::function<bool(const Measured&)>;

bool hue_in(const Measured& m, double lo, double hi) {
  return m.hue >= lo && m.hue <= hi;
}

// The expected family of every library pigment, by its shape name in swatches.json.
const std::map<std::string, std::pair<const char*, Family>>& families() {
  static const std::map<std::string, std::pair<const char*, Family>> f = {
      {"hematite_fine",
       {"red: hue 0-60, C* > 10", [](const Measured& m) { return hue_in(m, 0, 60) && m.chroma > 10; }}},
      {"hematite_coarse",
       {"purple: hue 300-360 or 0-20, C* > 5",
        [](const Measured& m) { return (hue_in(m, 300, 360) || hue_in(m, 0, 20)) && m.chroma > 5; }}},
      {"red_ochre",
       {"red: hue 0-60, C* > 10", [](const Measured& m) { return hue_in(m, 0, 60) && m.chroma > 10; }}},
      {"yellow_ochre",
       {"yellow: hue 60-100, C* > 30",
        [](const Measured& m) { return hue_in(m, 60, 100) && m.chroma > 30; }}},
      {"charcoal", {"black: L* < 30, C* < 3", [](const Measured& m) { return m.L < 30 && m.chroma < 3; }}},
      {"clay", {"pale: L* > 70, C* < 20", [](const Measured& m) { return m.L > 70 && m.chroma < 20; }}},
      {"limestone", {"pale: L* > 70, C* < 15", [](const Measured& m) { return m.L > 70 && m.chroma < 15; }}}};
  return f;
}

TEST(Pigments, EveryLibraryPigmentHasTheHueOfItsFamilyUnderD65) {
  const fs::path scene = source_dir() / "scenes/pigments/swatches.json";
  std::ifstream in(scene);
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, true, true);
  const nlohmann::json& shapes = json.at("shapes");
  const fs::path dir = scratch_dir();
  const int patch = 32, width = patch * static_cast<int>(shapes.size());
  const CommandResult r =
      run_ochre(fmt::format("render '{}' -o swatches.exr --png swatches.png -q --spp 32 --resolution {}x{}",
                            scene.string(), width, patch),
                dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage image = read_exr(dir / "swatches.exr");
  const std::vector<float>&R = *image.find_channel("R"), &G = *image.find_channel("G"),
        &B = *image.find_channel("B");
  std::cout << "pigment          L*     a*     b*    hue     C*   family\n";
  for (size_t k = 0; k < shapes.size(); ++k) {
    const std::string name = shapes[k].at("name").get<std::string>();
    ASSERT_TRUE(families().count(name)) << name << ": a library pigment without an expected colour family";
    double r = 0, g = 0, b = 0;
    int n = 0;
    for (int y = patch / 4; y < 3 * patch / 4; ++y)  // the patch's centre
      for (int x = int(k) * patch + patch / 4; x < int(k + 1) * patch - patch / 4; ++x, ++n) {
        const size_t i = size_t(y) * width + x;
        r += R[i];
        g += G[i];
        b += B[i];
      }
    const Lab lab = xyz_to_lab(linear_srgb_to_xyz(r / n, g / n, b / n), srgb_d65_white());
    double hue = std::atan2(lab.b, lab.a) * 180.0 / M_PI;
    if (hue < 0) hue += 360.0;
    const Measured m{lab.L, lab.a, lab.b, hue, std::hypot(lab.a, lab.b)};
    const auto& [description, family] = families().at(name);
    std::cout << fmt::format("{:<15} {:5.1f} {:6.1f} {:6.1f} {:6.1f} {:6.1f}   {}\n", name, m.L, m.a, m.b,
                             m.hue, m.chroma, description);
    EXPECT_TRUE(family(m)) << name << " is not " << description
                           << fmt::format(": L* {:.1f}, hue {:.1f}, C* {:.1f}", m.L, m.hue, m.chroma);
  }
}

// Infrared documentation photography (docs/materials/pigments.md#beyond-the-visible): through the
// ir720_model sensor, in a 5500 K sky (the camera flash's spectrum), every patch's response relative to a
// white patch is its reflectance averaged over 720-1000 nm. The iron oxides absorb little there: fine
// hematite reflects half as much as the limestone (under D65 less than a third), the others come close to
// it; charcoal stays black. The measured table is printed.
TEST(Pigments, InTheInfraredIronOxidesTurnLightAndCharcoalStaysDark) {
  const std::vector<std::string> names = {
      "hematite_fine", "hematite_coarse", "red_ochre", "yellow_ochre", "charcoal", "clay", "limestone"};
  std::string includes, shapes;
  for (size_t k = 0; k < names.size(); ++k) {
    includes += fmt::format("\"{}\", ", (source_dir() / "scenes/pigments" / (names[k] + ".json")).string());
    shapes += fmt::format(
        R"({{"type": "plane", "size": [2, 2], "material": "{}", "transform": [{{"translate": [{}, 0, 0]}}]}},)",
        names[k], 2 * k + 1);
  }
  const fs::path dir = scratch_dir();
  write_text(dir / "infrared.json", fmt::format(R"({{"include": [{}],
      "camera": {{"type": "orthographic", "size": 2, "eye": [8, 0, 5], "target": [8, 0, 0], "sensor": "ir720_model"}},
      "film": {{"resolution": [256, 32]}}, "integrator": {{"max_depth": 1}},
      "materials": {{"white": {{"type": "lambert", "color": 1}}}},
      "lights": [{{"type": "environment", "radiance": {{"blackbody": 5500}}}}],
      "shapes": [{} {{"type": "plane", "size": [2, 2], "material": "white", "transform": [{{"translate": [15, 0, 0]}}]}}]}})",
                                                includes.substr(0, includes.size() - 2), shapes));
  const CommandResult r = run_ochre("render infrared.json -o ir.exr --png ir.png -q --spp 64", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage image = read_exr(dir / "ir.exr");
  const int patch = 32, width = 256;
  auto patch_mean = [&](size_t k) {
    double sum = 0;
    int n = 0;
    for (const char* c : {"R", "G", "B"}) {
      const std::vector<float>& v = *image.find_channel(c);
      for (int y = patch / 4; y < 3 * patch / 4; ++y)
        for (int x = int(k) * patch + patch / 4; x < int(k + 1) * patch - patch / 4; ++x, ++n)
          sum += v[size_t(y) * width + x];
    }
    return sum / n;
  };
  const double white = patch_mean(names.size());
  ASSERT_GT(white, 0.0);
  std::map<std::string, double> reflectance;
  std::cout << "pigment          infrared reflectance (ir720_model, 5500 K)\n";
  for (size_t k = 0; k < names.size(); ++k) {
    reflectance[names[k]] = patch_mean(k) / white;
    std::cout << fmt::format("{:<15} {:6.3f}\n", names[k], reflectance[names[k]]);
  }
  for (const char* iron_oxide : {"hematite_fine", "hematite_coarse", "red_ochre", "yellow_ochre"})
    EXPECT_GT(reflectance[iron_oxide], 0.45 * reflectance["limestone"]) << iron_oxide;
  EXPECT_NEAR(reflectance["charcoal"], 0.04, 0.01);  // flat 4 % at every wavelength
  EXPECT_LT(reflectance["charcoal"], 0.1 * reflectance["limestone"]);
}

}  // namespace
}  // namespace ochre::test::pigments_test
