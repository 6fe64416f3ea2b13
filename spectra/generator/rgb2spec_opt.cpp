// ochre_rgb2spec_opt: build-time generator of the RGB -> spectrum coefficient table for linear
// Rec.709 / sRGB primaries (Jakob & Hanika 2019, "A Low-Dimensional Function Space for Efficient
// Spectral Upsampling", Computer Graphics Forum 38(2), sections 3-4). Not part of the library.
//
// Usage: ochre_rgb2spec_opt CIE_1NM_CSV D65_CSV RESOLUTION OUTPUT.bin [THREADS]
//
// For every cell of a res^3 grid, three times (once per choice of the largest RGB component), it
// finds the coefficients of the sigmoid polynomial S(c0 t^2 + c1 t + c2) whose reflectance, lit
// by D65 and seen by the CIE 1931 observer, has the cell's colour: Newton / Gauss-Newton
// iterations on the CIE76 (CIELAB) difference, with a backtracking line search. Each cell starts
// from its neighbour's solution (continuation from grey outwards), as the paper describes.
//
// Grid: for largest component l, z = rgb[l] ("scale"), x = rgb[l+1]/z, y = rgb[l+2]/z (indices
// mod 3). x and y are uniform on [0, 1]; z_k = smoothstep(smoothstep(k / (res-1))), denser near 0
// and 1 where the spectra change fastest (the paper's nonlinear scale axis).
//
// Integration matches the library's spectrum_to_xyz exactly: 1 nm Riemann sum over 360..830 nm,
// D65 interpolated linearly from its 5 nm table, normalized by sum(D65 ybar), so a table entry
// round-trips through RGBAlbedoSpectrum + spectrum_to_xyz without quadrature error.
//
// Output (little-endian, native floats), see rgb_to_spectrum_table.h:
//   char magic[16] = "ochre-rgb2spec\0\0"; int32 res; int32 zero;
//   float scale[res]; float coeffs[3][res][res][res][3]  indexed [l][k(z)][j(y)][i(x)][c],
//   with c0, c1, c2 of the polynomial in lambda in nm.

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "spectra/csv_table.h"
#include "spectra/rgb_primaries.h"

namespace {

using ochre::Mat3;
using ochre::Array3d;

constexpr double kLambdaMin = 360.0, kLambdaMax = 830.0;
constexpr int kSamples = 471;  // 1 nm steps
// Coefficients (in normalized wavelength t in [0, 1]) are kept below this magnitude: cells on the
// gamut boundary ask for a sigmoid that is exactly 0 or 1 somewhere, which only infinite
// coefficients reach. Scaling the whole polynomial down keeps its zero crossings (the shape).
constexpr double kMaxCoefficient = 1000.0;
constexpr int kMaxIterations = 40;
constexpr double kLabTolerance = 1e-6;

// ------------------------------------------------------------------ the observer under D65
struct Observer {
  std::array<double, kSamples> t{};               // (lambda - 360) / 470
  std::array<double, kSamples> wx{}, wy{}, wz{};  // cmf(lambda) D65(lambda) / sum(D65 ybar)
  Array3d white{};                                  // XYZ of a perfect white, Y = 1
  Mat3 rgb_to_xyz;
};

double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const auto i = std::size_t(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin()) - 1;
  const double f = (x - xs[i]) / (xs[i + 1] - xs[i]);
  return ys[i] + f * (ys[i + 1] - ys[i]);
}

Observer make_observer(const std::filesystem::path& cie_csv, const std::filesystem::path& d65_csv) {
  const auto cie = ochre::CsvTable::load(cie_csv);
  const auto d65 = ochre::CsvTable::load(d65_csv);
  const auto &xb = cie.column("xbar"), &yb = cie.column("ybar"), &zb = cie.column("zbar");
  if (cie.row_count() != kSamples || cie.wavelengths().front() != kLambdaMin)
    throw std::runtime_error(cie_csv.string() + ": expected 1 nm rows from 360 to 830 nm");
  Observer o;
  double norm = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    // The library stores tables as float: round the same way so both integrate the same numbers.
    const double illum = float(interpolate(d65.wavelengths(), d65.column("S"), kLambdaMin + i));
    o.t[i] = i / double(kSamples - 1);
    o.wx[i] = float(xb[i]) * illum;
    o.wy[i] = float(yb[i]) * illum;
    o.wz[i] = float(zb[i]) * illum;
    norm += o.wy[i];
  }
  for (int i = 0; i < kSamples; ++i) {
    o.wx[i] /= norm, o.wy[i] /= norm, o.wz[i] /= norm;
    o.white[0] += o.wx[i], o.white[1] += o.wy[i], o.white[2] += o.wz[i];
  }
  o.rgb_to_xyz = ochre::rgb_to_xyz_matrix(ochre::kRec709Primaries, o.white);
  return o;
}

