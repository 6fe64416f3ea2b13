#include "tools/ochre/merge_command.h"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <new>
#include <optional>

#include "renderer/output/output_files.h"
#include "renderer/output/partial_sums.h"
#include "renderer/output/render_output.h"
#include "renderer/scene/render_settings.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/memory_budget.h"
#include "renderer/util/output_transaction.h"
#include "renderer/util/progress.h"
#include "renderer/util/signal_cleanup.h"
#include "spectra/input_error.h"
#include "tools/cli/program.h"

namespace ochre {

namespace {

// Refuses parts of different renders, naming the field that differs.
void check_same_render(const std::vector<PartialSumsFile>& parts) {
  const PartialSumsFile& first = parts.front();
  for (const PartialSumsFile& part : parts)
    for (size_t i = 0; i < first.header().identity.size(); ++i) {
      const auto& [name, expected] = first.header().identity[i];
      const std::string& value = part.header().identity[i].second;
      if (value == expected) continue;
      const std::string why = name == "ochre.sceneHash" ? "the scene or a file it references differs"
                              : name == "ochre.version" ? "rendered by another version of ochre"
                                                        : "rendered with other settings";
      throw InputError(
          fmt::format("{}: {}: '{}' differs from '{}' in {} ({}): parts of different renders do not "
                      "merge",
                      part.path().string(), name, value, expected, first.path().string(), why));
    }
}

// The coverage check: overlaps are always an error, missing samples unless a partial merge is asked for.
CoverageReport check_parts_cover(const std::vector<PartialSumsFile>& parts, bool partial) {
  std::vector<SourcedPiece> pieces;
  for (const PartialSumsFile& part : parts)
    for (const CoveragePiece& piece : part.header().coverage) pieces.push_back({piece, part.path().string()});
  const PartialSumsHeader& h = parts.front().header();
  CoverageReport report = check_coverage(pieces, h.image_width, h.image_height, h.spp);
  if (report.overlaps.empty() && (partial || report.missing.empty())) return report;
  std::string message = "the parts do not hold every sample of every pixel exactly once:";
  constexpr size_t kShown = 20;
  size_t shown = 0;
  for (const std::string& o : report.overlaps)
    if (shown++ < kShown) message += "\n  overlap: " + o;
  if (!partial)
    for (const std::string& m : report.missing)
      if (shown++ < kShown) message += "\n  missing: " + m;
  if (shown > kShown) message += fmt::format("\n  ... and {} more", shown - kShown);
  if (report.overlaps.empty())
    message +=
        "\n(render the missing samples with ochre render --region R --sample-range A:B -o PART.exr, or merge "
        "with "
        "--partial for a lower-sample image)";
  throw InputError(message);
}

// The fields of a part's header that the merge applies, each read strictly: a value that `ochre render`
// would not have written ("3abc", an exposure of 1e9, an unknown sampler) is bad input naming the part file
// and the field, never a partial parse or a value out of range applied.
class PartFields {
 public:
  explicit PartFields(const PartialSumsFile& part) : file_(part.path().string()), header_(part.header()) {}

  const PartialSumsHeader& header() const { return header_; }

  [[noreturn]] void fail(const std::string& name, const std::string& message) const {
    throw InputError(fmt::format("{}: {}: {}", file_, name, message));
  }

  // A note, "" when absent.
  std::string note(const std::string& name) const {
    const auto it = header_.notes.find(name);
    return it == header_.notes.end() ? "" : it->second;
  }

  // N space-separated finite numbers within +-limit (as fmt writes doubles: exact round trip); nothing when
  // the note is absent.
  template <size_t N>
  std::optional<std::array<double, N>> numbers(const std::string& name, double limit) const {
    const std::string text = note(name);
    if (text.empty()) return std::nullopt;
    std::array<double, N> values{};
    const char* p = text.data();
    const char* end = text.data() + text.size();
    for (size_t i = 0; i < N; ++i) {
      while (p < end && *p == ' ') ++p;
      const auto [next, error] = std::from_chars(p, end, values[i]);
      if (error != std::errc() || !std::isfinite(values[i]) || std::fabs(values[i]) > limit)
        fail(name, fmt::format("expected {} finite numbers within +-{:g}, got '{}'", N, limit, text));
      p = next;
    }
    if (p != end)
      fail(name, fmt::format("expected {} finite numbers within +-{:g}, got '{}'", N, limit, text));
    return values;
  }

