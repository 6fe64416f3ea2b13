#include "renderer/camera/camera_sensor.h"

#include <fmt/format.h>

#include "renderer/json/spectrum_json.h"
#include "spectra/cie.h"
#include "spectra/embedded_tables.h"
#include "spectra/tabulated_spectrum.h"
#include "spectra/white_balance.h"

namespace ochre {

namespace {

// Wavelengths a sensor may cover: silicon responds from the near UV to about 1100 nm.
constexpr double kMinSensorNm = 300.0, kMaxSensorNm = 1200.0;

struct NamedSensor {
  std::string_view name;
  std::string_view table;  // embedded CSV with columns r, g, b ("" for the observer)
  bool camera_rgb_default;
};

constexpr NamedSensor kSensors[] = {
    {"cie1931", "", false},
    {"canon_5d_mark_ii", "camera_canon_5d_mark_ii_10nm.csv", false},
    {"nokia_n900", "camera_nokia_n900_10nm.csv", false},
    {"ir720_model", "sensor_ir720_model_10nm.csv", true},
};

SensorPtr sensor_from_table(const std::string& name, const CsvTable& table, const std::string columns[3],
                            float lo, float hi) {
  const SpectrumPtr r = tabulated_spectrum(table, columns[0], TableExtrapolation::kZero);
  const SpectrumPtr g = tabulated_spectrum(table, columns[1], TableExtrapolation::kZero);
  const SpectrumPtr b = tabulated_spectrum(table, columns[2], TableExtrapolation::kZero);
  return std::make_shared<SensorResponse>(name, *r, *g, *b, lo, hi);
}

// Runs `load` turning a CSV error (std::runtime_error naming the file) into std::invalid_argument, which
// JsonFields::in_context reports as bad input of the field.
template <class Load>
auto as_input_error(Load&& load) {
  try {
    return load();
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
}

const NamedSensor& named_sensor(const JsonFields& f, const char* key, const std::string& name) {
  for (const NamedSensor& s : kSensors)
    if (s.name == name) return s;
  f.fail(key, fmt::format("unknown sensor '{}' (known: {})", name, sensor_names()));
}

}  // namespace

std::string sensor_names() {
  std::string names;
  for (const NamedSensor& s : kSensors) names += (names.empty() ? "" : ", ") + std::string(s.name);
  return names;
}

CameraSensor parse_camera_sensor(const JsonFields& camera, const std::filesystem::path& scene_dir) {
  CameraSensor sensor;
  if (!camera.has("sensor")) return sensor;
  const nlohmann::json& value = camera.require("sensor");
  nlohmann::json object = value.is_string() ? nlohmann::json{{"name", value}} : value;
  if (!object.is_object()) camera.fail("sensor", "expected a sensor name or an object");
  const JsonFields f(value.is_string() ? object : value, camera.child("sensor"));
  f.check_known({"name", "file", "columns", "range", "output", "white_balance"});
  if (f.has("name") == f.has("file")) f.fail("", "give exactly one of \"name\" or \"file\"");

  bool camera_rgb_default = false;
  float lo = 0.0f, hi = 0.0f;
  std::optional<CsvTable> table;
  std::string columns[3] = {"r", "g", "b"};
  if (f.has("name")) {
    const NamedSensor& named = named_sensor(f, "name", f.required_string("name"));
    sensor.name = std::string(named.name);
    camera_rgb_default = named.camera_rgb_default;
    if (!named.table.empty()) table = embedded_table(named.table);
  } else {
    std::filesystem::path path = f.required_string("file");
    if (path.is_relative()) path = scene_dir / path;
    table = f.in_context("file", [&] { return as_input_error([&] { return CsvTable::load(path); }); });
    sensor.name = path.filename().string();
    if (f.has("columns")) {
      const nlohmann::json& c =
          json_array(f.require("columns"), f.child("columns"), 3, "[r, g, b] column names");
      for (int i = 0; i < 3; ++i)
        columns[i] = json_string(c[i], fmt::format("{}[{}]", f.child("columns"), i));
    } else if (table->column_count() != 4) {
      f.fail("file",
             fmt::format("expected 4 columns (wavelength, r, g, b), got {}; name them with \"columns\"",
                         table->column_count()));
    } else {
      for (int i = 0; i < 3; ++i)
        columns[i] = table->header().empty() ? std::to_string(i + 1) : table->header()[i + 1];
    }
  }
  if (table) {
    lo = table->wavelengths().front();
    hi = table->wavelengths().back();
  }
  if (f.has("range")) {
    const std::string where = f.child("range");
    const nlohmann::json& r = json_array(f.require("range"), where, 2, "[min, max] in nm");
    lo = static_cast<float>(json_number(r[0], where + "[0]", kMinSensorNm, kMaxSensorNm));
    hi = static_cast<float>(json_number(r[1], where + "[1]", kMinSensorNm, kMaxSensorNm));
    if (!(hi >= lo + 10.0f))
      f.fail("range", fmt::format("max must exceed min by at least 10 nm (got [{}, {}])", lo, hi));
    if (!table) f.fail("range", "the CIE 1931 observer covers 360-830 nm: a range needs a camera sensor");
  }
  const std::string output = f.string("output", camera_rgb_default ? "camera_rgb" : "white_balanced");
  if (output != "camera_rgb" && output != "white_balanced")
    f.fail("output", fmt::format("unknown output '{}' (known: white_balanced, camera_rgb)", output));
  SpectrumPtr white = d65();
  if (f.has("white_balance"))
    white = parse_spectrum(f.require("white_balance"), SpectrumRole::Illuminant, f.child("white_balance"),
                           scene_dir);
  if (!table) {  // the observer
    if (f.has("output") || f.has("white_balance"))
      f.fail(f.has("output") ? "output" : "white_balance",
             "applies to camera sensors (the CIE observer gives XYZ)");
    return sensor;
  }
  if (!(lo >= kMinSensorNm && hi <= kMaxSensorNm))
    f.fail(f.has("file") ? "file" : "name",
           fmt::format(
               "the sensor's table covers [{}, {}] nm; sensors cover at most [{}, {}] nm (set \"range\")", lo,
               hi, kMinSensorNm, kMaxSensorNm));
  sensor.response = f.in_context(f.has("file") ? "file" : "name", [&] {
    return as_input_error([&] { return sensor_from_table(sensor.name, *table, columns, lo, hi); });
  });
  sensor.camera_rgb = output == "camera_rgb";
  if (!sensor.camera_rgb)
    sensor.sensor_to_xyz = f.in_context("white_balance", [&] {
      try {
        return white_balance_matrix(*sensor.response, white);
      } catch (const std::exception& e) {
        throw std::invalid_argument(
            fmt::format("no white balance for this sensor and illuminant ({})", e.what()));
      }
    });
  return sensor;
}

}  // namespace ochre