// ------------------------------------------------------------------ CIELAB (CIE 15:2004 §8.2.1)
constexpr double kLabDelta = 6.0 / 29.0;

double lab_f(double r) {
  return r > kLabDelta * kLabDelta * kLabDelta ? std::cbrt(r) : r / (3 * kLabDelta * kLabDelta) + 4.0 / 29.0;
}
double lab_f_prime(double r) {
  if (r > kLabDelta * kLabDelta * kLabDelta) {
    const double c = std::cbrt(r);
    return 1.0 / (3.0 * c * c);
  }
  return 1.0 / (3 * kLabDelta * kLabDelta);
}

// Lab of an XYZ and, when wanted, d(Lab)/d(XYZ).
Array3d xyz_to_lab(const Array3d& xyz, const Array3d& white, Mat3* jacobian = nullptr) {
  const double fx = lab_f(xyz[0] / white[0]), fy = lab_f(xyz[1] / white[1]), fz = lab_f(xyz[2] / white[2]);
  if (jacobian) {
    const double dx = lab_f_prime(xyz[0] / white[0]) / white[0],
                 dy = lab_f_prime(xyz[1] / white[1]) / white[1],
                 dz = lab_f_prime(xyz[2] / white[2]) / white[2];
    *jacobian = Mat3{{0, 116 * dy, 0, 500 * dx, -500 * dy, 0, 0, 200 * dy, -200 * dz}};
  }
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

// ------------------------------------------------------------------ one cell
struct Evaluation {
  Array3d lab;
  Mat3 jacobian;  // d(Lab) / d(c0, c1, c2)
};

// Lab of the sigmoid spectrum with coefficients c (normalized wavelength) and its derivatives:
// dS/dp = 1 / (2 (1 + p^2)^(3/2)), dp/dc = (t^2, t, 1).
Evaluation evaluate(const Observer& o, const Array3d& c) {
  double x = 0, y = 0, z = 0;
  std::array<double, 3> dx{}, dy{}, dz{};
  for (int i = 0; i < kSamples; ++i) {
    const double t = o.t[i];
    const double p = (c[0] * t + c[1]) * t + c[2];
    const double q = 1.0 / std::sqrt(1.0 + p * p);
    const double s = 0.5 + 0.5 * p * q, ds = 0.5 * q * q * q;
    x += o.wx[i] * s, y += o.wy[i] * s, z += o.wz[i] * s;
    const double d[3] = {ds * t * t, ds * t, ds};
    for (int k = 0; k < 3; ++k) dx[k] += o.wx[i] * d[k], dy[k] += o.wy[i] * d[k], dz[k] += o.wz[i] * d[k];
  }
  Mat3 lab_by_xyz;
  Evaluation e;
  e.lab = xyz_to_lab({x, y, z}, o.white, &lab_by_xyz);
  e.jacobian = lab_by_xyz * Mat3{{dx[0], dx[1], dx[2], dy[0], dy[1], dy[2], dz[0], dz[1], dz[2]}};
  return e;
}

double distance(const Array3d& a, const Array3d& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

Array3d limit_magnitude(Array3d c) {
  const double m = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])});
  if (m > kMaxCoefficient)
    for (double& v : c) v *= kMaxCoefficient / m;
  return c;
}

