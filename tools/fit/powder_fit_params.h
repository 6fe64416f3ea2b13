#pragma once
// The six parameters ochre-fit fits for the dry-powder BRDF (materials/lobes/powder/powder_model.h), named
// as the powder node's inputs, with the default bounds of the fit (docs/tools.md, ochre-fit; --bounds
// overrides them) and the values the model accepts (for --fix, --start, --bounds and --params). kappa, radius
// and correlation_length span decades and are fitted as their logarithms; the others linearly,
// surface_amplitude in units of 1e-5 um^2 so that every fitted coordinate moves the BRDF by comparable
// amounts.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ochre {

enum PowderFitParam : int {
  kVolumeAmplitude,
  kAnisotropy,
  kKappa,
  kRadius,
  kSurfaceAmplitude,
  kCorrelationLength,
};
inline constexpr int kPowderFitParams = 6;

using PowderValues = std::array<double, kPowderFitParams>;

struct FitParamSpec {
  const char* name;
  const char* unit;                   // "" for none
  double lower, upper;                // default bounds of the fit
  double domain_lower, domain_upper;  // values the model accepts (inclusive)
  bool logarithmic;                   // fitted as log(value)
  double scale;                       // linear parameters: fitted as value / scale
  double fallback;                    // the powder node's default
};

const std::array<FitParamSpec, kPowderFitParams>& powder_fit_specs();

struct ParamBounds {
  double lower = 0, upper = 0;
};
using PowderBounds = std::array<ParamBounds, kPowderFitParams>;

// The default bounds of every parameter (powder_fit_specs()).
PowderBounds powder_default_bounds();

// The powder node's defaults (the default material).
PowderValues powder_default_values();

// Fitted coordinate <-> value, and d value / d coordinate.
double to_coordinate(int param, double value);
double from_coordinate(int param, double coordinate);
double value_per_coordinate(int param, double value);

// "NAME=VALUE" items (from --fix, --start or --params) to values by parameter. Throws InputError naming
// `option` and the item: not NAME=VALUE, unknown name (the names are listed), a value that is not a
// finite number or is outside the model's domain, a name given twice.
std::array<std::optional<double>, kPowderFitParams> parse_param_values(const std::vector<std::string>& items,
                                                                       std::string_view option);

// "NAME=LO:HI" items (from --bounds): the bounds given, by parameter. Throws InputError naming `option`
// and the item, as parse_param_values does, and for LO >= HI.
std::array<std::optional<ParamBounds>, kPowderFitParams> parse_param_bounds(
    const std::vector<std::string>& items, std::string_view option);

}  // namespace ochre