  // One number in [lo, hi]; `fallback` when the note is absent.
  double number(const std::string& name, double lo, double hi, double fallback) const {
    const std::string text = note(name);
    if (text.empty()) return fallback;
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !(value >= lo && value <= hi))
      fail(name, fmt::format("expected a number in [{:g}, {:g}], got '{}'", lo, hi, text));
    return value;
  }

  // A field of the render's identity.
  const std::string& identity(const std::string& name) const {
    const std::string* value = identity_field(header_.identity, name);
    if (!value) fail(name, "missing");
    return *value;
  }

  template <class Enum, size_t N>
  Enum choice(const std::string& name, const NamedChoices<Enum, N>& choices) const {
    const std::string& text = identity(name);
    const std::optional<Enum> value = choices.parse(text);
    if (!value) fail(name, fmt::format("unknown value '{}' (known: {})", text, choices.list()));
    return *value;
  }

  uint64_t unsigned_integer(const std::string& name) const {
    const std::string& text = identity(name);
    uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
      fail(name, fmt::format("expected an integer in [0, 2^64), got '{}'", text));
    return value;
  }

 private:
  std::string file_;
  const PartialSumsHeader& header_;
};

// The final outputs as the render that made the parts would have written them.
OutputSettings merged_outputs(const MergeCommand& command, const PartFields& part) {
  const PartialSumsHeader& h = part.header();
  OutputSettings out;
  out.exr = command.exr;
  out.png = command.png;
  out.colorspace = part.choice("ochre.colorspace", kWorkingSpaces);
  out.aovs = h.layers.aovs;
  out.stokes = h.layers.stokes;
  out.spectral_bins = h.layers.spectral_bins;
  out.spectral_min = h.layers.spectral_min;
  out.spectral_max = h.layers.spectral_max;
  out.light_groups = h.layers.light_groups;
  for (const std::string& group : out.light_groups)
    out.light_group_emission.push_back(part.note(light_group_emission_attribute(group)));
  out.ocio_config = command.ocio_config.value_or(part.note("ochre.display.ocioConfig"));
  out.display = command.display.value_or(part.note("ochre.display.display"));
  out.view = command.view.value_or(part.note("ochre.display.view"));
  // As output.exposure and --exposure.
  out.exposure =
      command.exposure.value_or(static_cast<float>(part.number("ochre.display.exposure", -64.0, 64.0, 0.0)));
  // A camera sensor's film (docs/cameras.md): its name and output mode are part of the identity.
  const std::string& sensor = part.identity("ochre.sensor");
  const size_t space = sensor.rfind(' ');
  out.sensor = sensor.substr(0, space);
  if (space != std::string::npos) {
    const std::string mode = sensor.substr(space + 1);
    if (mode != "camera_rgb" && mode != "white_balanced")
      part.fail("ochre.sensor", fmt::format("unknown output '{}' (known: camera_rgb, white_balanced)", mode));
    out.camera_rgb = mode == "camera_rgb";
  }
  if (const auto m = part.numbers<9>("ochre.sensorToXYZ", 1e6)) out.sensor_to_xyz = Mat3{*m};
  if (const auto xyz = part.numbers<3>("ochre.display.whiteBalance", 1e6)) {
    // As output.white_balance: the XYZ of a colour.
    if (!((*xyz)[0] > 0.0 && (*xyz)[1] > 0.0 && (*xyz)[2] > 0.0))
      part.fail("ochre.display.whiteBalance", "the illuminant's X, Y and Z must be positive");
    out.white_balance_xyz = xyz;
  }
  return out;
}

RenderSettings merged_settings(const PartFields& part) {
  const PartialSumsHeader& h = part.header();
  RenderSettings s;
  s.width = h.image_width;
  s.height = h.image_height;
  s.spp = h.spp;
  s.sample_begin = 0;
  s.seed = part.unsigned_integer("ochre.seed");
  s.sampler = part.choice("ochre.sampler", kSamplerKinds);
  s.noise_threshold = h.noise_threshold;
  return s;
}

int merge(const MergeCommand& command) {
  const bool final_image = !command.exr.empty() || !command.png.empty();
  if (!command.check && !final_image && command.sums.empty())
    throw InputError("no output: give -o OUT.exr, --png OUT.png and/or --sums OUT.exr (or --check)");
  InputFileLog inputs;
  std::vector<PartialSumsFile> parts;
  {
    const InputFileLog::Recording recording(inputs);
    for (const std::string& path : command.parts) parts.emplace_back(path);
  }
  check_same_render(parts);
  // Partial sums alone may miss samples: they are meant to be merged again with further parts.
  const CoverageReport coverage = check_parts_cover(parts, command.partial || command.check || !final_image);
  const PartFields fields(parts.front());
  const PartialSumsHeader& first = fields.header();
  if (command.check) {
    for (const std::string& m : coverage.missing) std::cout << "missing: " << m << "\n";
    if (coverage.missing.empty()) std::cout << "complete: every sample of every pixel is held exactly once\n";
    return coverage.missing.empty() ? kExitDone : kExitCheckFailed;
  }

  const OutputSettings out = merged_outputs(command, fields);
  if (final_image) check_outputs(out);
  if (!command.sums.empty()) check_output_writable(command.sums);
  std::vector<std::filesystem::path> paths;
  for (const std::string& p : output_paths(out)) paths.emplace_back(p);
  if (!command.sums.empty()) paths.emplace_back(command.sums);
  check_output_files(paths, inputs);

  // The film: the whole image for a final image, else the rectangle the parts hold.
  std::vector<CoveragePiece> pieces;
  for (const PartialSumsFile& part : parts)
    pieces.insert(pieces.end(), part.header().coverage.begin(), part.header().coverage.end());
  const PixelRect rect =
      final_image ? PixelRect{0, 0, first.image_width, first.image_height} : bounding_rect(pieces);
  if (final_image)
    check_render_memory(rect.width(), rect.height(), out);
  else
    check_memory_estimate(
        static_cast<double>(Film::bytes_per_pixel(first.layers)) * rect.width() * rect.height(),
        film_description(rect.width(), rect.height(), first.layers));
  Film film(rect.width(), rect.height(), first.layers);
  RenderStats stats;
  const auto read_start = std::chrono::steady_clock::now();
  for (const PartialSumsFile& part : parts) {
    const PixelRect& r = part.header().rect;
    part.add_to(film, r.x0 - rect.x0, r.y0 - rect.y0);
    stats.discarded += part.header().discarded_samples;
    stats.nonfinite_values += part.header().nonfinite_values;
  }

  std::vector<std::string> written = {
      fmt::format("added the sums of {} parts in {:.2f} s", parts.size(), seconds_since(read_start))};
  OutputTransaction transaction;
  if (!command.sums.empty()) {
    const auto write_start = std::chrono::steady_clock::now();
    PartialSumsHeader merged = first;
    merged.rect = rect;
    merged.coverage = simplify_coverage(pieces);
    merged.discarded_samples = stats.discarded;
    merged.nonfinite_values = stats.nonfinite_values;
    write_partial_sums(transaction.add(command.sums), merged, film);
    written.push_back(fmt::format("wrote {} (partial sums of {} parts, {:.2f} s)", command.sums, parts.size(),
                                  seconds_since(write_start)));
  }
  if (final_image)
    for (const std::string& line :
         add_outputs(transaction, film, out, merged_settings(fields), stats, fields.note("ochre.scene")))
      written.push_back(line);
  transaction.commit();
  if (!command.quiet) {
    if (!coverage.missing.empty())
      std::cerr << fmt::format("ochre: partial merge: {} missing (e.g. {})\n", coverage.missing.size(),
                               coverage.missing.front());
    for (const std::string& line : written) std::cerr << "ochre: " << line << "\n";
  }
  return 0;
}

}  // namespace

int run_merge(const MergeCommand& command) {
  install_signal_cleanup();
  set_memory_limit(command.memory_limit);
  try {
    return merge(command);
  } catch (const std::bad_alloc&) {
    std::cerr << "ochre: error: out of memory while merging (see --memory-limit in docs/cli.md)\n";
    return kExitBadInput;
  }  // any other exception: run_program (tools/cli/program.h)
}

}  // namespace ochre