// Newton iterations from c towards the colour `target_lab`; returns the final CIE76 error.
double solve_cell(const Observer& o, const Array3d& target_lab, Array3d& c) {
  Evaluation e = evaluate(o, c);
  double error = distance(e.lab, target_lab);
  for (int it = 0; it < kMaxIterations && error > kLabTolerance; ++it) {
    if (std::abs(e.jacobian.determinant()) < 1e-300) break;
    const Array3d r{target_lab[0] - e.lab[0], target_lab[1] - e.lab[1], target_lab[2] - e.lab[2]};
    const Array3d step = e.jacobian.inverse() * r;
    bool improved = false;
    for (double alpha = 1.0; alpha > 1e-4 && !improved; alpha *= 0.5) {
      const Array3d trial =
          limit_magnitude({c[0] + alpha * step[0], c[1] + alpha * step[1], c[2] + alpha * step[2]});
      const Evaluation et = evaluate(o, trial);
      const double et_error = distance(et.lab, target_lab);
      if (et_error < error) c = trial, e = et, error = et_error, improved = true;
    }
    if (!improved) break;
  }
  return error;
}

// ------------------------------------------------------------------ the table
double smoothstep(double x) {
  return x * x * (3.0 - 2.0 * x);
}

struct Table {
  int res;
  std::vector<float> scale;
  std::vector<float> coeffs;  // [3][res][res][res][3]
  std::vector<float> errors;  // CIE76 error per cell (statistics only)
  std::size_t index(int l, int k, int j, int i) const {
    return ((std::size_t(l) * res + k) * res + j) * res + i;
  }
};

class Generator {
 public:
  Generator(const Observer& o, int res) : o_(o), table_{res, {}, {}, {}} {
    table_.scale.resize(res);
    for (int k = 0; k < res; ++k) table_.scale[k] = float(smoothstep(smoothstep(k / double(res - 1))));
    table_.coeffs.resize(std::size_t(3) * res * res * res * 3);
    table_.errors.resize(std::size_t(3) * res * res * res);
    // The continuation starts where the spectra are far from 0 and 1 (scale ~ 0.2).
    k_start_ = int(std::lower_bound(table_.scale.begin(), table_.scale.end(), 0.2f) - table_.scale.begin());
  }

  Table run(int threads) {
    const int res = table_.res;
    // Seeds along the grey edge x = 1, for each y, at k_start: walking from the grey corner.
    seeds_.assign(std::size_t(3) * res, Array3d{});
    for (int l = 0; l < 3; ++l) {
      Array3d c{0, 0, 0};
      for (int j = res - 1; j >= 0; --j) {
        solve_at(l, k_start_, j, res - 1, c);
        seeds_[std::size_t(l) * res + j] = c;
      }
    }
    std::atomic<int> next_row{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back([&] {
        for (int row = next_row++; row < 3 * res; row = next_row++) solve_row(row / res, row % res);
      });
    for (auto& th : pool) th.join();
    return std::move(table_);
  }

 private:
  Array3d rgb_of(int l, int k, int j, int i) const {
    const double z = table_.scale[k], x = i / double(table_.res - 1), y = j / double(table_.res - 1);
    Array3d rgb;
    rgb[l] = z, rgb[(l + 1) % 3] = x * z, rgb[(l + 2) % 3] = y * z;
    return rgb;
  }

  void solve_at(int l, int k, int j, int i, Array3d& c) {
    const Array3d target = xyz_to_lab(o_.rgb_to_xyz * rgb_of(l, k, j, i), o_.white);
    const double error = solve_cell(o_, target, c);
    store(l, k, j, i, c, error);
  }

  // All cells of one (l, y) row: along x from the seed, then along z from each x's start cell.
  void solve_row(int l, int j) {
    const int res = table_.res;
    Array3d along_x = seeds_[std::size_t(l) * res + j];
    for (int i = res - 1; i >= 0; --i) {
      solve_at(l, k_start_, j, i, along_x);
      Array3d c = along_x;
      for (int k = k_start_ + 1; k < res; ++k) solve_at(l, k, j, i, c);
      c = along_x;
      for (int k = k_start_ - 1; k >= 0; --k) solve_at(l, k, j, i, c);
    }
  }

  // Converts t-coefficients to lambda-in-nm coefficients: t = (lambda - 360) / 470.
  void store(int l, int k, int j, int i, const Array3d& c, double error) {
    const double w = kLambdaMax - kLambdaMin, a = kLambdaMin;
    const double c0 = c[0] / (w * w), c1 = c[1] / w - 2 * c[0] * a / (w * w),
                 c2 = c[0] * a * a / (w * w) - c[1] * a / w + c[2];
    const std::size_t cell = table_.index(l, k, j, i);
    table_.coeffs[3 * cell + 0] = float(c0), table_.coeffs[3 * cell + 1] = float(c1);
    table_.coeffs[3 * cell + 2] = float(c2);
    table_.errors[cell] = float(error);
  }

  const Observer& o_;
  Table table_;
  int k_start_ = 0;
  std::vector<Array3d> seeds_;
};

void write_table(const Table& t, const std::filesystem::path& output) {
  const std::filesystem::path tmp = output.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    char magic[16] = "ochre-rgb2spec";
    const std::int32_t header[2] = {t.res, 0};
    out.write(magic, sizeof magic);
    out.write(reinterpret_cast<const char*>(header), sizeof header);
    out.write(reinterpret_cast<const char*>(t.scale.data()), std::streamsize(t.scale.size() * sizeof(float)));
    out.write(reinterpret_cast<const char*>(t.coeffs.data()),
              std::streamsize(t.coeffs.size() * sizeof(float)));
    if (!out) throw std::runtime_error(tmp.string() + ": write failed");
  }
  std::filesystem::rename(tmp, output);
}

