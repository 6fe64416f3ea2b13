// Rendered polarization: filters on lights and on the camera, Malus's law, the camera's Stokes
// frame, depolarizing surfaces between crossed polarizers, and the consistency of the modes.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "materials/core/pi.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::polarization_render_test {
namespace {

struct Rendered {
  ExrImage exr;
  std::string log;
  // Mean over all pixels of a channel.
  double mean(const std::string& channel) const { return mean_of(exr_channel(exr, channel)); }
  double luminance() const { return 0.2126729 * mean("R") + 0.7151522 * mean("G") + 0.0721750 * mean("B"); }
};

Rendered render(const std::string& scene, const std::string& args = "") {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", scene);
  const CommandResult r = run_tool("ochre", "render scene.json -o out.exr " + args, dir);
  Rendered out;
  out.log = r.output;
  EXPECT_EQ(r.exit_code, 0) << r.output;
  if (r.exit_code == 0) out.exr = read_exr(dir / "out.exr");
  return out;
}

// An emissive square seen head-on by an orthographic camera (image x = world x, image up = world y),
// behind a linear polarizer with world axis `light_axis`; `camera` adds camera keys (e.g. a polarizer).
std::string polarized_lamp_scene(const std::string& light_axis, const std::string& camera) {
  return fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 1, "eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0] {}}},
    "film": {{"resolution": [8, 8]}},
    "integrator": {{"spp": 16, "max_depth": 1}},
    "materials": {{"lamp": {{"type": "emission", "color": 1.0, "strength": 2.0}}}},
    "shapes": [{{"type": "plane", "size": [4, 4], "material": "lamp" {}}}]
  }})",
                     camera, light_axis.empty() ? "" : ", \"polarizer\": {\"axis\": " + light_axis + "}");
}

std::string analyzer(double degrees) {
  return fmt::format(R"(, "polarizer": {{"angle": {}}})", degrees);
}

// Malus's law: light polarized along the image x axis through an analyzer at angle t passes cos^2 t of
// what a parallel analyzer passes. The paths' wavelengths are the same in every render (same seed), so
// the ratio is exact up to rounding.
TEST(PolarizationRender, MalusLawThroughARotatedAnalyzer) {
  const double parallel = render(polarized_lamp_scene("[1, 0, 0]", analyzer(0))).luminance();
  const double unfiltered = render(polarized_lamp_scene("", "")).luminance();
  ASSERT_GT(parallel, 0.0);
  // A polarizer passes half of unpolarized light; a parallel analyzer passes all of what it lets through.
  EXPECT_NEAR(parallel / unfiltered, 0.5, 1e-5);
  for (int degrees = 15; degrees <= 90; degrees += 15) {
    const double t = degrees * kPiD / 180.0;
    const double ratio = render(polarized_lamp_scene("[1, 0, 0]", analyzer(degrees))).luminance() / parallel;
    std::printf("Malus: analyzer at %2d deg passes %.6f (cos^2 = %.6f)\n", degrees, ratio,
                std::cos(t) * std::cos(t));
    EXPECT_NEAR(ratio, std::cos(t) * std::cos(t), 1e-5) << degrees << " deg";
  }
}

// The camera's Stokes frame: x = image x axis, y = image up. Light polarized along world x, y and the
// diagonal x + y has AoLP 0, 90 and +45 degrees, DoLP 1; S3 = 0.
TEST(PolarizationRender, AngleOfLinearPolarizationIsMeasuredFromTheImageXAxis) {
  struct Case {
    const char* axis;
    double aolp_degrees;
  };
  for (const Case& c : {Case{"[1, 0, 0]", 0.0}, Case{"[1, 1, 0]", 45.0}, Case{"[0, 1, 0]", 90.0},
                        Case{"[1, -1, 0]", -45.0}}) {
    const Rendered r = render(polarized_lamp_scene(c.axis, ""), "--stokes");
    const double s0 = r.mean("stokes.S0.Y"), s1 = r.mean("stokes.S1.Y"), s2 = r.mean("stokes.S2.Y"),
                 s3 = r.mean("stokes.S3.Y");
    ASSERT_GT(s0, 0.0) << r.log;
    double aolp = r.mean("AoLP") * 180.0 / kPiD;
    if (c.aolp_degrees == 90.0 && aolp < 0.0) aolp += 180.0;  // +-90 is the same axis
    EXPECT_NEAR(aolp, c.aolp_degrees, 1e-3) << c.axis;
    EXPECT_NEAR(r.mean("DoLP"), 1.0, 1e-5) << c.axis;
    EXPECT_NEAR(std::sqrt(s1 * s1 + s2 * s2) / s0, 1.0, 1e-5) << c.axis;
    EXPECT_NEAR(s3 / s0, 0.0, 1e-6) << c.axis;
    EXPECT_NE(r.log.find("polarization: stokes (auto: a Stokes output is requested)"), std::string::npos)
        << r.log;
  }
}

