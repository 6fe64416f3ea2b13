// Physics of whole renders through the CLI: white furnace, analytic direct lighting.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "cli/cli_runner.h"
#include "cli/render_probe.h"
#include "renderer/image/exr_reader.h"
#include "renderer/image/exr_writer.h"
#include "support/test_paths.h"

namespace ochre::test::render_physics_test {
namespace {

// One Lambert sphere (radius 1) filling the centre of an orthographic view, in a constant
// environment of radiance 1 (equal-energy spectrum: luminance 1).
std::string furnace_scene(double albedo, int spp = 256, int branches = 1, int rr_depth = 100) {
  return fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 3, "eye": [0, 0, 10], "target": [0, 0, 0]}},
    "film": {{"resolution": [48, 48]}},
    "integrator": {{"spp": {}, "branches": {}, "max_depth": 100, "rr_depth": {}}},
    "materials": {{"m": {{"type": "lambert", "color": {}}}}},
    "lights": [{{"type": "environment", "radiance": 1.0}}],
    "shapes": [{{"type": "sphere", "radius": 1, "subdivisions": 256, "material": "m"}}]
  }})",
                     spp, branches, rr_depth, albedo);
}

TEST(WhiteFurnace, LambertSpheresRenderAlbedoTimesL) {
  for (double albedo : {1.0, 0.5}) {
    const LuminanceImage img = render_luminance(furnace_scene(albedo));
    ASSERT_EQ(img.width, 48);
    // The central 16x16 pixels lie inside the sphere's silhouette (radius 16 px).
    const double sphere = img.mean(16, 16, 32, 32);
    const double background = img.mean(0, 0, 4, 4);
    std::printf("furnace albedo %.2f: sphere Y = %.5f, background Y = %.5f\n", albedo, sphere, background);
    EXPECT_NEAR(background, 1.0, 0.005);
    EXPECT_NEAR(sphere, albedo, 0.005 * albedo);
  }
}

// Branched paths (integrator.branches) average their continuations: the same albedo x L.
TEST(WhiteFurnace, BranchedPathsRenderAlbedoTimesL) {
  const LuminanceImage img = render_luminance(furnace_scene(0.5, 64, 4));
  const double sphere = img.mean(16, 16, 32, 32);
  std::printf("furnace albedo 0.50, 4 branches: sphere Y = %.5f\n", sphere);
  EXPECT_NEAR(sphere, 0.5, 0.005 * 0.5);
}

// Russian roulette on branched paths (the matched-box benchmark scene starts it at depth 3 with two
// branches): from the first bounce on, each continuation survives with probability sqrt(0.5) and is
// reweighted by its inverse, and the average of the branches still renders albedo x L.
TEST(WhiteFurnace, RouletteOnBranchedPathsRendersAlbedoTimesL) {
  const LuminanceImage img = render_luminance(furnace_scene(0.5, 64, 4, 1));
  const double sphere = img.mean(16, 16, 32, 32);
  std::printf("furnace albedo 0.50, 4 branches, roulette from the first bounce: sphere Y = %.5f\n", sphere);
  EXPECT_NEAR(sphere, 0.5, 0.005 * 0.5);
}

// A point light of intensity I at height h over a Lambert plane of albedo rho, seen from
// above with an orthographic camera: L = rho / pi * I cos(theta) / r^2 at every pixel.
TEST(AnalyticDirectLighting, PointLightOverLambertPlane) {
  const double rho = 0.5, I = 10.0, h = 1.0, view = 4.0;
  const int res = 32;
  const LuminanceImage img = render_luminance(fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": {}, "eye": [0, 0, 5], "target": [0, 0, 0]}},
    "film": {{"resolution": [{}, {}]}},
    "integrator": {{"spp": 1024, "max_depth": 1}},
    "materials": {{"m": {{"type": "lambert", "color": {}}}}},
    "lights": [{{"type": "point", "position": [0, 0, {}], "intensity": {}}}],
    "shapes": [{{"type": "plane", "size": [10, 10], "material": "m"}}]
  }})",
                                                          view, res, res, rho, h, I));
  ASSERT_EQ(img.width, res);
  double worst = 0.0;
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) {
      // The pixel is a box filter: average the analytic radiance over its footprint (8x8 points;
      // x right, y up in the image).
      double expected = 0.0;
      for (int sj = 0; sj < 8; ++sj)
        for (int si = 0; si < 8; ++si) {
          const double x = (i + (si + 0.5) / 8) / res * view - view / 2;
          const double y = view / 2 - (j + (sj + 0.5) / 8) / res * view;
          const double r2 = x * x + y * y + h * h;
          expected += rho / M_PI * I * (h / std::sqrt(r2)) / r2 / 64.0;
        }
      worst = std::max(worst, std::fabs(img.at(i, j) / expected - 1.0));
    }
  std::printf("point light over Lambert plane: worst per-pixel relative error %.4f\n", worst);
  EXPECT_LT(worst, 0.01);
}

