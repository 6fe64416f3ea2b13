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

std::string note_or_empty(const PartialSumsHeader& h, const std::string& name) {
  const auto it = h.notes.find(name);
  return it == h.notes.end() ? "" : it->second;
}

// The numbers of note `name` (space-separated, as fmt writes doubles: exact round trip); nothing when the
// note is absent. Throws InputError naming the file when there are not N finite numbers.
template <size_t N>
std::optional<std::array<double, N>> note_numbers(const PartialSumsHeader& h, const std::string& name) {
  const std::string text = note_or_empty(h, name);
  if (text.empty()) return std::nullopt;
  std::array<double, N> values{};
  const char* p = text.data();
  const char* end = text.data() + text.size();
  for (size_t i = 0; i < N; ++i) {
    while (p < end && *p == ' ') ++p;
    const auto [next, error] = std::from_chars(p, end, values[i]);
    if (error != std::errc() || !std::isfinite(values[i]))
      throw InputError(fmt::format("{}: expected {} numbers, got '{}'", name, N, text));
    p = next;
  }
  if (p != end) throw InputError(fmt::format("{}: expected {} numbers, got '{}'", name, N, text));
  return values;
}

// The final outputs as the render that made the parts would have written them.
OutputSettings merged_outputs(const MergeCommand& command, const PartialSumsHeader& h) {
  OutputSettings out;
  out.exr = command.exr;
  out.png = command.png;
  out.colorspace = *identity_field(h.identity, "ochre.colorspace");
  out.aovs = h.layers.aovs;
  out.stokes = h.layers.stokes;
  out.spectral_bins = h.layers.spectral_bins;
  out.spectral_min = h.layers.spectral_min;
  out.spectral_max = h.layers.spectral_max;
  out.ocio_config = command.ocio_config.value_or(note_or_empty(h, "ochre.display.ocioConfig"));
  out.display = command.display.value_or(note_or_empty(h, "ochre.display.display"));
  out.view = command.view.value_or(note_or_empty(h, "ochre.display.view"));
  float exposure = 0.0f;
  const std::string stops = note_or_empty(h, "ochre.display.exposure");
  std::from_chars(stops.data(), stops.data() + stops.size(), exposure);
  out.exposure = command.exposure.value_or(exposure);
  // A camera sensor's film (docs/cameras.md): its name and output mode are part of the identity.
  const std::string sensor = *identity_field(h.identity, "ochre.sensor");
  const size_t space = sensor.rfind(' ');
  out.sensor = sensor.substr(0, space);
  out.camera_rgb = space != std::string::npos && sensor.substr(space + 1) == "camera_rgb";
  if (const auto m = note_numbers<9>(h, "ochre.sensorToXYZ")) out.sensor_to_xyz = Mat3{*m};
  out.white_balance_xyz = note_numbers<3>(h, "ochre.display.whiteBalance");
  return out;
}

RenderSettings merged_settings(const PartialSumsHeader& h) {
  RenderSettings s;
  s.width = h.image_width;
  s.height = h.image_height;
  s.spp = h.spp;
  s.sample_begin = 0;
  const std::string& seed = *identity_field(h.identity, "ochre.seed");
  std::from_chars(seed.data(), seed.data() + seed.size(), s.seed);
  s.sampler = *identity_field(h.identity, "ochre.sampler");
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
  const PartialSumsHeader& first = parts.front().header();
  if (command.check) {
    for (const std::string& m : coverage.missing) std::cout << "missing: " << m << "\n";
    if (coverage.missing.empty()) std::cout << "complete: every sample of every pixel is held exactly once\n";
    return coverage.missing.empty() ? kExitDone : kExitCheckFailed;
  }

  const OutputSettings out = merged_outputs(command, first);
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
    for (const std::string& line : add_outputs(transaction, film, out, merged_settings(first), stats,
                                               note_or_empty(first, "ochre.scene")))
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
