#include "tools/fit/powder_fit_params.h"

#include <fmt/format.h>

#include <cmath>

#include "renderer/input_error.h"
#include "tools/csv_columns.h"

namespace ochre {

const std::array<FitParamSpec, kPowderFitParams>& powder_fit_specs() {
  // Domains: A_v, A_s' >= 0; |g| < 1 as the powder node clamps it; the radius within the range the pigment
  // table covers (materials/lobes/powder/pigment_table.h), so a rendered material matches its fit.
  static const std::array<FitParamSpec, kPowderFitParams> specs = {{
      {"volume_amplitude", "", 0.0, 10.0, 0.0, 1e6, false, 1.0, 1.0},
      {"g", "", -0.95, 0.95, -0.99, 0.99, false, 1.0, 0.0},
      {"kappa", "1/um", 0.01, 50.0, 1e-6, 1e6, true, 1.0, 0.25},
      {"radius", "um", 0.005, 5.0, 0.002, 20.0, true, 1.0, 0.05},
      {"surface_amplitude", "um^2", 0.0, 1e-3, 0.0, 1.0, false, 1e-5, 3e-6},
      {"correlation_length", "um", 0.05, 50.0, 1e-6, 1e6, true, 1.0, 2.0},
  }};
  return specs;
}

PowderValues powder_default_values() {
  PowderValues v{};
  for (int p = 0; p < kPowderFitParams; ++p) v[p] = powder_fit_specs()[p].fallback;
  return v;
}

double to_coordinate(int param, double value) {
  const FitParamSpec& s = powder_fit_specs()[param];
  return s.logarithmic ? std::log(value) : value / s.scale;
}

double from_coordinate(int param, double coordinate) {
  const FitParamSpec& s = powder_fit_specs()[param];
  return s.logarithmic ? std::exp(coordinate) : coordinate * s.scale;
}

double value_per_coordinate(int param, double value) {
  const FitParamSpec& s = powder_fit_specs()[param];
  return s.logarithmic ? value : s.scale;
}

std::array<std::optional<double>, kPowderFitParams> parse_param_values(const std::vector<std::string>& items,
                                                                       std::string_view option) {
  std::array<std::optional<double>, kPowderFitParams> values;
  for (const std::string& item : items) {
    const size_t equals = item.find('=');
    if (equals == std::string::npos)
      throw InputError(fmt::format("{} '{}': expected NAME=VALUE", option, item));
    const std::string name = item.substr(0, equals), text = item.substr(equals + 1);
    int param = -1;
    std::string names;
    for (int p = 0; p < kPowderFitParams; ++p) {
      if (name == powder_fit_specs()[p].name) param = p;
      names += fmt::format("{}{}", p ? ", " : "", powder_fit_specs()[p].name);
    }
    if (param < 0)
      throw InputError(fmt::format("{} '{}': unknown parameter '{}' (parameters: {})", option, item, name, names));
    if (values[param])
      throw InputError(fmt::format("{} '{}': parameter '{}' is given twice", option, item, name));
    const std::optional<double> number = finite_number(text);
    if (!number) throw InputError(fmt::format("{} '{}': '{}' is not a finite number", option, item, text));
    const double value = *number;
    const FitParamSpec& s = powder_fit_specs()[param];
    if (!(value >= s.domain_lower && value <= s.domain_upper))
      throw InputError(fmt::format("{} '{}': {} must be in [{}, {}]", option, item, name, s.domain_lower,
                                   s.domain_upper));
    values[param] = value;
  }
  return values;
}

}  // namespace ochre