// A directional light of irradiance E arriving at 60 degrees from the normal of a Lambert plane: every pixel
// is rho E cos(60) / pi (a delta light: the only noise is the spectral estimate of the constant spectrum's
// luminance, 8 wavelengths a sample); under a second, larger plane above the camera
// every pixel is in its shadow (the shadow ray runs to infinity).
TEST(AnalyticDirectLighting, DirectionalLightOverLambertPlane) {
  const double rho = 0.5, E = 3.0, theta = 60.0 * M_PI / 180.0;
  const int res = 32;
  const LuminanceImage img =
      render_luminance(fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 4, "eye": [0, 0, 5], "target": [0, 0, 0]}},
    "film": {{"resolution": [{}, {}]}},
    "integrator": {{"spp": 256, "max_depth": 1}},
    "materials": {{"m": {{"type": "lambert", "color": {}}}}},
    "lights": [{{"type": "directional", "direction": [{}, 0, {}], "irradiance": {}}}],
    "shapes": [{{"type": "plane", "size": [10, 10], "material": "m"}}]
  }})",
                                   res, res, rho, -std::sin(theta), -std::cos(theta), E));
  ASSERT_EQ(img.width, res);
  const double expected = rho * E * std::cos(theta) / M_PI;
  double worst = 0.0, mean = 0.0;
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) {
      worst = std::max(worst, std::fabs(img.at(i, j) / expected - 1.0));
      mean += img.at(i, j) / (res * res);
    }
  std::printf("directional light over Lambert plane: worst per-pixel relative error %.2e, mean %.2e\n", worst,
              mean / expected - 1.0);
  EXPECT_LT(worst, 3e-4);
  EXPECT_NEAR(mean / expected, 1.0, 1e-5);

  const LuminanceImage shadowed = render_luminance(fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 4, "eye": [0, 0, 0.5], "target": [0, 0, 0]}},
    "film": {{"resolution": [8, 8]}},
    "integrator": {{"spp": 4, "max_depth": 1}},
    "materials": {{"m": {{"type": "lambert", "color": 0.5}}}},
    "lights": [{{"type": "directional", "direction": [{}, 0, {}], "irradiance": 3}}],
    "shapes": [{{"type": "plane", "size": [10, 10], "material": "m"}},
               {{"type": "plane", "size": [100, 100], "material": "m", "transform": {{"translate": [0, 0, 1]}}}}]
  }})",
                                                               -std::sin(theta), -std::cos(theta)));
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) EXPECT_EQ(shadowed.at(i, j), 0.0) << i << ", " << j;
}

// A constant environment L over a Lambert plane seen straight down: every pixel is rho L.
TEST(AnalyticDirectLighting, ConstantEnvironmentOverPlane) {
  const LuminanceImage img = render_luminance(R"({
    "camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 5], "target": [0, 0, 0]},
    "film": {"resolution": [16, 16]},
    "integrator": {"spp": 256, "max_depth": 1},
    "materials": {"m": {"type": "lambert", "color": 0.3}},
    "lights": [{"type": "environment", "radiance": 2.0}],
    "shapes": [{"type": "plane", "size": [4, 4], "material": "m"}]
  })");
  ASSERT_EQ(img.width, 16);
  const double mean = img.mean(0, 0, 16, 16);
  std::printf("constant environment over plane: mean Y = %.5f (expected 0.6)\n", mean);
  EXPECT_NEAR(mean, 0.6, 0.006);
}

}  // namespace
}  // namespace ochre::test::render_physics_test

