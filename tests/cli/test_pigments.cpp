// Colour sanity of the pigment library (scenes/pigments/, docs/materials/pigments.md): each pigment, a flat
// patch seen along its normal under a uniform D65 sky of luminance 1 (scenes/pigments/swatches.json), has
// the CIELAB colour of its family: red pigments hue 0-60 degrees, yellow 60-100, blacks low L*, coarse
// hematite purple (hue 300-360 or 0-20, low chroma), the pale extenders light and weakly coloured. The
// measured table is printed (docs/materials/pigments.md lists it).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "renderer/ciede2000.h"
#include "renderer/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test {
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
  const CommandResult r = run_ochre(
      fmt::format("render '{}' -o swatches.exr -q --spp 32 --resolution {}x{}", scene.string(), width, patch),
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

}  // namespace
}  // namespace ochre::test
