// Camera sensors (camera.sensor, docs/cameras.md): a grey wall in a uniform sky seen through a camera
// gives the sensor's integral (camera RGB) or the white-balanced colour; the infrared sensor records what
// lies beyond 830 nm; bad sensor fields are refused naming the file and the field.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <memory>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "renderer/image/exr_reader.h"
#include "spectra/blackbody_spectrum.h"
#include "spectra/cie.h"
#include "spectra/embedded_tables.h"
#include "spectra/sensor_response.h"
#include "spectra/tabulated_spectrum.h"
#include "support/test_paths.h"

namespace ochre::test::camera_sensors_test {
namespace {

// A grey (0.5) wall filling the view, in a uniform sky of `radiance`, seen through `sensor`.
std::string grey_wall(const std::string& sensor, const std::string& radiance) {
  return fmt::format(
      R"({{"camera": {{"type": "orthographic", "size": 1, "eye": [0, 0, 5], "target": [0, 0, 0]{}}},
          "film": {{"resolution": [8, 8]}}, "integrator": {{"spp": 256, "max_depth": 1}},
          "materials": {{"grey": {{"type": "lambert", "color": 0.5}}}},
          "lights": [{{"type": "environment", "radiance": {}}}],
          "shapes": [{{"type": "plane", "size": [4, 4], "material": "grey"}}]}})",
      sensor.empty() ? "" : ", \"sensor\": " + sensor, radiance);
}

std::array<double, 3> mean_rgb(const ExrImage& image) {
  return {mean_of(exr_channel(image, "R")), mean_of(exr_channel(image, "G")),
          mean_of(exr_channel(image, "B"))};
}

ExrImage render(const std::string& scene) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", scene);
  const CommandResult r = run_ochre("render scene.json -o out.exr -q", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return read_exr(dir / "out.exr");
}

// The infrared sensor behind its 720 nm filter, in a 1700 K sky: camera RGB = 0.5 x the sensor's integral of
// the (luminance-1) blackbody, most of which lies beyond 830 nm.
TEST(CameraSensors, InfraredSensorRecordsBeyondTheVisible) {
  const ExrImage image = render(grey_wall(R"("ir720_model")", R"({"blackbody": 1700})"));
  const CsvTable& t = embedded_table("sensor_ir720_model_10nm.csv");
  const SensorResponse sensor("ir", *tabulated_spectrum(t, "r", TableExtrapolation::kZero),
                              *tabulated_spectrum(t, "g", TableExtrapolation::kZero),
                              *tabulated_spectrum(t, "b", TableExtrapolation::kZero), 360, 1000);
  const XYZ expected =
      sensor.response_of(*normalized_to_unit_luminance(std::make_shared<BlackbodySpectrum>(1700.0f)));
  const auto m = mean_rgb(image);
  EXPECT_NEAR(m[0] / (0.5 * expected.x), 1.0, 0.01);
  EXPECT_NEAR(m[1] / (0.5 * expected.y), 1.0, 0.01);
  EXPECT_NEAR(m[2] / (0.5 * expected.z), 1.0, 0.01);
  // Camera RGB claims no chromaticities; the header names the sensor.
  EXPECT_FALSE(image.chromaticities.has_value());
  EXPECT_EQ(image.string_attributes.at("ochre.sensor"), "ir720_model");
  EXPECT_EQ(image.string_attributes.at("ochre.sensorOutput"), "camera_rgb");
}

// White-balanced to the sky's own spectrum, a grey wall is grey with the luminance the observer sees.
TEST(CameraSensors, WhiteBalancedGreyIsGrey) {
  for (const char* camera : {"canon_5d_mark_ii", "nokia_n900"}) {
    const ExrImage image =
        render(grey_wall(fmt::format(R"({{"name": "{}", "white_balance": {{"blackbody": 1700}}}})", camera),
                         R"({"blackbody": 1700})"));
    const auto m = mean_rgb(image);  // linear Rec.709; white (D65) is (1, 1, 1) at luminance 1
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[c], 0.5, 0.01) << camera << " channel " << c;
    EXPECT_EQ(image.string_attributes.at("ochre.sensorOutput"), "white_balanced");
  }
}

