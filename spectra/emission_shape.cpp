#include "spectra/emission_shape.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "spectra/cie.h"

namespace ochre {

std::optional<std::vector<double>> emission_shape(const Spectrum& s) {
  const double luminance = spectrum_to_xyz(s).y;
  if (!(luminance > 0.0) || !std::isfinite(luminance)) return std::nullopt;
  std::vector<double> shape(kEmissionShapeCount);
  for (int i = 0; i < kEmissionShapeCount; ++i)
    shape[i] = s.eval(static_cast<float>(kEmissionShapeFirstNm + i)) / luminance;
  return shape;
}

bool same_emission_shape(const std::vector<double>& a, const std::vector<double>& b, double tolerance) {
  if (a.size() != b.size()) return false;
  double largest = 0.0;
  for (size_t i = 0; i < a.size(); ++i) largest = std::max({largest, std::fabs(a[i]), std::fabs(b[i])});
  for (size_t i = 0; i < a.size(); ++i)
    if (!(std::fabs(a[i] - b[i]) <= tolerance * largest)) return false;
  return true;
}

std::string format_emission_shape(const std::vector<double>& shape) {
  std::string text;
  char number[32];
  for (const double v : shape) {
    const auto result = std::to_chars(number, number + sizeof number, v, std::chars_format::general, 9);
    if (!text.empty()) text += ' ';
    text.append(number, result.ptr);
  }
  return text;
}

std::optional<std::vector<double>> parse_emission_shape(std::string_view text) {
  std::vector<double> shape;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = std::min(text.find(' ', start), text.size());
    double v = 0.0;
    const auto [last, error] = std::from_chars(text.data() + start, text.data() + end, v);
    if (error != std::errc() || last != text.data() + end || !std::isfinite(v) || v < 0.0)
      return std::nullopt;
    shape.push_back(v);
    if (shape.size() > kEmissionShapeCount) return std::nullopt;
    start = end + 1;
  }
  if (shape.size() != kEmissionShapeCount) return std::nullopt;
  return shape;
}

namespace {

constexpr double kFirst = kEmissionShapeFirstNm, kLast = kEmissionShapeFirstNm + kEmissionShapeCount - 1;

// The shape read as linear between its 1 nm samples.
double shape_at(const std::vector<double>& shape, double lambda) {
  const double x = std::clamp(lambda - kFirst, 0.0, double(kEmissionShapeCount - 1));
  const int i = std::min(static_cast<int>(x), kEmissionShapeCount - 2);
  const size_t k = static_cast<size_t>(i);
  return shape[k] + (x - i) * (shape[k + 1] - shape[k]);
}

// The integral over [a, b] nm (within 360..830) of the shape times `weight`: trapezoids between a, the sample
// wavelengths inside (a, b), and b (exact for the shape's linear pieces when the weight is 1).
template <class Weight>
double shape_integral(const std::vector<double>& shape, double a, double b, const Weight& weight) {
  double sum = 0.0, left = a;
  for (double knot = std::floor(a) + 1.0; left < b; knot += 1.0) {
    const double right = std::min(knot, b);
    sum += 0.5 * (shape_at(shape, left) * weight(left) + shape_at(shape, right) * weight(right)) *
           (right - left);
    left = right;
  }
  return sum;
}

double unweighted(double) {
  return 1.0;
}

// Bin b of `bins` over [lambda_min, lambda_max], the first and last reaching to 360 and 830 nm (as
// Film::group_bin counts a wavelength outside the range in them).
std::pair<double, double> bin_edges(int b, int bins, double lambda_min, double lambda_max) {
  const double width = (lambda_max - lambda_min) / bins;
  const double a = b == 0 ? kFirst : std::clamp(lambda_min + b * width, kFirst, kLast);
  const double c = b == bins - 1 ? kLast : std::clamp(lambda_min + (b + 1) * width, kFirst, kLast);
  return {a, c};
}

}  // namespace

std::vector<double> emission_bin_ratios(const std::vector<double>& from, const std::vector<double>& to,
                                        int bins, double lambda_min, double lambda_max) {
  std::vector<double> ratios(static_cast<size_t>(bins), 0.0);
  for (int b = 0; b < bins; ++b) {
    const auto [a, c] = bin_edges(b, bins, lambda_min, lambda_max);
    const double old_integral = shape_integral(from, a, c, unweighted);
    if (old_integral > 0.0)
      ratios[static_cast<size_t>(b)] = shape_integral(to, a, c, unweighted) / old_integral;
  }
  return ratios;
}

std::vector<std::array<double, 3>> emission_bin_ratios_xyz(const std::vector<double>& from,
                                                           const std::vector<double>& to, int bins,
                                                           double lambda_min, double lambda_max) {
  const std::vector<double> plain = emission_bin_ratios(from, to, bins, lambda_min, lambda_max);
  const auto cmf = [](int k) {
    return [k](double lambda) {
      const float l = static_cast<float>(lambda);
      return static_cast<double>(k == 0 ? cie_x(l) : k == 1 ? cie_y(l) : cie_z(l));
    };
  };
  std::vector<std::array<double, 3>> ratios(static_cast<size_t>(bins));
  for (int b = 0; b < bins; ++b) {
    const auto [a, c] = bin_edges(b, bins, lambda_min, lambda_max);
    const double whole = shape_integral(from, a, c, unweighted);
    for (int k = 0; k < 3; ++k) {
      const double old_integral = shape_integral(from, a, c, cmf(k));
      ratios[static_cast<size_t>(b)][static_cast<size_t>(k)] =
          old_integral > 1e-9 * whole ? shape_integral(to, a, c, cmf(k)) / old_integral
                                      : plain[static_cast<size_t>(b)];
    }
  }
  return ratios;
}

}  // namespace ochre