// A Lambert plane lit by a point light behind a polarizer: the diffuse reflection depolarizes, so an
// analyzer crossed with the light's polarizer passes exactly what a parallel one passes, half of the
// light reaching it (without the analyzer).
std::string polarized_light_on_lambert(const std::string& camera) {
  return fmt::format(R"({{
    "camera": {{"type": "perspective", "fov": 40, "eye": [0, -3, 3], "target": [0, 0, 0], "up": [0, 0, 1] {}}},
    "film": {{"resolution": [16, 16]}},
    "integrator": {{"spp": 8, "max_depth": 3}},
    "materials": {{"m": {{"type": "lambert", "color": 0.7}}}},
    "lights": [{{"type": "point", "position": [0.5, 0, 2], "intensity": 10, "polarizer": {{"axis": [1, 0, 0]}}}},
               {{"type": "environment", "radiance": 0.2}}],
    "shapes": [{{"type": "plane", "size": [4, 4], "material": "m"}}]
  }})",
                     camera);
}

TEST(PolarizationRender, DepolarizingSurfaceBetweenCrossedPolarizers) {
  const Rendered parallel = render(polarized_light_on_lambert(analyzer(0)));
  const Rendered crossed = render(polarized_light_on_lambert(analyzer(90)));
  const Rendered open = render(polarized_light_on_lambert(""));
  const double p = parallel.luminance(), c = crossed.luminance(), o = open.luminance();
  std::printf("depolarizing plane: parallel %.6f, crossed %.6f, no analyzer %.6f\n", p, c, o);
  ASSERT_GT(o, 0.0);
  EXPECT_NEAR(c / p, 1.0, 1e-5);
  EXPECT_NEAR(c / o, 0.5, 1e-5);
}

// Mode auto picks off for a scene of diffuse materials with no filter, and the image is bit-identical to
// mode off; mode intensity, forced, gives the same bits (a depolarizer keeps only the first component).
TEST(PolarizationRender, AutoIsOffForDiffuseScenesAndIntensityAgrees) {
  const std::string scene = R"({
    "camera": {"type": "perspective", "fov": 40, "eye": [0, -3, 3], "target": [0, 0, 0], "up": [0, 0, 1]},
    "film": {"resolution": [16, 16]},
    "integrator": {"spp": 8, "max_depth": 4},
    "materials": {"m": {"type": "lambert", "color": 0.7}},
    "lights": [{"type": "point", "position": [0.5, 0, 2], "intensity": 10},
               {"type": "environment", "radiance": 0.2}],
    "shapes": [{"type": "plane", "size": [4, 4], "material": "m"},
               {"type": "sphere", "center": [0, 0, 0.5], "radius": 0.5, "material": "m"}]
  })";
  const Rendered automatic = render(scene);
  const Rendered off = render(scene, "--polarization off");
  const Rendered intensity = render(scene, "--polarization intensity");
  EXPECT_NE(automatic.log.find("polarization: off (auto: no material or filter polarizes)"),
            std::string::npos)
      << automatic.log;
  for (const char* channel : {"R", "G", "B"}) {
    EXPECT_EQ(*automatic.exr.find_channel(channel), *off.exr.find_channel(channel)) << channel;
    EXPECT_EQ(*intensity.exr.find_channel(channel), *off.exr.find_channel(channel)) << channel;
  }
}