// The default sensor is the observer, and naming it changes nothing.
TEST(CameraSensors, NamedObserverIsTheDefault) {
  const ExrImage a = render(grey_wall("", R"({"blackbody": 1700})"));
  const ExrImage b = render(grey_wall(R"("cie1931")", R"({"blackbody": 1700})"));
  EXPECT_EQ(*a.find_channel("R"), *b.find_channel("R"));
  EXPECT_EQ(*a.find_channel("B"), *b.find_channel("B"));
  EXPECT_EQ(a.string_attributes.count("ochre.sensor"), 0u);
}

TEST(CameraSensors, CsvSensor) {
  const auto dir = scratch_dir();
  write_text(dir / "cam.csv",
             "wavelength,red,green,blue\n400,0,0,1\n500,0,1,0.5\n600,1,0.5,0\n700,0.5,0,0\n");
  write_text(
      dir / "scene.json",
      grey_wall(R"({"file": "cam.csv", "columns": ["red", "green", "blue"], "output": "camera_rgb"})", "1"));
  const CommandResult r = run_ochre("render scene.json -o out.exr -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // A constant radiance 1 gives G = 1 by definition; the wall reflects 0.5 of it.
  EXPECT_NEAR(mean_rgb(read_exr(dir / "out.exr"))[1], 0.5, 0.005);
}

TEST(CameraSensors, BadSensorFieldsAreNamed) {
  const BadCase cases[] = {
      {"unknown name",
       grey_wall(R"("canon_eos_r5")", "1"),
       {"camera.sensor.name", "unknown sensor", "nokia_n900"}},
      {"name and file", grey_wall(R"({"name": "nokia_n900", "file": "x.csv"})", "1"), {"camera.sensor"}},
      {"neither", grey_wall(R"({"output": "camera_rgb"})", "1"), {"camera.sensor", "exactly one"}},
      {"not a sensor", grey_wall("42", "1"), {"camera.sensor"}},
      {"missing file", grey_wall(R"({"file": "nope.csv"})", "1"), {"camera.sensor.file", "nope.csv"}},
      {"unknown output",
       grey_wall(R"({"name": "nokia_n900", "output": "raw"})", "1"),
       {"camera.sensor.output", "unknown output 'raw'"}},
      {"range of the observer",
       grey_wall(R"({"name": "cie1931", "range": [360, 1000]})", "1"),
       {"camera.sensor.range"}},
      {"output of the observer",
       grey_wall(R"({"name": "cie1931", "output": "camera_rgb"})", "1"),
       {"camera.sensor.output"}},
      {"range too wide",
       grey_wall(R"({"name": "ir720_model", "range": [360, 2000]})", "1"),
       {"camera.sensor.range[1]"}},
      {"range reversed",
       grey_wall(R"({"name": "ir720_model", "range": [900, 400]})", "1"),
       {"camera.sensor.range", "max must exceed min"}},
      {"negative white",
       grey_wall(R"({"name": "nokia_n900", "white_balance": -1})", "1"),
       {"camera.sensor.white_balance"}},
      {"unknown key", grey_wall(R"({"name": "nokia_n900", "gain": 2})", "1"), {"camera.sensor", "gain"}},
  };
  for (const BadCase& c : cases) expect_rejected(c);
}

TEST(CameraSensors, BadCsvSensorsAreNamed) {
  const auto dir = scratch_dir();
  write_text(dir / "two.csv", "wavelength,r,g\n400,1,1\n700,1,1\n");
  expect_rejected(
      {"too few columns", grey_wall(R"({"file": "two.csv"})", "1"), {"camera.sensor.file", "4 columns"}},
      dir);
  const auto dir2 = scratch_dir();
  write_text(dir2 / "cam.csv", "wavelength,r,g,b\n400,1,1,1\n700,1,1,1\n");
  expect_rejected({"unknown column",
                   grey_wall(R"({"file": "cam.csv", "columns": ["r", "green", "b"]})", "1"),
                   {"camera.sensor.file", "green"}},
                  dir2);
  const auto dir3 = scratch_dir();
  write_text(dir3 / "cam.csv", "wavelength,r,g,b\n400,1,0,1\n700,1,0,1\n");
  expect_rejected({"no green", grey_wall(R"({"file": "cam.csv"})", "1"), {"camera.sensor.file", "green"}},
                  dir3);
}

}  // namespace
}  // namespace ochre::test::camera_sensors_test
