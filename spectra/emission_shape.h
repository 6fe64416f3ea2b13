#pragma once
// The shape of an emission spectrum, for relighting a render's light groups with another spectrum
// (docs/lights.md, "Relighting").
//
// A shape is the spectrum at 360, 361, ..., 830 nm divided by its luminance (spectrum_to_xyz(s).y), so that
// two shapes compare whatever the light's intensity. A change of spectrum keeps the group's luminance, as a
// scene's {"blackbody": T} and a flame's candela do. A group kept per spectral bin is relit bin by bin: the
// light that reached the film through wavelengths of bin b scales by the ratio of the new shape's integral
// over the bin (the shape linear between its samples) to the old one's. That is exact when the ratio is
// constant over each bin (a change of intensity) and converges as the bins narrow.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "spectra/spectrum.h"

namespace ochre {

inline constexpr int kEmissionShapeFirstNm = 360;
inline constexpr int kEmissionShapeCount = 471;  // 360..830 nm

// The shape of `s`; nullopt when its luminance is not positive and finite.
std::optional<std::vector<double>> emission_shape(const Spectrum& s);
// True when the shapes are equal to `tolerance` relative to their largest value.
bool same_emission_shape(const std::vector<double>& a, const std::vector<double>& b, double tolerance = 1e-5);

// A shape as the text of an EXR attribute (471 numbers separated by spaces), and back (nullopt when the text
// is not 471 finite numbers >= 0).
std::string format_emission_shape(const std::vector<double>& shape);
std::optional<std::vector<double>> parse_emission_shape(std::string_view text);

// For each of `bins` equal bins over [lambda_min, lambda_max] nm, the integral of `to` over the bin divided
// by that of `from` (0 where `from` is 0 over the bin). The first and last bins reach down to 360 and up to
// 830 nm: a film's group bins hold the wavelengths outside its range there.
std::vector<double> emission_bin_ratios(const std::vector<double>& from, const std::vector<double>& to,
                                        int bins, double lambda_min, double lambda_max);

// The same per X, Y and Z of a bin's light: the integrals over the bin of each shape times the
// colour-matching function xbar, ybar or zbar (cie.h). Light reaching the film through a bin is weighed by
// the colour-matching functions within it, so these ratios follow a change of spectrum inside wide bins far
// better. A component whose old integral is below 1e-9 of the bin's plain integral (no response there) takes
// the plain ratio.
std::vector<std::array<double, 3>> emission_bin_ratios_xyz(const std::vector<double>& from,
                                                           const std::vector<double>& to, int bins,
                                                           double lambda_min, double lambda_max);

}  // namespace ochre