// S0 of mode stokes equals mode intensity (the same paths; the full matrix product only adds rows).
TEST(PolarizationRender, StokesModeS0EqualsIntensityMode) {
  const Rendered intensity = render(polarized_light_on_lambert(analyzer(30)), "--polarization intensity");
  const Rendered stokes = render(polarized_light_on_lambert(analyzer(30)), "--polarization stokes --stokes");
  for (const char* channel : {"R", "G", "B"}) {
    const auto& a = *intensity.exr.find_channel(channel);
    const auto& b = *stokes.exr.find_channel(channel);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-5 * (1.0 + std::fabs(a[i]))) << i;
  }
}

TEST(PolarizationRender, StokesOutputNeedsModeStokes) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", polarized_lamp_scene("[1, 0, 0]", ""));
  const CommandResult r =
      run_tool("ochre", "render scene.json -o out.exr --stokes --polarization intensity", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("needs polarization mode stokes"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

TEST(PolarizationRender, PolarizerWithoutAxisIsBadInput) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", polarized_lamp_scene("[0, 0, 0]", ""));
  const CommandResult r = run_tool("ochre", "render scene.json -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("shapes[0].polarizer.axis"), std::string::npos) << r.output;
}

TEST(PolarizationRender, PolarizationPngIsWritten) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", polarized_lamp_scene("[1, 1, 0]", ""));
  const CommandResult r = run_tool("ochre", "render scene.json -o out.exr --polarization-png pol.png", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "pol.png"));
}

}  // namespace
}  // namespace ochre::test::polarization_render_test

namespace ochre::test::polarization_render_test {
namespace {

// Black glass (n = 1.5, refraction absorbed) seen at Brewster's angle atan(1.5) in the x-z plane,
// reflecting an emissive square. The camera's image x axis is the world y axis: the s direction.
// `lamp_extra` adds keys to the lamp shape (a polarizer), `camera_extra` to the camera, `scene_rotation`
// is a transform applied to both shapes.
std::string brewster_scene(const std::string& lamp_extra, const std::string& camera_extra,
                           const std::string& scene_rotation = "") {
  const double theta = std::atan(1.5);
  const double s = std::sin(theta), c = std::cos(theta);
  const std::string rotate = scene_rotation.empty() ? "" : ", " + scene_rotation;
  return fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 0.2, "eye": [{}, 0, {}], "target": [0, 0, 0], "up": [0, 0, 1] {}}},
    "film": {{"resolution": [4, 4]}},
    "integrator": {{"spp": 16, "max_depth": 3}},
    "materials": {{"glass": {{"type": "dielectric", "ior": 1.5, "opaque": 1}},
                  "lamp": {{"type": "emission", "color": 1.0, "strength": 1.0}}}},
    "shapes": [{{"type": "plane", "size": [20, 20], "material": "glass", "transform": [{{"scale": 1}} {}]}},
               {{"type": "plane", "size": [10, 10], "material": "lamp" {},
                "transform": [{{"rotate": {{"axis": [0, 1, 0], "angle": {}}}}}, {{"translate": [{}, 0, {}]}} {}]}}]
  }})",
                     -5 * s, 5 * c, camera_extra, rotate, lamp_extra, 180.0 + theta * 180.0 / kPiD, 5 * s,
                     5 * c, rotate);
}

// The unpolarized reflectance at Brewster's angle, (R_s + R_p) / 2 = 0.0739645 (the note's Brewster
// block), measured against the lamp seen directly with the same wavelengths.
double direct_lamp_luminance() {
  return render(R"({
    "camera": {"type": "orthographic", "size": 0.2, "eye": [0, 0, 5], "target": [0, 0, 0]},
    "film": {"resolution": [4, 4]},
    "integrator": {"spp": 16, "max_depth": 3},
    "materials": {"lamp": {"type": "emission", "color": 1.0, "strength": 1.0}},
    "shapes": [{"type": "plane", "size": [10, 10], "material": "lamp"}]
  })")
      .luminance();
}

