#pragma once
// ochre-fit's input: BRDF measurements as a CSV (docs/tools.md, ochre-fit) with the columns theta_i, phi_i,
// theta_o, phi_o (degrees: polar angles from the normal, azimuths about it), lambda_nm and brdf (1/sr), in
// any order, '#' comment lines allowed. The angles become unit vectors of the local frame (z = normal),
// wi towards the light and wo towards the viewer, both above the surface.

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace ochre {

inline constexpr std::array<const char*, 6> kMeasurementColumns = {"theta_i", "phi_i",     "theta_o",
                                                                   "phi_o",   "lambda_nm", "brdf"};

struct Direction {
  double x = 0, y = 0, z = 1;
};

// The unit vector at polar angle theta and azimuth phi (degrees).
Direction direction_from_angles(double theta_deg, double phi_deg);

struct Measurement {
  double theta_i = 0, phi_i = 0, theta_o = 0, phi_o = 0;  // degrees
  double lambda_nm = 700;
  double brdf = 0;  // 1/sr
  Direction wi, wo;
  int line = 0;  // in the file (0: not read from a file)
};

// Throws InputError "FILE: line N: column C: ..." for a malformed file (csv_columns.h), a polar angle
// outside [0, 90) degrees, an azimuth outside [-360, 360] degrees, a wavelength outside ochre's spectral
// range [360, 830] nm, a negative brdf, or no measurement.
std::vector<Measurement> read_measurements(const std::filesystem::path& file);

// The six columns of a measurement, formatted to round-trip (for the synthetic data and the fit CSV).
std::string measurement_fields(const Measurement& m);

}  // namespace ochre