namespace ochre::test::render_physics_test {
namespace {

// A one-sided emissive disk of radius R and radiance L, facing down at height h over a Lambert
// plane: the irradiance under its centre is pi L R^2 / (h^2 + R^2), so the plane's radiance there
// is rho L R^2 / (h^2 + R^2). Exercises area-light sampling, emission from the material graph and
// MIS (the disk is also hit by BSDF samples).
TEST(AnalyticDirectLighting, EmissiveDiskOverLambertPlane) {
  const double rho = 0.8, L = 3.0, R = 0.5, h = 1.0;
  const LuminanceImage img = render_luminance(fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 0.02, "eye": [0, 0, 0.5], "target": [0, 0, 0]}},
    "film": {{"resolution": [4, 4]}},
    "integrator": {{"spp": 4096, "max_depth": 1}},
    "materials": {{"m": {{"type": "lambert", "color": {}}},
                  "lamp": {{"type": "emission", "color": 1.0, "strength": {}}}}},
    "shapes": [{{"type": "plane", "size": [10, 10], "material": "m"}},
               {{"type": "disk", "radius": {}, "segments": 512, "material": "lamp",
                 "transform": [{{"rotate": {{"axis": [1, 0, 0], "angle": 180}}}}, {{"translate": [0, 0, {}]}}]}}]
  }})",
                                                          rho, L, R, h));
  ASSERT_EQ(img.width, 4);
  const double expected = rho * L * R * R / (h * h + R * R);
  const double mean = img.mean(0, 0, 4, 4);
  std::printf("emissive disk over plane: Y = %.5f, expected %.5f\n", mean, expected);
  EXPECT_NEAR(mean, expected, 0.01 * expected);
}

// An 8-bit sRGB texture on a plane under a D65 environment of luminance 1: each quadrant renders
// its texel's linear colour (checks the sRGB decoding, the uv orientation and the upsampling).
TEST(Textures, TexturedPlaneShowsTexelColours) {
  const auto dir = scratch_dir();
  // 8x8 PPM of four 4x4 blocks: top row (200,60,40), (60,180,70); bottom row (50,70,200), grey 188.
  const int codes[4][3] = {{200, 60, 40}, {60, 180, 70}, {50, 70, 200}, {188, 188, 188}};
  std::string ppm = "P3\n8 8\n255\n";
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const int* c = codes[(y / 4) * 2 + x / 4];
      ppm += fmt::format("{} {} {}\n", c[0], c[1], c[2]);
    }
  write_text(dir / "tex.ppm", ppm);
  write_text(dir / "scene.json", R"({
    "camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 5], "target": [0, 0, 0]},
    "film": {"resolution": [8, 8]},
    "integrator": {"spp": 256, "max_depth": 1},
    "materials": {"m": {"nodes": {"t": {"type": "texture", "file": "tex.ppm"},
                                   "d": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "d"}},
    "lights": [{"type": "environment", "radiance": [1, 1, 1]}],
    "shapes": [{"type": "plane", "size": [2, 2], "material": "m"}]
  })");
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage exr = read_exr(dir / "out.exr");
  auto mean_rgb = [&](int x0, int y0) {
    std::array<double, 3> m{0, 0, 0};
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
      for (int y = y0 + 1; y < y0 + 3; ++y)
        for (int x = x0 + 1; x < x0 + 3; ++x) m[c] += (*exr.find_channel(names[c]))[y * 8 + x] / 4.0;
    return m;
  };
  auto srgb_decode = [](double code) {
    const double v = code / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  const int corners[4][2] = {{0, 0}, {4, 0}, {0, 4}, {4, 4}};
  for (int q = 0; q < 4; ++q) {
    const auto m = mean_rgb(corners[q][0], corners[q][1]);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(m[c], srgb_decode(codes[q][c]), 0.02) << "quadrant " << q << " channel " << c;
  }
}

}  // namespace
}  // namespace ochre::test::render_physics_test

