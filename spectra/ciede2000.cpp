#include "spectra/ciede2000.h"

#include <cmath>
#include <numbers>

namespace ochre {

namespace {

constexpr double kPi = std::numbers::pi;

double degrees(double radians) {
  return radians * 180.0 / kPi;
}
double radians(double degrees) {
  return degrees * kPi / 180.0;
}

// The cube-root companding of CIE 1976 with its linear segment near black (CIE 15:2004, eq. 8.2).
double lab_f(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

// Hue angle in degrees in [0, 360); 0 for an achromatic colour (Sharma et al. eq. 4).
double hue_degrees(double b, double a_prime) {
  if (b == 0.0 && a_prime == 0.0) return 0.0;
  const double h = degrees(std::atan2(b, a_prime));
  return h < 0.0 ? h + 360.0 : h;
}

// C' and h' of one colour after the a* rescaling by G (Sharma et al. eqs. 2-4).
struct ChromaHue {
  double chroma, hue;
};
ChromaHue chroma_hue(const Lab& lab, double g) {
  const double a_prime = (1.0 + g) * lab.a;
  return {std::hypot(a_prime, lab.b), hue_degrees(lab.b, a_prime)};
}

// Delta h' (eq. 10): the signed hue difference, 0 when either colour is achromatic.
double hue_difference(const ChromaHue& first, const ChromaHue& second) {
  if (first.chroma * second.chroma == 0.0) return 0.0;
  const double dh = second.hue - first.hue;
  if (dh > 180.0) return dh - 360.0;
  if (dh < -180.0) return dh + 360.0;
  return dh;
}

// Mean hue h-bar' (eq. 14): the sum when either colour is achromatic.
double mean_hue(const ChromaHue& first, const ChromaHue& second) {
  const double sum = first.hue + second.hue;
  if (first.chroma * second.chroma == 0.0) return sum;
  if (std::abs(first.hue - second.hue) <= 180.0) return sum / 2.0;
  return sum < 360.0 ? (sum + 360.0) / 2.0 : (sum - 360.0) / 2.0;
}

}  // namespace

Lab xyz_to_lab(const XyzD& xyz, const XyzD& white) {
  const double fx = lab_f(xyz.x / white.x);
  const double fy = lab_f(xyz.y / white.y);
  const double fz = lab_f(xyz.z / white.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// IEC 61966-2-1:1999 (sRGB), linear RGB -> XYZ matrix, D65 white.
XyzD linear_srgb_to_xyz(double r, double g, double b) {
  return {0.4124 * r + 0.3576 * g + 0.1805 * b,  //
          0.2126 * r + 0.7152 * g + 0.0722 * b,  //
          0.0193 * r + 0.1192 * g + 0.9505 * b};
}

XyzD srgb_d65_white() {
  return linear_srgb_to_xyz(1.0, 1.0, 1.0);
}

double ciede2000(const Lab& first, const Lab& second, double kL, double kC, double kH) {
  // Eqs. 2-3: rescale a* so that near-neutral colours get a hue that matches perception.
  const double mean_chroma_ab = (std::hypot(first.a, first.b) + std::hypot(second.a, second.b)) / 2.0;
  const double c7 = std::pow(mean_chroma_ab, 7.0);
  const double g = 0.5 * (1.0 - std::sqrt(c7 / (c7 + std::pow(25.0, 7.0))));
  const ChromaHue ch1 = chroma_hue(first, g);
  const ChromaHue ch2 = chroma_hue(second, g);

  // Eqs. 8-11: differences in lightness, chroma and hue.
  const double dL = second.L - first.L;
  const double dC = ch2.chroma - ch1.chroma;
  const double dH =
      2.0 * std::sqrt(ch1.chroma * ch2.chroma) * std::sin(radians(hue_difference(ch1, ch2)) / 2.0);

  // Eqs. 12-21: weighting functions and the rotation term.
  const double L_mean = (first.L + second.L) / 2.0;
  const double C_mean = (ch1.chroma + ch2.chroma) / 2.0;
  const double h_mean = mean_hue(ch1, ch2);
  const double t = 1.0 - 0.17 * std::cos(radians(h_mean - 30.0)) + 0.24 * std::cos(radians(2.0 * h_mean)) +
                   0.32 * std::cos(radians(3.0 * h_mean + 6.0)) -
                   0.20 * std::cos(radians(4.0 * h_mean - 63.0));
  const double d_theta = 30.0 * std::exp(-std::pow((h_mean - 275.0) / 25.0, 2.0));
  const double C_mean7 = std::pow(C_mean, 7.0);
  const double r_c = 2.0 * std::sqrt(C_mean7 / (C_mean7 + std::pow(25.0, 7.0)));
  const double l50 = (L_mean - 50.0) * (L_mean - 50.0);
  const double s_l = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
  const double s_c = 1.0 + 0.045 * C_mean;
  const double s_h = 1.0 + 0.015 * C_mean * t;
  const double r_t = -std::sin(radians(2.0 * d_theta)) * r_c;

  // Eq. 22.
  const double l_term = dL / (kL * s_l);
  const double c_term = dC / (kC * s_c);
  const double h_term = dH / (kH * s_h);
  return std::sqrt(l_term * l_term + c_term * c_term + h_term * h_term + r_t * c_term * h_term);
}

}  // namespace ochre
