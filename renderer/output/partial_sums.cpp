#include "renderer/output/partial_sums.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "renderer/film/noise_threshold.h"
#include "renderer/image/exr_input_stream.h"
#include "renderer/image/exr_writer.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/fnv1a.h"
#include "renderer/util/image_error.h"
#include "renderer/util/memory_budget.h"
#include "spectra/color_space.h"
#include "spectra/input_error.h"

namespace ochre {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kFormatVersion = "1";
constexpr int kWords = 4;  // 32-bit words of a 128-bit sum
constexpr size_t kBandBytes = 16u << 20;

std::string word_channel(const std::string& accumulator, int word) {
  return fmt::format("sums.{}.w{}", accumulator, word);
}

// Rows per band so that a band of `bytes_per_pixel` channels of `width` pixels takes about 16 MB.
int band_rows(int width, size_t bytes_per_pixel) {
  const size_t row = std::max<size_t>(1, static_cast<size_t>(width) * bytes_per_pixel);
  return static_cast<int>(std::clamp<size_t>(kBandBytes / row, 1, 1u << 20));
}

template <class T>
std::optional<T> parse_integer(std::string_view text, int base = 10) {
  T value{};
  if (text.empty()) return std::nullopt;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, base);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

[[noreturn]] void fail_field(const std::string& file, const std::string& field, const std::string& why) {
  throw InputError(fmt::format("{}: {}: {}", file, field, why));
}

// The count each pixel must hold according to the coverage: pieces are looked up per cell of the grid
// their edges make, so the check costs one lookup per pixel however many pieces there are.
class ExpectedCounts {
 public:
  ExpectedCounts(const std::vector<CoveragePiece>& pieces, const PixelRect& rect) : rect_(rect) {
    std::vector<int> xs = {rect.x0, rect.x1}, ys = {rect.y0, rect.y1};
    for (const CoveragePiece& p : pieces) {
      xs.insert(xs.end(), {p.rect.x0, p.rect.x1});
      ys.insert(ys.end(), {p.rect.y0, p.rect.y1});
    }
    for (auto* cuts : {&xs, &ys}) {
      std::sort(cuts->begin(), cuts->end());
      cuts->erase(std::unique(cuts->begin(), cuts->end()), cuts->end());
    }
    column_of_.resize(static_cast<size_t>(rect.width()));
    for (int x = rect.x0; x < rect.x1; ++x)
      column_of_[x - rect.x0] = static_cast<int>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin()) - 1;
    row_of_.resize(static_cast<size_t>(rect.height()));
    for (int y = rect.y0; y < rect.y1; ++y)
      row_of_[y - rect.y0] = static_cast<int>(std::upper_bound(ys.begin(), ys.end(), y) - ys.begin()) - 1;
    columns_ = xs.size();
    counts_.assign(xs.size() * ys.size(), 0);
    for (size_t j = 0; j + 1 < ys.size(); ++j)
      for (size_t i = 0; i + 1 < xs.size(); ++i)
        for (const CoveragePiece& p : pieces)
          if (p.rect.contains({xs[i], ys[j], xs[i + 1], ys[j + 1]}))
            counts_[j * columns_ + i] += p.samples.size();
  }
  uint64_t at(int x, int y) const {
    return counts_[static_cast<size_t>(row_of_[y - rect_.y0]) * columns_ + column_of_[x - rect_.x0]];
  }

 private:
  PixelRect rect_;
  std::vector<int> column_of_, row_of_;
  size_t columns_ = 0;
  std::vector<uint64_t> counts_;
};

void add_value_to_checksum(Fnv1a64& checksum, __int128 value) {
  const auto bits = static_cast<unsigned __int128>(value);
  checksum.add_word(static_cast<uint64_t>(bits));
  checksum.add_word(static_cast<uint64_t>(bits >> 64));
}

std::optional<std::pair<float, float>> parse_float_pair(std::string_view text) {
  const size_t dash = text.find('-', 1);
  if (dash == std::string_view::npos) return std::nullopt;
  const std::string lo(text.substr(0, dash)), hi(text.substr(dash + 1));
  char* end_lo = nullptr;
  char* end_hi = nullptr;
  const float a = std::strtof(lo.c_str(), &end_lo), b = std::strtof(hi.c_str(), &end_hi);
  if (lo.empty() || hi.empty() || *end_lo || *end_hi || !std::isfinite(a) || !std::isfinite(b) || !(a < b))
    return std::nullopt;
  return std::pair{a, b};
}