namespace ochre::test::render_physics_test {
namespace {

// A 256x256 black/white checker seen so that one pixel covers 32x32 texels: with the ray-cone
// footprint, the filtered lookup returns the texels' average (0.5). Compared per pixel with a plain
// 0.5 grey rendered with the same seed (same wavelengths, so the spectral noise cancels); point
// sampling would give 0 or 1 per sample.
TEST(Textures, MinifiedTextureIsFiltered) {
  const auto dir = scratch_dir();
  std::string ppm = "P2\n256 256\n255\n";
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) ppm += ((x + y) % 2 ? "255\n" : "0\n");
  write_text(dir / "checker.pgm", ppm);
  auto scene = [](const std::string& colour) {
    return R"({
    "camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 5], "target": [0, 0, 0]},
    "film": {"resolution": [8, 8]},
    "integrator": {"spp": 4, "max_depth": 1},
    "materials": {"m": {"nodes": {"t": {"type": "texture", "file": "checker.pgm", "colorspace": "linear"},
                                   "d": {"type": "lambert", "color": )" +
           colour + R"(}}, "output": "d"}},
    "lights": [{"type": "environment", "radiance": 1}],
    "shapes": [{"type": "plane", "size": [2, 2], "material": "m"}]
  })";
  };
  write_text(dir / "textured.json", scene(R"({"link": "t.color"})"));
  write_text(dir / "grey.json", scene("0.5"));
  ASSERT_EQ(run_ochre("render textured.json -o textured.exr", dir).exit_code, 0);
  ASSERT_EQ(run_ochre("render grey.json -o grey.exr", dir).exit_code, 0);
  const ExrImage textured = read_exr(dir / "textured.exr"), grey = read_exr(dir / "grey.exr");
  double worst = 0.0;
  for (size_t i = 0; i < 64; ++i)
    worst = std::max(worst, std::fabs((*textured.find_channel("G"))[i] / (*grey.find_channel("G"))[i] - 1.0));
  std::printf("minified checker vs grey 0.5: worst per-pixel ratio error %.4f\n", worst);
  EXPECT_LT(worst, 0.05);
}

}  // namespace
}  // namespace ochre::test::render_physics_test

namespace ochre::test::render_physics_test {
namespace {

// A spot light straight above a Lambert plane: inside the inner cone the plane shows the point-light
// value rho/pi I cos/r^2, outside the outer cone it is black, and in between it falls off smoothly.
TEST(AnalyticDirectLighting, SpotLightCone) {
  const double rho = 0.5, I = 10.0, h = 1.0;
  const LuminanceImage img = render_luminance(fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 0.125, "eye": [0, 0, 5], "target": [0, 0, 0]}},
    "film": {{"resolution": [64, 2]}},
    "integrator": {{"spp": 1024, "max_depth": 1}},
    "materials": {{"m": {{"type": "lambert", "color": {}}}}},
    "lights": [{{"type": "spot", "position": [0, 0, {}], "target": [0, 0, 0], "cone_angle": 45,
                "falloff_start": 30, "intensity": {}}}],
    "shapes": [{{"type": "plane", "size": [10, 10], "material": "m"}}]
  }})",
                                                          rho, h, I));
  ASSERT_EQ(img.width, 64);
  for (int i = 0; i < 64; ++i) {
    // Pixel centre on the plane: the film is 4 x 0.125 world units, row 0 at y = 0.03125.
    const double x = (i + 0.5) / 64 * 4 - 2, y = 0.03125;
    const double angle = std::atan(std::sqrt(x * x + y * y) / h) * 180 / M_PI;
    const double r2 = x * x + y * y + h * h;
    const double point = rho / M_PI * I * (h / std::sqrt(r2)) / r2;
    if (angle < 28) {
      EXPECT_NEAR(img.at(i, 0), point, 0.01 * point) << "inside, x = " << x;
    } else if (angle > 46) {
      EXPECT_EQ(img.at(i, 0), 0.0) << "outside, x = " << x;
    } else if (angle > 32 && angle < 43) {
      EXPECT_LT(img.at(i, 0), point) << "falloff, x = " << x;
    }
  }
}

}  // namespace
}  // namespace ochre::test::render_physics_test