TEST(PolarizationRender, BrewsterAngleExtinguishesPPolarizedLight) {
  const double theta = std::atan(1.5);
  const std::string p_axis =
      fmt::format(R"(, "polarizer": {{"axis": [{}, 0, {}]}})", std::cos(theta), -std::sin(theta));
  const std::string s_axis = R"(, "polarizer": {"axis": [0, 1, 0]})";
  const double lamp = direct_lamp_luminance();
  const double unpolarized = render(brewster_scene("", "")).luminance();
  const double p_light = render(brewster_scene(p_axis, "")).luminance();
  const double s_light = render(brewster_scene(s_axis, "")).luminance();
  // The same through the camera: an analyzer along p (image y) sees nothing of unpolarized light.
  const double p_analyzer = render(brewster_scene("", analyzer(90))).luminance();
  const double s_analyzer = render(brewster_scene("", analyzer(0))).luminance();
  std::printf(
      "Brewster: R = %.7f (expected 0.0739645); p light %.3g, s light %.7f; p analyzer %.3g, s analyzer "
      "%.7f\n",
      unpolarized / lamp, p_light / lamp, s_light / lamp, p_analyzer / lamp, s_analyzer / lamp);
  EXPECT_NEAR(unpolarized / lamp, 0.0739645, 2e-6);
  EXPECT_LT(p_light / lamp, 1e-6);
  EXPECT_LT(p_analyzer / lamp, 1e-6);
  // s light: half the lamp through the polarizer, reflected with R_s = 2 x 0.0739645.
  EXPECT_NEAR(s_light / lamp, 0.0739645, 2e-6);
  EXPECT_NEAR(s_analyzer / lamp, 0.0739645, 2e-6);
}

// Rotating the scene about the camera's view axis by psi leaves S0 unchanged and turns the polarization
// with it: (S1, S2) rotate by 2 psi (AoLP + psi).
TEST(PolarizationRender, RotationAboutTheViewAxisRotatesS1S2ByTwiceTheAngle) {
  const double theta = std::atan(1.5);
  const double psi_degrees = 30.0, psi = psi_degrees * kPiD / 180.0;
  // About the view axis pointing back at the camera: a right-handed turn about it is counter-clockwise as
  // the camera sees it (from its image x axis toward its up axis), the sense in which AoLP grows.
  const std::string rotation = fmt::format(R"({{"rotate": {{"axis": [{}, 0, {}], "angle": {}}}}})",
                                           -std::sin(theta), std::cos(theta), psi_degrees);
  const Rendered base = render(brewster_scene("", ""), "--stokes");
  const Rendered turned = render(brewster_scene("", "", rotation), "--stokes");
  const double s0 = base.mean("stokes.S0.Y"), s1 = base.mean("stokes.S1.Y"), s2 = base.mean("stokes.S2.Y");
  const double t0 = turned.mean("stokes.S0.Y"), t1 = turned.mean("stokes.S1.Y"),
               t2 = turned.mean("stokes.S2.Y");
  std::printf("rotation by %.0f deg: S = (%.6f, %.6f, %.6f) -> (%.6f, %.6f, %.6f)\n", psi_degrees, s0, s1, s2,
              t0, t1, t2);
  EXPECT_NEAR(t0 / s0, 1.0, 1e-4);
  // Light turned by +psi: S1' = cos 2psi S1 - sin 2psi S2, S2' = sin 2psi S1 + cos 2psi S2.
  EXPECT_NEAR(t1 / s0, (std::cos(2 * psi) * s1 - std::sin(2 * psi) * s2) / s0, 1e-4);
  EXPECT_NEAR(t2 / s0, (std::sin(2 * psi) * s1 + std::cos(2 * psi) * s2) / s0, 1e-4);
  EXPECT_NEAR(turned.mean("AoLP") - base.mean("AoLP"), psi, 1e-4);
}

}  // namespace
}  // namespace ochre::test::polarization_render_test

