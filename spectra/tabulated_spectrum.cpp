// Piecewise-linear tabulated spectra and CSV loading (see tabulated_spectrum.h).

#include "spectra/tabulated_spectrum.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace ochre {

namespace {

void validate(const std::vector<float>& lambda, const std::vector<float>& values) {
  if (lambda.size() != values.size())
    throw std::invalid_argument("TabulatedSpectrum: " + std::to_string(lambda.size()) + " wavelengths but " +
                                std::to_string(values.size()) + " values");
  if (lambda.size() < 2) throw std::invalid_argument("TabulatedSpectrum: fewer than 2 points");
  for (std::size_t i = 0; i < lambda.size(); ++i) {
    if (!std::isfinite(lambda[i]) || !std::isfinite(values[i]))
      throw std::invalid_argument("TabulatedSpectrum: non-finite entry at index " + std::to_string(i));
    if (i > 0 && !(lambda[i] > lambda[i - 1]))
      throw std::invalid_argument("TabulatedSpectrum: wavelengths not strictly increasing at index " +
                                  std::to_string(i));
    // Interpolation takes the difference of neighbouring values: infinite, it would give NaN at a knot.
    if (i > 0 && !std::isfinite(values[i] - values[i - 1]))
      throw std::invalid_argument("TabulatedSpectrum: values at index " + std::to_string(i - 1) + " and " +
                                  std::to_string(i) + " differ by more than the float range");
  }
}

// Step of an equally spaced table, or 0 when the spacing varies.
float uniform_step(const std::vector<float>& lambda) {
  const double step = (double(lambda.back()) - lambda.front()) / double(lambda.size() - 1);
  for (std::size_t i = 0; i < lambda.size(); ++i)
    if (std::abs(lambda[i] - (lambda.front() + step * double(i))) > 1e-4 * step) return 0.0f;
  return static_cast<float>(step);
}

std::vector<float> to_float(const std::vector<double>& v) {
  return {v.begin(), v.end()};
}

}  // namespace

std::optional<TableExtrapolation> table_extrapolation_from_name(std::string_view name) {
  if (name == "clamp") return TableExtrapolation::kClamp;
  if (name == "zero") return TableExtrapolation::kZero;
  return std::nullopt;
}

TabulatedSpectrum::TabulatedSpectrum(std::vector<float> lambda_nm, std::vector<float> values,
                                     TableExtrapolation extrapolation)
    : lambda_(std::move(lambda_nm)), values_(std::move(values)) {
  validate(lambda_, values_);
  const bool clamp = extrapolation == TableExtrapolation::kClamp;
  below_ = clamp ? values_.front() : 0.0f;
  above_ = clamp ? values_.back() : 0.0f;
  uniform_step_ = uniform_step(lambda_);
  inverse_step_ = uniform_step_ > 0.0f ? 1.0f / uniform_step_ : 0.0f;
  // Constant over [360, 830] nm: equal values, and the same value wherever the range leaves the table.
  const float first = values_.front();
  is_constant_ = std::all_of(values_.begin(), values_.end(), [&](float v) { return v == first; }) &&
                 (lambda_.front() <= kLambdaMin || below_ == first) &&
                 (lambda_.back() >= kLambdaMax || above_ == first);
  // Piecewise linear: the maximum over [360, 830] is at a knot inside the range or at an end.
  max_value_ = std::max(eval(kLambdaMin), eval(kLambdaMax));
  for (std::size_t i = 0; i < lambda_.size(); ++i)
    if (lambda_[i] >= kLambdaMin && lambda_[i] <= kLambdaMax) max_value_ = std::max(max_value_, values_[i]);
}

float TabulatedSpectrum::eval(float lambda_nm) const {
  // Outside or at the ends (a rare branch); NaN takes the first one and gets a finite value.
  if (!(lambda_nm > lambda_.front())) return lambda_nm == lambda_.front() ? values_.front() : below_;
  if (lambda_nm >= lambda_.back()) return lambda_nm == lambda_.back() ? values_.back() : above_;
  if (uniform_step_ > 0.0f) return eval_uniform(lambda_nm);
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(lambda_.begin(), lambda_.end(), lambda_nm) -
                                                 lambda_.begin()) -
                        1;
  const float t = (lambda_nm - lambda_[i]) / (lambda_[i + 1] - lambda_[i]);
  return values_[i] + t * (values_[i + 1] - values_[i]);
}

float TabulatedSpectrum::eval_uniform(float lambda_nm) const {
  const float position = (lambda_nm - lambda_.front()) * inverse_step_;
  const int last = static_cast<int>(values_.size()) - 2;
  const int i = std::min(static_cast<int>(position), last);
  const float t = std::min(position - static_cast<float>(i), 1.0f);
  const float* v = values_.data() + i;
  return v[0] + t * (v[1] - v[0]);
}

SampledSpectrum TabulatedSpectrum::sample(const SampledWavelengths& lambda) const {
  SampledSpectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = TabulatedSpectrum::eval(lambda[i]);
  return s;
}

SpectrumPtr tabulated_spectrum(const CsvTable& table, std::size_t column, TableExtrapolation extrapolation) {
  if (column == 0)
    throw std::runtime_error(table.source() + ": column 0 holds the wavelengths, not spectrum values");
  return std::make_shared<TabulatedSpectrum>(to_float(table.wavelengths()), to_float(table.column(column)),
                                             extrapolation);
}

SpectrumPtr tabulated_spectrum(const CsvTable& table, std::string_view column,
                               TableExtrapolation extrapolation) {
  return tabulated_spectrum(table, table.column_index(column), extrapolation);
}

SpectrumPtr load_spectrum_csv(const std::filesystem::path& path) {
  return load_spectrum_csv(path, std::size_t{1});
}

SpectrumPtr load_spectrum_csv(const std::filesystem::path& path, std::string_view column,
                              TableExtrapolation extrapolation) {
  return tabulated_spectrum(CsvTable::load(path), column, extrapolation);
}

SpectrumPtr load_spectrum_csv(const std::filesystem::path& path, std::size_t column,
                              TableExtrapolation extrapolation) {
  return tabulated_spectrum(CsvTable::load(path), column, extrapolation);
}

}  // namespace ochre