// A pixel holds the samples the coverage says; a pixel of a noise-threshold render may have stopped at a
// decision point before them (renderer/film/noise_threshold.h).
bool count_matches(__int128 count, uint64_t expected, const PartialSumsHeader& h) {
  if (count < 0 || count > static_cast<__int128>(UINT64_MAX)) return false;
  const auto n = static_cast<uint64_t>(count);
  return h.noise_threshold > 0.0 ? valid_noise_threshold_count(n, expected) : n == expected;
}

}  // namespace

void parse_identity_fields(const std::string& file, PartialSumsHeader& header) {
  for (const std::string& name : identity_field_names())
    if (!identity_field(header.identity, name))
      fail_field(file, name, "missing (not written by this version of ochre?)");
  const auto field = [&](const char* name) {
    return std::string_view(*identity_field(header.identity, name));
  };
  const std::string_view resolution = field("ochre.resolution");
  const size_t x = resolution.find('x');
  const auto width = parse_integer<int>(resolution.substr(0, x == std::string_view::npos ? 0 : x));
  const auto height = parse_integer<int>(x == std::string_view::npos ? "" : resolution.substr(x + 1));
  if (!width || !height || *width < 1 || *height < 1)
    fail_field(file, "ochre.resolution",
               fmt::format("expected WxH with positive integers, got '{}'", resolution));
  header.image_width = *width;
  header.image_height = *height;
  const auto spp = parse_integer<uint32_t>(field("ochre.spp"));
  if (!spp || *spp < 1)
    fail_field(file, "ochre.spp", fmt::format("expected a positive integer, got '{}'", field("ochre.spp")));
  header.spp = *spp;
  for (const char* flag : {"ochre.aovs", "ochre.stokes"})
    if (field(flag) != "0" && field(flag) != "1")
      fail_field(file, flag, fmt::format("expected 0 or 1, got '{}'", field(flag)));
  header.layers.aovs = field("ochre.aovs") == "1";
  header.layers.stokes = field("ochre.stokes") == "1";
  const auto bins = parse_integer<int>(field("ochre.spectralBins"));
  if (!bins || *bins < 0 || *bins > 471)
    fail_field(file, "ochre.spectralBins",
               fmt::format("expected an integer in [0, 471], got '{}'", field("ochre.spectralBins")));
  header.layers.spectral_bins = *bins;
  const auto range = parse_float_pair(field("ochre.spectralRange"));
  if (!range)
    fail_field(file, "ochre.spectralRange",
               fmt::format("expected MIN-MAX in nm, got '{}'", field("ochre.spectralRange")));
  header.layers.spectral_min = range->first;
  header.layers.spectral_max = range->second;
  const std::string_view threshold = field("ochre.noiseThreshold");
  double value = -1.0;
  const auto [end, error] = std::from_chars(threshold.data(), threshold.data() + threshold.size(), value);
  if (error != std::errc() || end != threshold.data() + threshold.size() || !(value >= 0.0 && value <= 1.0))
    fail_field(file, "ochre.noiseThreshold", fmt::format("expected a number in [0, 1], got '{}'", threshold));
  header.noise_threshold = value;
  // Light groups: comma-separated names (is_light_group_name, renderer/film/film.h).
  const std::string_view groups = field("ochre.lightGroups");
  header.layers.light_groups.clear();
  for (size_t start = 0; start < groups.size();) {
    const size_t comma = std::min(groups.find(',', start), groups.size());
    const std::string_view name = groups.substr(start, comma - start);
    if (!is_light_group_name(name) || header.layers.light_groups.size() >= kMaxLightGroups)
      fail_field(file, "ochre.lightGroups",
                 fmt::format("expected up to {} group names separated by commas, got '{}'", kMaxLightGroups,
                             groups));
    header.layers.light_groups.emplace_back(name);
    start = comma + 1;
    if (comma + 1 == groups.size())
      fail_field(file, "ochre.lightGroups", fmt::format("ends with a comma: '{}'", groups));
  }
}