namespace ochre::test::polarization_render_test {
namespace {

struct V3 {
  double x, y, z;
};

// Rodrigues rotation of v about the unit axis k by `degrees`.
V3 rotate(const V3& v, const V3& k, double degrees) {
  const double a = degrees * kPiD / 180.0, c = std::cos(a), s = std::sin(a);
  const double kv = k.x * v.x + k.y * v.y + k.z * v.z;
  const V3 kxv{k.y * v.z - k.z * v.y, k.z * v.x - k.x * v.z, k.x * v.y - k.y * v.x};
  return {v.x * c + kxv.x * s + k.x * kv * (1 - c), v.y * c + kxv.y * s + k.y * kv * (1 - c),
          v.z * c + kxv.z * s + k.z * kv * (1 - c)};
}

std::string json(const V3& v) {
  return fmt::format("[{:.9f}, {:.9f}, {:.9f}]", v.x, v.y, v.z);
}

// A 90-degree V-groove of two smooth silicon facets (n = 4.073, k = 0.028) along the x axis, seen at
// theta from the normal looking along the groove under a constant white environment: every ray is
// reflected exactly twice and its middle segment is horizontal. `degrees` turns the whole scene (camera
// included) about a generic axis. The exact reflectance is 0.1242 at theta = 30 deg and 0.0188 at 63 deg
// (Mitsuba 3 renders 0.1624 and 0.1488 here, from a basis flip: docs/polarization.md, 'Discontinuous
// reference frames').
std::string groove_scene(double theta_degrees, double degrees) {
  const V3 axis{0.267261242, 0.534522484, 0.801783726};  // (1, 2, 3) / sqrt(14)
  const double t = theta_degrees * kPiD / 180.0;
  const V3 target{0, 0.4, 0.4};
  const V3 eye{target.x - 6 * std::sin(t), target.y, target.z + 6 * std::cos(t)};
  const double h = 0.70710678118654752;  // half the facet width (2) times cos 45
  const std::string turn =
      degrees == 0.0 ? ""
                     : fmt::format(R"(, {{"rotate": {{"axis": {}, "angle": {}}}}})", json(axis), degrees);
  return fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 0.1, "eye": {}, "target": {}, "up": {}}},
    "film": {{"resolution": [4, 4]}},
    "integrator": {{"spp": 4, "max_depth": 8}},
    "materials": {{"si": {{"type": "conductor", "eta": 4.073, "k": 0.028}}}},
    "lights": [{{"type": "environment", "radiance": 1.0}}],
    "shapes": [{{"type": "plane", "size": [40, 2], "material": "si",
                "transform": [{{"rotate": {{"axis": [1, 0, 0], "angle": 45}}}}, {{"translate": [0, {}, {}]}} {}]}},
               {{"type": "plane", "size": [40, 2], "material": "si",
                "transform": [{{"rotate": {{"axis": [1, 0, 0], "angle": -45}}}}, {{"translate": [0, {}, {}]}} {}]}}]
  }})",
                     json(rotate(eye, axis, degrees)), json(rotate(target, axis, degrees)),
                     json(rotate({0, 0, 1}, axis, degrees)), h, h, turn, -h, h, turn);
}

// The environment alone, with the same pixels and samples (so the same wavelengths): the groove's
// reflectance is spectrally constant, so the ratio of the two images is exact.
double environment_luminance() {
  return render(R"({
    "camera": {"type": "orthographic", "size": 0.1, "eye": [0, 0, 5], "target": [0, 0, 0]},
    "film": {"resolution": [4, 4]},
    "integrator": {"spp": 4},
    "materials": {},
    "lights": [{"type": "environment", "radiance": 1.0}],
    "shapes": []
  })")
      .luminance();
}

TEST(PolarizationRender, GrooveWithHorizontalSegmentsMatchesTheExactReflectance) {
  const double white = environment_luminance();
  struct Case {
    double theta, exact;
  };
  for (const Case& c : {Case{30.0, 0.1242}, Case{63.0, 0.0188}}) {
    const double aligned = render(groove_scene(c.theta, 0.0), "--polarization intensity").luminance() / white;
    const double generic =
        render(groove_scene(c.theta, 37.0), "--polarization intensity").luminance() / white;
    const double off = render(groove_scene(c.theta, 0.0), "--polarization off").luminance() / white;
    std::printf(
        "V-groove theta %.0f: axis-aligned %.5f, generic orientation %.5f, exact %.4f; mode off %.5f (%+.0f "
        "%%)\n",
        c.theta, aligned, generic, c.exact, off, 100.0 * (off / c.exact - 1.0));
    EXPECT_NEAR(aligned, c.exact, 6e-5) << c.theta;
    EXPECT_NEAR(generic, aligned, 1e-5) << c.theta;
  }
}

}  // namespace
}  // namespace ochre::test::polarization_render_test