void print_statistics(const Table& t, double seconds, int threads) {
  const auto& e = t.errors;
  const double max_error = *std::max_element(e.begin(), e.end());
  double sum = 0;
  std::size_t above = 0;
  for (float v : e) sum += v, above += v > 1e-3f;
  std::printf(
      "rgb2spec: res %d, %zu cells, %.1f s on %d threads; CIE76 error max %.3g, mean %.3g, "
      "%zu cells above 1e-3\n",
      t.res, e.size(), seconds, threads, max_error, sum / double(e.size()), above);
  // Near black a CIELAB difference of a few units is invisible; report the rest separately.
  double max_lit = 0;
  for (std::size_t cell = 0; cell < e.size(); ++cell)
    if (t.scale[cell / t.res / t.res % t.res] >= 0.01f) max_lit = std::max(max_lit, double(e[cell]));
  std::printf("rgb2spec: max CIE76 error over cells with largest component >= 0.01: %.3g\n", max_lit);
  if (!std::getenv("OCHRE_RGB2SPEC_VERBOSE")) return;
  std::vector<std::size_t> order(e.size());
  for (std::size_t n = 0; n < order.size(); ++n) order[n] = n;
  std::partial_sort(order.begin(), order.begin() + 20, order.end(),
                    [&](auto a, auto b) { return e[a] > e[b]; });
  for (int n = 0; n < 20; ++n) {
    const std::size_t cell = order[n];
    const int i = int(cell % t.res), j = int(cell / t.res % t.res), k = int(cell / t.res / t.res % t.res),
              l = int(cell / t.res / t.res / t.res);
    std::printf("  l %d k %d (z %.4f) j %d i %d: error %.4g coeffs %g %g %g\n", l, k, t.scale[k], j, i,
                e[cell], t.coeffs[3 * cell], t.coeffs[3 * cell + 1], t.coeffs[3 * cell + 2]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5 || argc > 6) {
    std::fprintf(stderr, "usage: %s CIE_1NM_CSV D65_CSV RESOLUTION OUTPUT.bin [THREADS]\n", argv[0]);
    return 2;
  }
  try {
    const int res = std::stoi(argv[3]);
    if (res < 4 || res > 256) throw std::runtime_error("RESOLUTION must be in [4, 256]");
    const int threads =
        argc == 6 ? std::stoi(argv[5]) : int(std::max(1u, std::thread::hardware_concurrency()));
    const auto start = std::chrono::steady_clock::now();
    const Observer observer = make_observer(argv[1], argv[2]);
    const Table table = Generator(observer, res).run(threads);
    write_table(table, argv[4]);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    print_statistics(table, seconds, threads);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ochre_rgb2spec_opt: %s\n", e.what());
    return 1;
  }
  return 0;
}
