#include "tools/fit/powder_fit_params.h"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "spectra/input_error.h"
#include "tools/cli/csv_columns.h"

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

PowderBounds powder_default_bounds() {
  PowderBounds bounds;
  for (int p = 0; p < kPowderFitParams; ++p)
    bounds[p] = {powder_fit_specs()[p].lower, powder_fit_specs()[p].upper};
  return bounds;
}

namespace {

// One "NAME=TEXT" item of `option`: the parameter and the text after '='.
std::pair<int, std::string> split_param_item(const std::string& item, std::string_view option) {
  const size_t equals = item.find('=');
  if (equals == std::string::npos)
    throw InputError(fmt::format("{} '{}': expected NAME=VALUE", option, item));
  const std::string name = item.substr(0, equals);
  std::string names;
  for (int p = 0; p < kPowderFitParams; ++p) {
    if (name == powder_fit_specs()[p].name) return {p, item.substr(equals + 1)};
    names += fmt::format("{}{}", p ? ", " : "", powder_fit_specs()[p].name);
  }
  throw InputError(
      fmt::format("{} '{}': unknown parameter '{}' (parameters: {})", option, item, name, names));
}

// The number `text` of a parameter, finite and in the model's domain.
double param_number(int param, const std::string& text, const std::string& item, std::string_view option) {
  const std::optional<double> number = finite_number(text);
  if (!number) throw InputError(fmt::format("{} '{}': '{}' is not a finite number", option, item, text));
  const FitParamSpec& s = powder_fit_specs()[param];
  if (!(*number >= s.domain_lower && *number <= s.domain_upper))
    throw InputError(
        fmt::format("{} '{}': {} must be in [{}, {}]", option, item, s.name, s.domain_lower, s.domain_upper));
  return *number;
}

}  // namespace

std::array<std::optional<double>, kPowderFitParams> parse_param_values(const std::vector<std::string>& items,
                                                                       std::string_view option) {
  std::array<std::optional<double>, kPowderFitParams> values;
  for (const std::string& item : items) {
    const auto [param, text] = split_param_item(item, option);
    if (values[param])
      throw InputError(fmt::format("{} '{}': parameter '{}' is given twice", option, item,
                                   powder_fit_specs()[param].name));
    values[param] = param_number(param, text, item, option);
  }
  return values;
}

std::array<std::optional<ParamBounds>, kPowderFitParams> parse_param_bounds(
    const std::vector<std::string>& items, std::string_view option) {
  std::array<std::optional<ParamBounds>, kPowderFitParams> bounds;
  for (const std::string& item : items) {
    const auto [param, text] = split_param_item(item, option);
    const char* name = powder_fit_specs()[param].name;
    if (bounds[param])
      throw InputError(fmt::format("{} '{}': parameter '{}' is given twice", option, item, name));
    const size_t colon = text.find(':');
    if (colon == std::string::npos)
      throw InputError(fmt::format("{} '{}': expected NAME=LOWER:UPPER", option, item));
    const double lower = param_number(param, text.substr(0, colon), item, option);
    const double upper = param_number(param, text.substr(colon + 1), item, option);
    if (!(lower < upper))
      throw InputError(
          fmt::format("{} '{}': the lower bound {} is not below the upper bound {} (to hold {} at a "
                      "value: --fix {}=VALUE)",
                      option, item, lower, upper, name, name));
    bounds[param] = ParamBounds{lower, upper};
  }
  return bounds;
}

}  // namespace ochre