namespace ochre::test::polarization_render_test {
namespace {

// With unpolarized light, an intensity film and one polarizing bounce, the first row of the Mueller
// product applied to unpolarized light is M00: modes off and intensity estimate the same image (here
// with the same random numbers, so to rounding).
TEST(PolarizationRender, ModesOffAndIntensityAgreeWithOnePolarizingBounce) {
  const std::string scene = R"({
    "camera": {"type": "perspective", "fov": 40, "eye": [0, -3, 3], "target": [0, 0, 0], "up": [0, 0, 1]},
    "film": {"resolution": [16, 16]},
    "integrator": {"spp": 16, "max_depth": 1},
    "materials": {"gold": {"type": "conductor", "metal": "Au", "roughness": 0.3}},
    "lights": [{"type": "point", "position": [0.5, 0.5, 2], "intensity": 10},
               {"type": "environment", "radiance": 0.3}],
    "shapes": [{"type": "plane", "size": [4, 4], "material": "gold"}]
  })";
  const Rendered off = render(scene, "--polarization off");
  const Rendered intensity = render(scene);
  EXPECT_NE(intensity.log.find("polarization: intensity (auto: a material polarizes (diattenuation "),
            std::string::npos)
      << intensity.log;
  std::printf("one polarizing bounce: off %.7f, intensity %.7f\n", off.luminance(), intensity.luminance());
  EXPECT_NEAR(intensity.luminance() / off.luminance(), 1.0, 1e-4);
}

// A damp film over diffuse rock (the default cave's material in small): a rough dielectric lobe reflecting a
// few percent over a Lambertian base. Its closures polarize too little to change intensities, so auto leaves
// polarization off, and tracing it (mode intensity) changes the image by less than the bound auto printed;
// rough gold alone polarizes strongly and auto traces it.
std::string damp_corner_scene(const std::string& film, double film_weight) {
  return R"({
    "camera": {"type": "perspective", "fov": 50, "eye": [2, 1.2, 2], "target": [0, 0.5, 0]},
    "film": {"resolution": [16, 16]},
    "integrator": {"spp": 64, "max_depth": 4},
    "materials": {"damp": {"nodes": {"rock": {"type": "lambert", "color": 0.6}, )" +
         film + R"(, "wet": {"type": "multiply", "a": {"link": "film"}, "b": )" +
         std::to_string(film_weight) +
         R"(}, "out": {"type": "add", "a": {"link": "rock"}, "b": {"link": "wet"}}}, "output": "out"}},
    "lights": [{"type": "point", "position": [1, 1.5, 1], "intensity": 5}],
    "shapes": [{"type": "plane", "size": [4, 4], "material": "damp"},
               {"type": "plane", "size": [4, 4], "material": "damp", "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}}]},
               {"type": "plane", "size": [4, 4], "material": "damp", "transform": [{"rotate": {"axis": [0, 0, 1], "angle": -90}}]}]
  })";
}

TEST(PolarizationRender, AutoLeavesOffWhatPolarizesTooLittleToChangeIntensities) {
  // The cave's film: ior 1.5, roughness 0.2, weighed by its wetness (here 0.3).
  const std::string film = R"("film": {"type": "dielectric", "ior": 1.5, "roughness": 0.2, "opaque": 1})";
  const Rendered automatic = render(damp_corner_scene(film, 0.3));
  const Rendered traced = render(damp_corner_scene(film, 0.3), "--polarization intensity");
  const std::smatch bound = [&] {
    std::smatch m;
    std::regex_search(
        automatic.log, m,
        std::regex(
            R"(polarization: off \(auto: the materials polarize too little to change intensities \(diattenuation ([0-9.e-]+) x polarizance ([0-9.e-]+) = ([0-9.e-]+) < 0.001\)\))"));
    return m;
  }();
  ASSERT_EQ(bound.size(), 4u) << automatic.log;
  const double estimate = std::stod(bound[3]);
  const double change = traced.luminance() / automatic.luminance() - 1.0;
  std::printf(
      "damp film: auto off (diattenuation %s x polarizance %s = %g); intensity mode changes the image by "
      "%.2e\n",
      bound[1].str().c_str(), bound[2].str().c_str(), estimate, change);
  EXPECT_GT(estimate, 0.0);
  EXPECT_LT(std::fabs(change), estimate);  // the same paths (same seed): only the cross terms differ

  // Rough gold over the same rock: strongly polarizing, traced.
  const Rendered gold =
      render(damp_corner_scene(R"("film": {"type": "conductor", "metal": "Au", "roughness": 0.3})", 1.0));
  EXPECT_NE(gold.log.find("polarization: intensity (auto: a material polarizes (diattenuation "),
            std::string::npos)
      << gold.log;
}

// Cross-polarized photography: a flash behind a polarizer and a crossed analyzer on the lens remove the
// glare of a glossy film (rough dielectric) over diffuse paint; a parallel analyzer keeps it.
std::string glossy_paint_scene(bool with_film, double analyzer_degrees) {
  const std::string film =
      with_film ? R"(, "film": {"type": "dielectric", "ior": 1.5, "roughness": 0.1, "opaque": 1},
      "out": {"type": "add", "a": {"link": "paint"}, "b": {"link": "film"}})"
                : "";
  return fmt::format(R"({{
    "camera": {{"type": "perspective", "fov": 30, "eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0],
               "polarizer": {{"angle": {}}}}},
    "film": {{"resolution": [8, 8]}},
    "integrator": {{"spp": 64, "max_depth": 2}},
    "materials": {{"m": {{"nodes": {{"paint": {{"type": "lambert", "color": 0.3}} {}}}, "output": "{}"}}}},
    "lights": [{{"type": "point", "position": [0.1, 0.1, 3], "intensity": 10, "polarizer": {{"axis": [1, 0, 0]}}}}],
    "shapes": [{{"type": "plane", "size": [4, 4], "material": "m"}}]
  }})",
                     analyzer_degrees, film, with_film ? "out" : "paint");
}

