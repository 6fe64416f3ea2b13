#include "tools/fit/measurements.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "spectra/input_error.h"
#include "spectra/sampled_wavelengths.h"
#include "tools/cli/csv_columns.h"

namespace ochre {

namespace {

void check_polar(double theta, const char* column, const std::string& where) {
  if (!(theta >= 0.0 && theta < 90.0))
    throw InputError(fmt::format("{}: column {}: {} is outside [0, 90) degrees", where, column, theta));
}

// Any azimuth names a direction; beyond one turn either way it is more likely radians or a wrong column.
void check_azimuth(double phi, const char* column, const std::string& where) {
  if (!(phi >= -360.0 && phi <= 360.0))
    throw InputError(fmt::format("{}: column {}: {} is outside [-360, 360] degrees", where, column, phi));
}

}  // namespace

Direction direction_from_angles(double theta_deg, double phi_deg) {
  const double t = theta_deg * std::numbers::pi / 180.0, p = phi_deg * std::numbers::pi / 180.0;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

std::vector<Measurement> read_measurements(const std::filesystem::path& file) {
  const CsvColumns csv = read_csv_columns(file, kMeasurementColumns);
  std::vector<Measurement> measurements;
  for (const CsvRecord& record : csv.records) {
    const std::string where = fmt::format("{}: line {}", file.string(), record.line);
    const std::vector<double>& v = record.values;
    Measurement m;
    m.theta_i = v[0];
    m.phi_i = v[1];
    m.theta_o = v[2];
    m.phi_o = v[3];
    m.lambda_nm = v[4];
    m.brdf = v[5];
    check_polar(m.theta_i, "theta_i", where);
    check_polar(m.theta_o, "theta_o", where);
    check_azimuth(m.phi_i, "phi_i", where);
    check_azimuth(m.phi_o, "phi_o", where);
    if (!(m.brdf >= 0.0))
      throw InputError(fmt::format("{}: column brdf: {} is negative (a BRDF is >= 0)", where, m.brdf));
    if (!(m.lambda_nm >= kLambdaMin && m.lambda_nm <= kLambdaMax))
      throw InputError(
          fmt::format("{}: column lambda_nm: {} nm is outside ochre's spectral range [{}, {}] nm", where,
                      m.lambda_nm, kLambdaMin, kLambdaMax));
    m.wi = direction_from_angles(m.theta_i, m.phi_i);
    m.wo = direction_from_angles(m.theta_o, m.phi_o);
    m.line = record.line;
    measurements.push_back(std::move(m));
  }
  if (measurements.empty())
    throw InputError(fmt::format("{}: no measurements (a header line and no data)", file.string()));
  return measurements;
}

std::string measurement_fields(const Measurement& m) {
  return fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}", m.theta_i, m.phi_i, m.theta_o, m.phi_o,
                     m.lambda_nm, m.brdf);
}

}  // namespace ochre
