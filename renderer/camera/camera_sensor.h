#pragma once
// `camera.sensor` (docs/cameras.md): which spectral response the film records, and how its values become
// the EXR's RGB.
//
//   "sensor": "canon_5d_mark_ii"
//   "sensor": {"name": "nokia_n900", "output": "white_balanced", "white_balance": {"blackbody": 1700}}
//   "sensor": {"file": "my_camera.csv", "columns": ["r", "g", "b"], "range": [380, 1000],
//              "output": "camera_rgb"}
//
// Named sensors: cie1931 (the default: the CIE 1931 observer, XYZ), canon_5d_mark_ii and nokia_n900
// (Jiang et al. 2013, measured), ir720_model (a modelled full-spectrum camera behind a 720 nm IR-pass
// filter, 360-1000 nm). Errors name the file and the field.

#include <filesystem>
#include <optional>
#include <string>

#include "renderer/json/json_fields.h"
#include "spectra/mat3.h"
#include "spectra/sensor_response.h"

namespace ochre {

struct CameraSensor {
  SensorPtr response;                 // nullptr: the CIE 1931 observer (the film holds XYZ)
  bool camera_rgb = false;            // write the sensor's R, G, B as they are
  std::optional<Mat3> sensor_to_xyz;  // white balance and colour correction (spectra/white_balance.h)
  std::string name = "cie1931";
};

// The known sensor names, "cie1931, canon_5d_mark_ii, ...", for messages and docs.
std::string sensor_names();

// Reads `camera.sensor` of the camera object `camera` (absent: the observer). Paths relative to scene_dir.
CameraSensor parse_camera_sensor(const JsonFields& camera, const std::filesystem::path& scene_dir);

}  // namespace ochre