void write_partial_sums(AtomicOutput& output, const PartialSumsHeader& header, const Film& film) {
  const std::string file = output.final_path().string();
  const PixelRect& rect = header.rect;
  if (film.width() != rect.width() || film.height() != rect.height())
    throw ImageError(fmt::format("cannot write {}: the film is not the size of the region", file));
  Imf::Header exr(Imath::Box2i({0, 0}, {header.image_width - 1, header.image_height - 1}),
                  Imath::Box2i({rect.x0, rect.y0}, {rect.x1 - 1, rect.y1 - 1}));
  // RLE: the high words of the sums are nearly all 0 (or all ones) and compress to nothing, the low words
  // are noise that nothing compresses. Measured on a 1024x1024 part: RLE writes in a quarter of ZIP's time
  // and reads in half, for files 15 % larger (docs/distributed.md, Figures).
  exr.compression() = Imf::RLE_COMPRESSION;
  const std::vector<std::string> accumulators = film.accumulator_names();
  for (const char* c : {"R", "G", "B"}) exr.channels().insert(c, Imf::Channel(Imf::FLOAT));
  for (const std::string& a : accumulators)
    for (int w = 0; w < kWords; ++w) exr.channels().insert(word_channel(a, w), Imf::Channel(Imf::UINT));
  const std::string colorspace = *identity_field(header.identity, "ochre.colorspace");
  const bool acescg = colorspace == "acescg";
  const Chromaticities c = acescg ? acescg_chromaticities() : rec709_chromaticities();
  Imf::addChromaticities(exr, Imf::Chromaticities({c.red[0], c.red[1]}, {c.green[0], c.green[1]},
                                                  {c.blue[0], c.blue[1]}, {c.white[0], c.white[1]}));
  std::map<std::string, std::string> attributes = header.notes;
  for (const auto& [name, value] : header.identity) attributes[name] = value;
  attributes["ochre.partialSums"] = std::string(kFormatVersion);
  attributes["ochre.coverage"] = format_coverage(header.coverage);
  attributes["ochre.discardedSamples"] = std::to_string(header.discarded_samples);
  attributes["ochre.nonFiniteShadingValues"] = std::to_string(header.nonfinite_values);

  // The checksum covers every sum; it is known only after the last band, so the pixels are hashed first.
  Fnv1a64 checksum;
  for (int y = 0; y < film.height(); ++y)
    for (size_t a = 0; a < accumulators.size(); ++a)
      for (int x = 0; x < film.width(); ++x)
        add_value_to_checksum(checksum, film.accumulator(a, static_cast<size_t>(y) * film.width() + x));
  attributes["ochre.sumsChecksum"] = fmt::format("{:016x}", checksum.value());
  attributes["software"] = "ochre " + *identity_field(header.identity, "ochre.version");
  for (const auto& [name, value] : attributes) exr.insert(name, Imf::StringAttribute(value));

  const ColorSpace space = parse_color_space(colorspace);
  const int width = film.width();
  const int rows = band_rows(width, 3 * sizeof(float) + accumulators.size() * kWords * sizeof(uint32_t));
  std::vector<std::vector<float>> preview(3);
  std::vector<std::vector<uint32_t>> words(accumulators.size() * kWords);
  try {
    Imf::OutputFile out(output.temp_path().c_str(), exr);
    for (int band = 0; band < film.height(); band += rows) {
      const int n = std::min(rows, film.height() - band);
      const size_t count = static_cast<size_t>(n) * width;
      Imf::FrameBuffer frame;
      const Imath::V2i origin(rect.x0, rect.y0 + band);
      for (int k = 0; k < 3; ++k) {
        preview[k].resize(count);
        frame.insert(k == 0   ? "R"
                     : k == 1 ? "G"
                              : "B",
                     Imf::Slice::Make(Imf::FLOAT, preview[k].data(), origin, width, n));
      }
      for (size_t a = 0; a < accumulators.size(); ++a)
        for (int w = 0; w < kWords; ++w) {
          std::vector<uint32_t>& channel = words[a * kWords + w];
          channel.resize(count);
          frame.insert(word_channel(accumulators[a], w),
                       Imf::Slice::Make(Imf::UINT, channel.data(), origin, width, n));
        }
      for (size_t i = 0; i < count; ++i) {
        const int x = static_cast<int>(i % width), y = band + static_cast<int>(i / width);
        const RGB rgb = xyz_to_rgb(film.mean(x, y), space);
        preview[0][i] = rgb.r;
        preview[1][i] = rgb.g;
        preview[2][i] = rgb.b;
        const size_t pixel = static_cast<size_t>(y) * width + x;
        for (size_t a = 0; a < accumulators.size(); ++a) {
          const auto bits = static_cast<unsigned __int128>(film.accumulator(a, pixel));
          for (int w = 0; w < kWords; ++w) words[a * kWords + w][i] = static_cast<uint32_t>(bits >> (32 * w));
        }
      }
      out.setFrameBuffer(frame);
      out.writePixels(n);
    }
  } catch (const std::exception& error) {
    throw ImageError(fmt::format("cannot write {}: {}", file, error.what()));
  }
}

