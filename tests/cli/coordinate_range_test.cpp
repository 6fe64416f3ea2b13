// An image does not depend on where the scene sits (docs/scene-format.md, "Coordinate range"): the Cornell
// box translated far from the origin, with its camera, renders as at the origin. Georeferenced scans come in
// coordinates such as UTM metres (offsets of 5e5 and 5e6 around a panel of a few metres); before the scene
// was rendered relative to its camera, the box rendered 9 % dark at an offset of 1e5 and 28 % at 1e6.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "cli/file_test_support.h"
#include "cli/render_probe.h"
#include "renderer/json/json_file.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::coordinate_range_test {
namespace {

// The Cornell box (millimetres) with every position moved by `offset`: the camera's eye and target, and a
// translation on every shape; 32x32 pixels at 16 samples.
std::string translated_box(double x, double y, double z) {
  const auto dir = source_dir() / "scenes/cornell-box";
  nlohmann::json scene = read_json_file(dir / "cornell-box.json", "scene file");
  scene.erase("output");
  scene["film"]["resolution"] = {32, 32};
  scene["integrator"]["spp"] = 16;
  for (const char* key : {"eye", "target"}) {
    nlohmann::json& p = scene["camera"][key];
    p = {p[0].get<double>() + x, p[1].get<double>() + y, p[2].get<double>() + z};
  }
  for (auto& shape : scene["shapes"]) {
    shape["file"] = (dir / shape["file"].get<std::string>()).string();
    shape["transform"] = {{"translate", {x, y, z}}};
  }
  for (auto& [name, material] : scene["materials"].items()) {
    // Spectrum files, at any depth of the material.
    std::function<void(nlohmann::json&)> absolute = [&](nlohmann::json& value) {
      if (value.is_object()) {
        if (value.contains("file")) value["file"] = (dir / value["file"].get<std::string>()).string();
        for (auto& [key, member] : value.items()) absolute(member);
      }
    };
    absolute(material);
  }
  return scene.dump();
}

TEST(CoordinateRange, TheCornellBoxFarFromTheOriginRendersAsAtTheOrigin) {
  const LuminanceImage origin = render_luminance(translated_box(0, 0, 0));
  ASSERT_EQ(origin.width, 32);
  const double mean_origin = origin.mean(0, 0, 32, 32);
  // The audit's offsets, a UTM-like one, and one near the limit of the coordinate range a float can index.
  for (const auto& offset :
       {std::array<double, 3>{1e5, 0.98e5, 0.3e5}, std::array<double, 3>{1e6, 1e6, 1e6},
        std::array<double, 3>{512345.678, 5012345.678, 312.5}, std::array<double, 3>{-3e7, 2e7, 1e7}}) {
    const LuminanceImage far = render_luminance(translated_box(offset[0], offset[1], offset[2]));
    ASSERT_EQ(far.width, 32);
    double worst = 0.0;
    for (size_t i = 0; i < far.y.size(); ++i)
      worst = std::max(worst, std::fabs(far.y[i] - origin.y[i]) / std::max(origin.y[i], 1e-3));
    const double mean = far.mean(0, 0, 32, 32);
    std::printf("offset (%g, %g, %g): mean %.7f against %.7f at the origin (%+.1e), worst pixel %.1e\n",
                offset[0], offset[1], offset[2], mean, mean_origin, mean / mean_origin - 1.0, worst);
    EXPECT_NEAR(mean / mean_origin, 1.0, 1e-4);
    EXPECT_LT(worst, 1e-3);
  }
}

// A grid of quads 0.02 apart written in an OBJ at `offset`: its coordinates in the file itself.
void write_grid_obj(const std::filesystem::path& path, double offset) {
  std::string text;
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 10; ++i)
      text += fmt::format("v {:.6f} {:.6f} 0\n", offset + 0.02 * i, offset + 0.02 * j);
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i) {
      const int a = 1 + j * 11 + i;
      text += fmt::format("f {} {} {} {}\n", a, a + 1, a + 12, a + 11);
    }
  write_text(path, text);
}

// A mesh file whose own coordinates are too large for its detail in single precision (a scan exported in
// UTM metres without a local shift) loads with a warning that gives the numbers; the same mesh near the
// origin, placed by a transform, loads without one.
TEST(CoordinateRange, AMeshFileTooFarFromItsOriginForItsDetailIsNamed) {
  const auto dir = scratch_dir();
  write_grid_obj(dir / "utm.obj", 5e6);
  write_grid_obj(dir / "local.obj", 0.0);
  const std::string camera =
      R"("camera": {"type": "orthographic", "size": 0.5, "eye": [5000000.1, 5000000.1, 5], "target": [5000000.1, 5000000.1, 0]},
    "film": {"resolution": [8, 8]}, "integrator": {"spp": 1},
    "materials": {"m": {"type": "lambert"}}, "lights": [{"type": "environment", "radiance": 1}],)";
  write_text(dir / "utm.json",
             "{" + camera + R"("shapes": [{"type": "mesh", "file": "utm.obj", "material": "m"}]})");
  write_text(dir / "local.json",
             "{" + camera + R"("shapes": [{"type": "mesh", "file": "local.obj", "material": "m",
    "transform": {"translate": [5000000, 5000000, 0]}}]})");
  const CommandResult utm = run_ochre("render utm.json -o utm.exr -q", dir);
  ASSERT_EQ(utm.exit_code, 0) << utm.output;
  EXPECT_TRUE(contains(utm.output, "ochre: warning:")) << utm.output;
  EXPECT_TRUE(contains(utm.output, "utm.obj: single precision cannot hold this mesh's detail")) << utm.output;
  EXPECT_TRUE(contains(
      utm.output, "its coordinates reach 5e+06 in the file, where single-precision numbers are 0.5 apart"))
      << utm.output;
  const CommandResult local = run_ochre("render local.json -o local.exr -q", dir);
  ASSERT_EQ(local.exit_code, 0) << local.output;
  EXPECT_FALSE(contains(local.output, "warning")) << local.output;
}

}  // namespace
}  // namespace ochre::test::coordinate_range_test
