#include "renderer/film/film.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "renderer/util/memory_budget.h"

namespace ochre {

namespace {
constexpr double kScale = 0x1p40;

// Round to nearest (ties to even) in fixed point. Values below 2^62 / kScale (about 4e6, every
// ordinary sample) take one cvtsd2si, which rounds by the same default mode as nearbyint; larger ones
// the general 128-bit path (a library call). Both give the same integer.
__int128 to_fixed(double v) {
  v = std::clamp(v, -kMaxSampleMagnitude, kMaxSampleMagnitude);
  const double scaled = v * kScale;
#if defined(__SSE2__)
  if (std::fabs(scaled) < 0x1p62) return _mm_cvtsd_si64(_mm_set_sd(scaled));
#endif
  return static_cast<__int128>(std::nearbyint(scaled));
}
double from_fixed(__int128 v) {
  return static_cast<double>(v) / kScale;
}
}  // namespace

std::string film_description(int width, int height, const FilmLayers& layers) {
  std::string text = fmt::format("film {}x{} (XYZ", width, height);
  if (layers.aovs) text += ", AOVs";
  if (layers.stokes) text += ", Stokes";
  if (layers.spectral_bins > 0) text += fmt::format(", {} spectral bins", layers.spectral_bins);
  if (!layers.light_groups.empty()) text += fmt::format(", {} light groups", layers.light_groups.size());
  return text + ")";
}

std::size_t Film::bytes_per_pixel(const FilmLayers& layers) {
  const std::size_t components = layers.stokes ? 4 : 1;
  return sizeof(Pixel) + (layers.aovs ? sizeof(AovPixel) : 0) + (layers.stokes ? 9 * sizeof(__int128) : 0) +
         static_cast<std::size_t>(std::max(layers.spectral_bins, 0)) * components * sizeof(__int128) +
         layers.light_groups.size() * static_cast<std::size_t>(std::max(layers.spectral_bins, 1)) * 3 *
             sizeof(__int128);
}

Film::Film(int width, int height, const FilmLayers& layers) : width_(width), height_(height) {
  check_memory_estimate(static_cast<double>(bytes_per_pixel(layers)) * width * height,
                        film_description(width, height, layers));
  pixels_.resize(static_cast<size_t>(width) * height);
  if (layers.aovs) enable_aovs();
  if (layers.stokes) enable_stokes();
  if (layers.spectral_bins > 0)
    enable_spectral(layers.spectral_bins, layers.spectral_min, layers.spectral_max);
  if (!layers.light_groups.empty()) enable_light_groups(layers.light_groups);
}

bool is_light_group_name(std::string_view name) {
  return !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

void Film::enable_light_groups(const std::vector<std::string>& names) {
  light_groups_ = names;
  group_bins_ = std::max(spectral_bins_, 1);
  groups_.assign(pixels_.size() * names.size() * static_cast<size_t>(group_bins_) * 3, 0);
}

int Film::group_bin(float lambda_nm) const {
  if (group_bins_ == 1) return 0;
  const int bin = static_cast<int>(std::floor((lambda_nm - lambda_min_) / bin_width_));
  return std::clamp(bin, 0, group_bins_ - 1);
}

void Film::add_group_sample(int x, int y, size_t group, int bin, const XYZ& xyz) {
  __int128* g = &groups_[((index(x, y) * light_groups_.size() + group) * group_bins_ + bin) * 3];
  g[0] += to_fixed(xyz.x);
  g[1] += to_fixed(xyz.y);
  g[2] += to_fixed(xyz.z);
}

XYZ Film::mean_group(int x, int y, size_t group, int bin) const {
  const size_t i = index(x, y);
  const double n = std::max<double>(1.0, static_cast<double>(pixels_[i].count));
  const __int128* g = &groups_[((i * light_groups_.size() + group) * group_bins_ + bin) * 3];
  return {static_cast<float>(from_fixed(g[0]) / n), static_cast<float>(from_fixed(g[1]) / n),
          static_cast<float>(from_fixed(g[2]) / n)};
}

XYZ Film::mean_group(int x, int y, size_t group) const {
  const size_t i = index(x, y);
  const double n = std::max<double>(1.0, static_cast<double>(pixels_[i].count));
  // The exact sum over the bins (integers), then one rounding.
  const __int128* g = &groups_[(i * light_groups_.size() + group) * group_bins_ * 3];
  __int128 sum[3] = {0, 0, 0};
  for (int b = 0; b < group_bins_; ++b)
    for (int c = 0; c < 3; ++c) sum[c] += g[b * 3 + c];
  return {static_cast<float>(from_fixed(sum[0]) / n), static_cast<float>(from_fixed(sum[1]) / n),
          static_cast<float>(from_fixed(sum[2]) / n)};
}

void Film::add_sample(int x, int y, const XYZ& xyz) {
  Pixel& p = pixels_[index(x, y)];
  p.xyz[0] += to_fixed(xyz.x);
  p.xyz[1] += to_fixed(xyz.y);
  p.xyz[2] += to_fixed(xyz.z);
  p.y2 += to_fixed(static_cast<double>(xyz.y) * xyz.y);
  ++p.count;
}

void Film::enable_aovs() {
  aovs_.assign(pixels_.size(), AovPixel{});
}

void Film::add_aov_sample(int x, int y, const XYZ& albedo, const Vec3f& normal, float depth) {
  AovPixel& a = aovs_[index(x, y)];
  a.albedo[0] += to_fixed(albedo.x);
  a.albedo[1] += to_fixed(albedo.y);
  a.albedo[2] += to_fixed(albedo.z);
  a.normal[0] += to_fixed(normal.x);
  a.normal[1] += to_fixed(normal.y);
  a.normal[2] += to_fixed(normal.z);
  if (depth > 0.0f) {
    a.depth += to_fixed(depth);
    ++a.hits;
  }
}

XYZ Film::mean_albedo(int x, int y) const {
  const AovPixel& a = aovs_[index(x, y)];
  const double n = std::max<double>(1.0, static_cast<double>(pixels_[index(x, y)].count));
  return {static_cast<float>(from_fixed(a.albedo[0]) / n), static_cast<float>(from_fixed(a.albedo[1]) / n),
          static_cast<float>(from_fixed(a.albedo[2]) / n)};
}

Vec3f Film::mean_normal(int x, int y) const {
  const AovPixel& a = aovs_[index(x, y)];
  const double n = std::max<double>(1.0, static_cast<double>(pixels_[index(x, y)].count));
  return {static_cast<float>(from_fixed(a.normal[0]) / n), static_cast<float>(from_fixed(a.normal[1]) / n),
          static_cast<float>(from_fixed(a.normal[2]) / n)};
}

float Film::mean_depth(int x, int y) const {
  const AovPixel& a = aovs_[index(x, y)];
  return a.hits ? static_cast<float>(from_fixed(a.depth) / static_cast<double>(a.hits)) : 0.0f;
}

void Film::enable_spectral(int bins, float lambda_min, float lambda_max) {
  spectral_bins_ = bins;
  lambda_min_ = lambda_min;
  bin_width_ = (lambda_max - lambda_min) / static_cast<float>(bins);
  allocate_spectral();
  if (!light_groups_.empty()) enable_light_groups(light_groups_);  // now per bin
}

void Film::allocate_spectral() {
  spectral_.assign(pixels_.size() * static_cast<size_t>(spectral_bins_ * stokes_components_), 0);
}

void Film::enable_stokes() {
  stokes_components_ = 4;
  stokes_.assign(pixels_.size() * 9, 0);
  allocate_spectral();
}

void Film::add_stokes_sample(int x, int y, const std::array<XYZ, 3>& s123) {
  __int128* s = &stokes_[index(x, y) * 9];
  for (int c = 0; c < 3; ++c) {
    s[3 * c + 0] += to_fixed(s123[c].x);
    s[3 * c + 1] += to_fixed(s123[c].y);
    s[3 * c + 2] += to_fixed(s123[c].z);
  }
}

XYZ Film::mean_stokes(int x, int y, int c) const {
  const size_t i = index(x, y);
  const double n = std::max<double>(1.0, static_cast<double>(pixels_[i].count));
  const __int128* s = &stokes_[i * 9 + 3 * static_cast<size_t>(c - 1)];
  return {static_cast<float>(from_fixed(s[0]) / n), static_cast<float>(from_fixed(s[1]) / n),
          static_cast<float>(from_fixed(s[2]) / n)};
}

void Film::add_spectral_sample(int x, int y, const SampledSpectrum& L, const SampledWavelengths& lambda,
                               int component) {
  __int128* bins =
      &spectral_[(index(x, y) * stokes_components_ + component) * static_cast<size_t>(spectral_bins_)];
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float pdf = lambda.pdf()[i];
    if (!(pdf > 0.0f) || !std::isfinite(L[i])) continue;
    const int bin = static_cast<int>(std::floor((lambda[i] - lambda_min_) / bin_width_));
    if (bin < 0 || bin >= spectral_bins_) continue;
    // E[L(l) 1_bin(l) / pdf(l)] = integral of L over the bin; / width = the bin's mean; / the lanes.
    bins[bin] +=
        to_fixed(static_cast<double>(L[i]) / (static_cast<double>(pdf) * bin_width_ * kSpectrumSamples));
  }
}

float Film::mean_spectral(int x, int y, int bin, int component) const {
  const double n = std::max<double>(1.0, static_cast<double>(pixels_[index(x, y)].count));
  const size_t i = (index(x, y) * stokes_components_ + component) * static_cast<size_t>(spectral_bins_) + bin;
  return static_cast<float>(from_fixed(spectral_[i]) / n);
}

FilmLayers Film::layers() const {
  FilmLayers layers;
  layers.aovs = has_aovs();
  layers.stokes = has_stokes();
  layers.spectral_bins = spectral_bins_;
  layers.light_groups = light_groups_;
  if (spectral_bins_ > 0) {
    layers.spectral_min = lambda_min_;
    layers.spectral_max = lambda_min_ + bin_width_ * static_cast<float>(spectral_bins_);
  }
  return layers;
}

void Film::merge(const Film& other, int x0, int y0) {
  const std::vector<std::string> names = accumulator_names();
  if (names != other.accumulator_names() || x0 < 0 || y0 < 0 || x0 + other.width_ > width_ ||
      y0 + other.height_ > height_)
    throw std::invalid_argument("Film::merge: the films' layers or sizes do not fit");
  for (int y = 0; y < other.height_; ++y)
    for (int x = 0; x < other.width_; ++x) {
      const size_t from = other.index(x, y), to = index(x0 + x, y0 + y);
      for (size_t a = 0; a < names.size(); ++a)
        set_accumulator(a, to, accumulator(a, to) + other.accumulator(a, from));
    }
}

std::vector<std::string> Film::accumulator_names() const {
  std::vector<std::string> names = {"X", "Y", "Z", "Y2", "count"};
  if (has_aovs())
    names.insert(names.end(), {"albedo.X", "albedo.Y", "albedo.Z", "normal.X", "normal.Y", "normal.Z",
                               "depth", "depthHits"});
  if (has_stokes())
    for (int c = 1; c <= 3; ++c)
      for (const char* xyz : {"X", "Y", "Z"}) names.push_back(fmt::format("S{}.{}", c, xyz));
  for (int c = 0; c < stokes_components_ && spectral_bins_ > 0; ++c)
    for (int b = 0; b < spectral_bins_; ++b) names.push_back(fmt::format("S{}.bin{}", c, b));
  for (const std::string& group : light_groups_)
    for (int b = 0; b < group_bins_; ++b)
      for (const char* xyz : {"X", "Y", "Z"})
        names.push_back(group_bins_ == 1 ? fmt::format("group.{}.{}", group, xyz)
                                         : fmt::format("group.{}.bin{}.{}", group, b, xyz));
  return names;
}

Film::AccumulatorRef Film::accumulator_ref(size_t index, size_t pixel) {
  Pixel& p = pixels_[pixel];
  if (index < 3) return {&p.xyz[index], nullptr};
  if (index == 3) return {&p.y2, nullptr};
  if (index == 4) return {nullptr, &p.count};
  index -= 5;
  if (has_aovs()) {
    AovPixel& a = aovs_[pixel];
    if (index < 3) return {&a.albedo[index], nullptr};
    if (index < 6) return {&a.normal[index - 3], nullptr};
    if (index == 6) return {&a.depth, nullptr};
    if (index == 7) return {nullptr, &a.hits};
    index -= 8;
  }
  if (has_stokes()) {
    if (index < 9) return {&stokes_[pixel * 9 + index], nullptr};
    index -= 9;
  }
  const size_t per_pixel = static_cast<size_t>(spectral_bins_) * stokes_components_;
  if (index < per_pixel) return {&spectral_[pixel * per_pixel + index], nullptr};
  index -= per_pixel;
  const size_t group_sums = light_groups_.size() * static_cast<size_t>(group_bins_) * 3;
  if (index < group_sums) return {&groups_[pixel * group_sums + index], nullptr};
  throw std::out_of_range("Film: no accumulator " + std::to_string(index));
}

__int128 Film::accumulator(size_t index, size_t pixel) const {
  const AccumulatorRef ref = const_cast<Film*>(this)->accumulator_ref(index, pixel);
  return ref.sum ? *ref.sum : static_cast<__int128>(*ref.count);
}

void Film::set_accumulator(size_t index, size_t pixel, __int128 value) {
  const AccumulatorRef ref = accumulator_ref(index, pixel);
  if (ref.sum)
    *ref.sum = value;
  else
    *ref.count = static_cast<uint64_t>(value);
}

XYZ Film::mean(int x, int y) const {
  const Pixel& p = pixels_[index(x, y)];
  if (p.count == 0) return {0, 0, 0};
  const double n = static_cast<double>(p.count);
  return {static_cast<float>(from_fixed(p.xyz[0]) / n), static_cast<float>(from_fixed(p.xyz[1]) / n),
          static_cast<float>(from_fixed(p.xyz[2]) / n)};
}

double Film::variance_y(int x, int y) const {
  const Pixel& p = pixels_[index(x, y)];
  if (p.count < 2) return 0.0;
  const double n = static_cast<double>(p.count);
  const double mean = from_fixed(p.xyz[1]) / n;
  const double mean_sq = from_fixed(p.y2) / n;
  return std::max(0.0, (mean_sq - mean * mean) * n / (n - 1.0));
}

}  // namespace ochre