struct PartialSumsFile::Impl {
  fs::path path;
  std::string file;
  PartialSumsHeader header;
  std::string checksum;
};

PartialSumsFile::PartialSumsFile(const fs::path& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  const std::string file = impl_->file = path.string();
  std::error_code error;
  if (!fs::exists(path, error)) throw InputError(fmt::format("{}: no such file", file));
  InputFile input = InputFile::open(path, kImageFileInput);
  PartialSumsHeader& h = impl_->header;
  Imath::Box2i data, display;
  std::map<std::string, std::string> attributes;
  std::vector<std::pair<std::string, Imf::PixelType>> channels;
  try {
    InputFileIStream stream(input);
    Imf::InputFile exr(stream);
    data = exr.header().dataWindow();
    display = exr.header().displayWindow();
    for (auto it = exr.header().begin(); it != exr.header().end(); ++it)
      if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        attributes.emplace(it.name(), text->value());
    for (auto it = exr.header().channels().begin(); it != exr.header().channels().end(); ++it)
      channels.emplace_back(it.name(), it.channel().type);
  } catch (const std::exception& e) {
    throw InputError(fmt::format("{}: not a readable EXR file: {}", file, e.what()));
  }
  const auto version = attributes.find("ochre.partialSums");
  if (version == attributes.end())
    throw InputError(fmt::format(
        "{}: ochre.partialSums: missing: not a partial-sum file (ochre render --sample-range/--region/"
        "--checkpoint and ochre merge --sums write them)",
        file));
  if (version->second != kFormatVersion)
    fail_field(file, "ochre.partialSums",
               fmt::format("format version '{}' is not supported (this ochre reads {})", version->second,
                           kFormatVersion));
  for (const std::string& name : identity_field_names())
    if (const auto it = attributes.find(name); it != attributes.end())
      h.identity.emplace_back(name, it->second);
  parse_identity_fields(file, h);
  if (display.min.x != 0 || display.min.y != 0 || display.max.x != h.image_width - 1 ||
      display.max.y != h.image_height - 1)
    fail_field(file, "displayWindow",
               fmt::format("must be the whole {}x{} image", h.image_width, h.image_height));
  h.rect = {data.min.x, data.min.y, data.max.x + 1, data.max.y + 1};
  if (h.rect.empty() || !PixelRect{0, 0, h.image_width, h.image_height}.contains(h.rect))
    fail_field(file, "dataWindow", "must lie inside the image");
  const auto coverage = parse_coverage(attributes["ochre.coverage"]);
  if (!coverage)
    fail_field(file, "ochre.coverage",
               fmt::format("expected x0,y0,x1,y1:A:B;..., got '{}'", attributes["ochre.coverage"]));
  for (const CoveragePiece& piece : *coverage)
    if (!h.rect.contains(piece.rect) || piece.samples.end > h.spp)
      fail_field(file, "ochre.coverage",
                 fmt::format("piece {}:{} lies outside the file's pixels {} or samples 0:{}",
                             format_pixel_rect(piece.rect), format_sample_range(piece.samples),
                             format_pixel_rect(h.rect), h.spp));
  h.coverage = *coverage;
  if (h.noise_threshold > 0.0)
    for (const CoveragePiece& piece : h.coverage)
      if (piece.samples.begin != 0)
        fail_field(file, "ochre.coverage",
                   fmt::format("piece {}:{} does not start at sample 0: a noise-threshold render is split by "
                               "pixels, never by samples",
                               format_pixel_rect(piece.rect), format_sample_range(piece.samples)));
  for (auto [name, value] : {std::pair{"ochre.discardedSamples", &h.discarded_samples},
                             std::pair{"ochre.nonFiniteShadingValues", &h.nonfinite_values}}) {
    const auto parsed = parse_integer<uint64_t>(attributes[name]);
    if (!parsed) fail_field(file, name, fmt::format("expected a count, got '{}'", attributes[name]));
    *value = *parsed;
  }
  impl_->checksum = attributes["ochre.sumsChecksum"];
  if (!parse_integer<uint64_t>(impl_->checksum, 16) || impl_->checksum.size() != 16)
    fail_field(file, "ochre.sumsChecksum",
               fmt::format("expected 16 hexadecimal digits, got '{}'", impl_->checksum));
  const Film probe(1, 1, h.layers);
  for (const std::string& a : probe.accumulator_names())
    for (int w = 0; w < kWords; ++w) {
      const std::string name = word_channel(a, w);
      const auto it =
          std::find_if(channels.begin(), channels.end(), [&](const auto& c) { return c.first == name; });
      if (it == channels.end())
        fail_field(file, name,
                   "missing channel (the file's layers are " + film_description(1, 1, h.layers) + ")");
      if (it->second != Imf::UINT) fail_field(file, name, "must be a UINT channel");
    }
  for (const auto& [name, value] : attributes)
    if (name.rfind("ochre.", 0) == 0 && !identity_field(h.identity, name)) h.notes[name] = value;
}

