#include "tools/vgroove/vgroove_inputs.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "spectra/input_error.h"
#include "spectra/sampled_wavelengths.h"

namespace ochre {

namespace {

struct NamedModel {
  std::string_view name;
  ChainModel model;
};
constexpr NamedModel kModels[] = {{"rigorous", ChainModel::kRigorous},
                                  {"unpolarized", ChainModel::kUnpolarized},
                                  {"sp", ChainModel::kSeparateSP},
                                  {"paper_literal", ChainModel::kPaperLiteral}};

}  // namespace

std::vector<std::string_view> split_list(std::string_view option, std::string_view text) {
  if (text.empty()) throw InputError(fmt::format("{}: give at least one value", option));
  std::vector<std::string_view> items;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string_view item =
        text.substr(start, comma == std::string_view::npos ? text.npos : comma - start);
    if (item.empty()) throw InputError(fmt::format("{}: empty item in '{}'", option, text));
    items.push_back(item);
    if (comma == std::string_view::npos) return items;
    start = comma + 1;
  }
}

std::vector<double> parse_number_list(std::string_view option, std::string_view text) {
  std::vector<double> values;
  for (std::string_view item : split_list(option, text)) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (error != std::errc() || end != item.data() + item.size() || !std::isfinite(value))
      throw InputError(fmt::format("{}: '{}' is not a finite number", option, item));
    values.push_back(value);
  }
  return values;
}

std::vector<ChainModel> parse_models(std::string_view option, std::string_view text) {
  std::vector<ChainModel> models;
  for (std::string_view item : split_list(option, text)) {
    const NamedModel* found = nullptr;
    for (const NamedModel& m : kModels)
      if (m.name == item) found = &m;
    if (!found)
      throw InputError(fmt::format("{}: unknown model '{}' (known: rigorous, unpolarized, sp, paper_literal)",
                                   option, item));
    models.push_back(found->model);
  }
  return models;
}

std::string_view model_name(ChainModel model) {
  for (const NamedModel& m : kModels)
    if (m.model == model) return m.name;
  return "unknown";
}

void check_alphas(std::string_view option, const std::vector<double>& alphas_deg) {
  for (double a : alphas_deg)
    if (!(a > 0.0 && a <= 180.0))
      throw InputError(fmt::format("{}: dihedral angle {} is outside (0, 180] degrees", option, a));
}

void check_thetas(std::string_view option, const std::vector<double>& thetas_deg) {
  for (double t : thetas_deg)
    if (!(t >= 0.0 && t < 90.0))
      throw InputError(fmt::format("{}: polar angle {} is outside [0, 90) degrees", option, t));
}

void check_wavelengths(std::string_view option, const std::vector<double>& wavelengths_nm) {
  for (double w : wavelengths_nm)
    if (!(w >= kLambdaMin && w <= kLambdaMax))
      throw InputError(fmt::format("{}: {} nm is outside the spectral range [{}, {}] nm", option, w,
                                   kLambdaMin, kLambdaMax));
}

void check_reflection_limit(std::string_view option, int limit) {
  if (limit < 0)
    throw InputError(
        fmt::format("{}: {} is negative (0 = no limit, else a count of 1 or more)", option, limit));
}

}  // namespace ochre
