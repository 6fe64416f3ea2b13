#pragma once
// TabulatedSpectrum: a spectrum given at increasing wavelengths, linear in between.
//
// Outside the table (TableExtrapolation, docs/scene-format.md, 'Spectra'):
// - kClamp (the default): the first/last entry is held. Measured reflectance and optical-constant
//   tables often stop at 400 or 700 nm, and a surface does not turn black at 399 nm.
// - kZero: the spectrum is 0, as other renderers read a published table (Mitsuba's irregular and
//   regular spectra are zero outside their range), e.g. a light measured only over 400-700 nm.
// At the table's end wavelengths both give the end values.
//
//   TabulatedSpectrum(std::vector<float> lambda_nm, std::vector<float> values, extrapolation)
//       (throws std::invalid_argument: sizes differ, fewer than 2 points, non-finite entries,
//        wavelengths not strictly increasing, neighbouring values that differ by more than the float range)
//   tabulated_spectrum(const CsvTable&, column[, extrapolation])  one column of a parsed table
//   load_spectrum_csv(path)                          first value column (column 1) of a CSV file
//   load_spectrum_csv(path, "name"[, extrapolation]) / (path, index[, extrapolation])
//                                                    a chosen column (index 0 is the wavelength)
// Errors from the loaders name the file (see csv_table.h).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "spectra/csv_table.h"
#include "spectra/spectrum.h"

namespace ochre {

enum class TableExtrapolation { kClamp, kZero };

// "clamp" / "zero" (the names scenes use), or nullopt for any other text.
std::optional<TableExtrapolation> table_extrapolation_from_name(std::string_view name);

class TabulatedSpectrum final : public Spectrum {
 public:
  TabulatedSpectrum(std::vector<float> lambda_nm, std::vector<float> values,
                    TableExtrapolation extrapolation = TableExtrapolation::kClamp);

  float eval(float lambda_nm) const override;
  // Every lane without a virtual call each (eval is inlined here: the class is final).
  SampledSpectrum sample(const SampledWavelengths& lambda) const override;
  // Exact maximum over [360, 830] nm (the table is piecewise linear).
  float max_value() const override { return max_value_; }
  bool is_constant() const override { return is_constant_; }

  const std::vector<float>& wavelengths() const { return lambda_; }
  const std::vector<float>& values() const { return values_; }

 private:
  std::vector<float> lambda_;
  std::vector<float> values_;
  // Values below the first and above the last wavelength (the end values, or 0).
  float below_ = 0.0f, above_ = 0.0f;
  float max_value_ = 0.0f;
  bool is_constant_ = false;
  // Equally spaced tables (the common case) are indexed directly instead of searched.
  float uniform_step_ = 0.0f;
  float inverse_step_ = 0.0f;
  // Value of an equally spaced table: position in steps from the first knot, no division, no search
  // (the interpolation weight is the fractional position, equal to the one from the stored knots up to
  // rounding). The caller has handled wavelengths outside the table.
  float eval_uniform(float lambda_nm) const;
};

SpectrumPtr tabulated_spectrum(const CsvTable& table, std::size_t column,
                               TableExtrapolation extrapolation = TableExtrapolation::kClamp);
SpectrumPtr tabulated_spectrum(const CsvTable& table, std::string_view column,
                               TableExtrapolation extrapolation = TableExtrapolation::kClamp);
SpectrumPtr load_spectrum_csv(const std::filesystem::path& path);
SpectrumPtr load_spectrum_csv(const std::filesystem::path& path, std::string_view column,
                              TableExtrapolation extrapolation = TableExtrapolation::kClamp);
SpectrumPtr load_spectrum_csv(const std::filesystem::path& path, std::size_t column,
                              TableExtrapolation extrapolation = TableExtrapolation::kClamp);

}  // namespace ochre