PartialSumsFile::~PartialSumsFile() = default;
PartialSumsFile::PartialSumsFile(PartialSumsFile&&) noexcept = default;
PartialSumsFile& PartialSumsFile::operator=(PartialSumsFile&&) noexcept = default;

const fs::path& PartialSumsFile::path() const {
  return impl_->path;
}

const PartialSumsHeader& PartialSumsFile::header() const {
  return impl_->header;
}

void PartialSumsFile::add_to(Film& film, int x0, int y0) const {
  const PartialSumsHeader& h = impl_->header;
  const std::string& file = impl_->file;
  const PixelRect& rect = h.rect;
  const std::vector<std::string> accumulators = film.accumulator_names();
  if (accumulators != Film(1, 1, h.layers).accumulator_names() || x0 < 0 || y0 < 0 ||
      x0 + rect.width() > film.width() || y0 + rect.height() > film.height())
    throw std::invalid_argument("PartialSumsFile::add_to: the film does not fit the file");
  const ExpectedCounts expected(h.coverage, rect);
  const size_t count_index = 4;  // "count" (Film::accumulator_names)
  const int width = rect.width();
  const int rows = band_rows(width, accumulators.size() * kWords * sizeof(uint32_t));
  std::vector<std::vector<uint32_t>> words(accumulators.size() * kWords);
  Fnv1a64 checksum;
  InputFile input = InputFile::open(impl_->path, kImageFileInput);
  try {
    InputFileIStream stream(input);
    Imf::InputFile exr(stream);
    for (int band = 0; band < rect.height(); band += rows) {
      const int n = std::min(rows, rect.height() - band);
      const size_t size = static_cast<size_t>(n) * width;
      Imf::FrameBuffer frame;
      const Imath::V2i origin(rect.x0, rect.y0 + band);
      for (size_t a = 0; a < accumulators.size(); ++a)
        for (int w = 0; w < kWords; ++w) {
          std::vector<uint32_t>& channel = words[a * kWords + w];
          channel.assign(size, 0);
          frame.insert(word_channel(accumulators[a], w),
                       Imf::Slice::Make(Imf::UINT, channel.data(), origin, width, n));
        }
      exr.setFrameBuffer(frame);
      exr.readPixels(rect.y0 + band, rect.y0 + band + n - 1);
      for (int row = 0; row < n; ++row) {
        const int y = band + row;
        for (size_t a = 0; a < accumulators.size(); ++a)
          for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(row) * width + x;
            unsigned __int128 bits = 0;
            for (int w = kWords; w-- > 0;) bits = (bits << 32) | words[a * kWords + w][i];
            const auto value = static_cast<__int128>(bits);
            add_value_to_checksum(checksum, value);
            if (a == count_index && !count_matches(value, expected.at(rect.x0 + x, rect.y0 + y), h))
              fail_field(file, "sums.count",
                         fmt::format("pixel ({}, {}) holds {} samples, but ochre.coverage says {}{}",
                                     rect.x0 + x, rect.y0 + y, static_cast<uint64_t>(value),
                                     expected.at(rect.x0 + x, rect.y0 + y),
                                     h.noise_threshold > 0.0 ? " (or a power of two from 16 below it)" : ""));
            const size_t pixel = static_cast<size_t>(y0 + y) * film.width() + (x0 + x);
            film.set_accumulator(a, pixel, film.accumulator(a, pixel) + value);
          }
      }
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(fmt::format("{}: cannot read the sums: {}", file, e.what()));
  }
  if (fmt::format("{:016x}", checksum.value()) != impl_->checksum)
    fail_field(file, "ochre.sumsChecksum", "does not match the sums: the file is damaged or was edited");
}

Film PartialSumsFile::read_film() const {
  const PixelRect& rect = impl_->header.rect;
  Film film(rect.width(), rect.height(), impl_->header.layers);
  add_to(film, 0, 0);
  return film;
}

}  // namespace ochre