TEST(PolarizationRender, CrossedPolarizersRemoveSpecularGlare) {
  const double paint_parallel = render(glossy_paint_scene(false, 0)).luminance();
  const double paint_crossed = render(glossy_paint_scene(false, 90)).luminance();
  const double glare_parallel = render(glossy_paint_scene(true, 0)).luminance() - paint_parallel;
  const double glare_crossed = render(glossy_paint_scene(true, 90)).luminance() - paint_crossed;
  std::printf("glare: parallel analyzer %.5f, crossed %.5f (diffuse paint %.5f / %.5f)\n", glare_parallel,
              glare_crossed, paint_parallel, paint_crossed);
  EXPECT_NEAR(paint_crossed / paint_parallel, 1.0, 1e-5);  // the paint depolarizes
  ASSERT_GT(glare_parallel, 0.1 * paint_parallel);
  EXPECT_LT(std::fabs(glare_crossed), 0.02 * glare_parallel);
}

}  // namespace
}  // namespace ochre::test::polarization_render_test

namespace ochre::test::polarization_render_test {
namespace {

// Spectral Stokes layers (Fichet et al. 2021): S0..S3 per bin; light polarized along the image x axis has
// S1 = S0 and S2 = S3 = 0 in every bin; the handedness is declared in the header.
TEST(PolarizationRender, SpectralStokesLayersFollowTheSpectralLayout) {
  const Rendered r = render(polarized_lamp_scene("[1, 0, 0]", ""), "--stokes --spectral-bins 4");
  EXPECT_EQ(r.exr.string_attributes.at("polarisationHandedness"), "right");
  EXPECT_EQ(r.exr.string_attributes.at("spectralLayoutVersion"), "1.0");
  for (const char* bin : {"418,750000nm", "536,250000nm", "771,250000nm"}) {
    const double s0 = r.mean(std::string("S0.") + bin), s1 = r.mean(std::string("S1.") + bin);
    const double s2 = r.mean(std::string("S2.") + bin), s3 = r.mean(std::string("S3.") + bin);
    ASSERT_GT(s0, 0.0) << bin;
    EXPECT_NEAR(s1 / s0, 1.0, 1e-5) << bin;
    EXPECT_NEAR(s2 / s0, 0.0, 1e-6) << bin;
    EXPECT_NEAR(s3 / s0, 0.0, 1e-6) << bin;
  }
}

}  // namespace
}  // namespace ochre::test::polarization_render_test