namespace ochre::test::render_physics_test {
namespace {

// An environment map of constant value renders the same image as the constant environment of that
// value (within noise: the two sample directions differently).
TEST(EnvironmentMap, ConstantMapMatchesConstantEnvironment) {
  const auto dir = scratch_dir();
  ExrImage map;
  map.width = 16;
  map.height = 8;
  for (const char* c : {"R", "G", "B"}) map.channels.emplace_back(c, std::vector<float>(16 * 8, 0.7f));
  write_exr(dir / "const.exr", map);
  auto scene = [](const std::string& light) {
    return R"({"camera": {"type": "orthographic", "size": 3, "eye": [0, 0, 10], "target": [0, 0, 0]},
      "film": {"resolution": [24, 24]}, "integrator": {"spp": 256, "max_depth": 4},
      "materials": {"m": {"type": "lambert", "color": [0.8, 0.5, 0.3]}},
      "lights": [)" +
           light + R"(],
      "shapes": [{"type": "sphere", "radius": 1, "material": "m"}]})";
  };
  write_text(dir / "map.json", scene(R"({"type": "environment", "file": "const.exr", "rotation": 30})"));
  write_text(dir / "constant.json", scene(R"({"type": "environment", "radiance": [0.7, 0.7, 0.7]})"));
  ASSERT_EQ(run_ochre("render map.json -o map.exr", dir).exit_code, 0);
  ASSERT_EQ(run_ochre("render constant.json -o constant.exr", dir).exit_code, 0);
  const ExrImage a = read_exr(dir / "map.exr"), b = read_exr(dir / "constant.exr");
  for (const char* c : {"R", "G", "B"}) {
    double sum_a = 0, sum_b = 0;
    for (size_t i = 0; i < 24 * 24; ++i) {
      sum_a += (*a.find_channel(c))[i];
      sum_b += (*b.find_channel(c))[i];
    }
    std::printf("constant map vs constant environment, channel %s: %.5f vs %.5f\n", c, sum_a, sum_b);
    EXPECT_NEAR(sum_a / sum_b, 1.0, 0.005) << c;
  }
}

}  // namespace
}  // namespace ochre::test::render_physics_test

namespace ochre::test::render_physics_test {
namespace {

// A Catmull-Clark subdivided cube (the scene's "subdivision" key) is a closed convex-ish surface:
// with albedo 1 in a white furnace it disappears into the background.
TEST(Subdivision, SubdividedCubeInWhiteFurnace) {
  const auto dir = scratch_dir();
  const auto cube = source_dir() / "tests/data/cube_quads.obj";
  write_text(dir / "scene.json", R"({
    "camera": {"type": "orthographic", "size": 4, "eye": [3, 4, 5], "target": [0, 0, 0]},
    "film": {"resolution": [24, 24]}, "integrator": {"spp": 128, "max_depth": 64, "rr_depth": 64},
    "materials": {"white": {"type": "lambert", "color": 1}},
    "lights": [{"type": "environment", "radiance": 1}],
    "shapes": [{"type": "mesh", "file": ")" +
                                     cube.string() + R"(", "material": "white",
                "subdivision": {"scheme": "catmull-clark", "level": 3}}]})");
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("triangles"), std::string::npos);
  const ExrImage exr = read_exr(dir / "out.exr");
  double sum = 0.0;
  for (size_t i = 0; i < 24 * 24; ++i) sum += (*exr.find_channel("G"))[i];
  // Equal-energy radiance 1 has G = 1 minus the Rec.709 tint of illuminant E; compare with the
  // background corner instead of a constant.
  const double corner = (*exr.find_channel("G"))[0];
  std::printf("subdivided cube furnace: mean G %.5f, background %.5f\n", sum / 576, corner);
  EXPECT_NEAR(sum / 576 / corner, 1.0, 0.01);
}

TEST(Subdivision, DisplacementNeedsSubdivision) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", R"({"materials": {"g": {"type": "lambert"}},
    "shapes": [{"type": "mesh", "file": "x.obj", "material": "g", "displacement": {"file": "h.exr"}}]})");
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("shapes[0].displacement"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace ochre::test::render_physics_test
