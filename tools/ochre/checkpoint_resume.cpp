#include "tools/ochre/checkpoint_resume.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "renderer/scene/render_settings.h"
#include "spectra/input_error.h"
#include "tools/cli/duration.h"

namespace ochre {

namespace fs = std::filesystem;

namespace {

std::string absolute_or_empty(const std::string& path) {
  if (path.empty()) return path;
  std::error_code error;
  return fs::absolute(path, error).lexically_normal().string();
}

// The note `name` of the checkpoint; InputError naming the file and the note when it is missing.
const std::string& required_note(const PartialSumsFile& checkpoint, const std::string& name) {
  const auto& notes = checkpoint.header().notes;
  const auto it = notes.find(name);
  if (it == notes.end())
    throw InputError(
        fmt::format("{}: {}: missing: not a checkpoint of ochre render (a part of a split render "
                    "is merged with ochre merge, not resumed)",
                    checkpoint.path().string(), name));
  return it->second;
}

const std::string& field(const PartialSumsFile& checkpoint, const std::string& name) {
  return *identity_field(checkpoint.header().identity, name);
}

// A choice recorded in the checkpoint (sampler, polarization mode, working space): its enum value, or an
// InputError naming the file and the field when the text is not one of the known names.
template <class Enum, size_t N>
Enum choice(const PartialSumsFile& checkpoint, const std::string& name,
            const NamedChoices<Enum, N>& choices) {
  const std::string& text = field(checkpoint, name);
  const std::optional<Enum> value = choices.parse(text);
  if (!value)
    throw InputError(fmt::format("{}: {}: unknown value '{}' (known: {})", checkpoint.path().string(), name,
                                 text, choices.list()));
  return *value;
}

template <class T>
T number(const PartialSumsFile& checkpoint, const std::string& name) {
  const std::string& text = field(checkpoint, name);
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty())
    throw InputError(
        fmt::format("{}: {}: expected an integer, got '{}'", checkpoint.path().string(), name, text));
  return value;
}

}  // namespace

void add_checkpoint_notes(PartialSumsHeader& header, const RenderPart& part, bool split,
                          const OutputSettings& out, std::optional<double> interval,
                          std::optional<double> seconds) {
  header.notes["ochre.checkpoint.target"] = format_sample_range(part.samples);
  header.notes["ochre.checkpoint.partialSums"] = std::string(split ? "1" : "0");
  header.notes["ochre.checkpoint.exr"] = absolute_or_empty(out.exr);
  header.notes["ochre.checkpoint.png"] = absolute_or_empty(out.png);
  header.notes["ochre.checkpoint.polarizationPng"] = absolute_or_empty(out.polarization_png);
  header.notes["ochre.checkpoint.interval"] = interval ? fmt::format("{}s", *interval) : std::string();
  if (seconds) header.notes["ochre.checkpoint.seconds"] = fmt::format("{:.3f}", *seconds);
}

std::optional<double> recorded_seconds(const PartialSumsHeader& header) {
  const auto it = header.notes.find("ochre.checkpoint.seconds");
  if (it == header.notes.end()) return std::nullopt;
  const std::string& text = it->second;
  double seconds = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seconds);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(seconds) || seconds < 0.0)
    return std::nullopt;
  return seconds;
}

RenderCommand resumed_command(const RenderCommand& given, const PartialSumsFile& checkpoint) {
  const PartialSumsHeader& h = checkpoint.header();
  const std::string file = checkpoint.path().string();
  RenderCommand r = given;
  const auto target = parse_sample_range(required_note(checkpoint, "ochre.checkpoint.target"));
  if (!target)
    throw InputError(fmt::format("{}: ochre.checkpoint.target: expected A:B, got '{}'", file,
                                 required_note(checkpoint, "ochre.checkpoint.target")));
  if (r.scene.empty()) r.scene = required_note(checkpoint, "ochre.scene");
  r.overrides.spp = h.spp;
  r.overrides.seed = number<uint64_t>(checkpoint, "ochre.seed");
  r.overrides.width = h.image_width;
  r.overrides.height = h.image_height;
  r.overrides.sampler = choice(checkpoint, "ochre.sampler", kSamplerKinds);
  r.overrides.noise_threshold = h.noise_threshold;
  // The branch count, roulette start and light sampling as rendered (auto is recorded as what it chose; spp
  // counts camera samples then).
  r.overrides.branches = number<int>(checkpoint, "ochre.branches");
  r.overrides.rr_depth = number<int>(checkpoint, "ochre.rrDepth");
  r.overrides.light_selection = choice(checkpoint, "ochre.lightSelection", kLightSelections);
  r.overrides.guiding = choice(checkpoint, "ochre.guiding", kGuidingSettings);  // its guide is trained again
  // A frame of a sequence: "K at F fps" (its outputs are already numbered in the notes).
  if (const std::string& frame = field(checkpoint, "ochre.frame"); !frame.empty()) {
    uint64_t number = 0;
    double fps = 0.0;
    const size_t at = frame.find(" at ");
    const bool parsed = at != std::string::npos && frame.ends_with(" fps") &&
                        std::from_chars(frame.data(), frame.data() + at, number).ptr == frame.data() + at &&
                        std::from_chars(frame.data() + at + 4, frame.data() + frame.size() - 4, fps).ptr ==
                            frame.data() + frame.size() - 4;
    if (!parsed || number < 1 || !(fps > 0.0 && fps <= 10000.0))
      throw InputError(fmt::format("{}: ochre.frame: expected 'K at F fps', got '{}'", file, frame));
    r.still_frame = number;
    r.fps = fps;
    r.number_outputs = false;
  }
  // The mode used, as chosen then (auto is recorded as the mode it chose).
  r.overrides.polarization = choice(checkpoint, "ochre.polarization", kPolarizationSettings);
  r.aovs = h.layers.aovs;
  r.stokes = h.layers.stokes;
  r.spectral_bins = h.layers.spectral_bins;
  r.colorspace = choice(checkpoint, "ochre.colorspace", kWorkingSpaces);
  if (r.exr.empty()) r.exr = required_note(checkpoint, "ochre.checkpoint.exr");
  if (r.png.empty()) r.png = required_note(checkpoint, "ochre.checkpoint.png");
  if (r.polarization_png.empty())
    r.polarization_png = required_note(checkpoint, "ochre.checkpoint.polarizationPng");
  if (!r.ocio_config) r.ocio_config = required_note(checkpoint, "ochre.display.ocioConfig");
  if (!r.display) r.display = required_note(checkpoint, "ochre.display.display");
  if (!r.view) r.view = required_note(checkpoint, "ochre.display.view");
  if (!r.exposure) {
    // As --exposure: a finite number in [-64, 64], the whole text of the note.
    const std::string& stops = required_note(checkpoint, "ochre.display.exposure");
    float exposure = 0.0f;
    const auto [end, error] = std::from_chars(stops.data(), stops.data() + stops.size(), exposure);
    if (error != std::errc() || end != stops.data() + stops.size() ||
        !(exposure >= -64.0f && exposure <= 64.0f))
      throw InputError(
          fmt::format("{}: ochre.display.exposure: expected a number in [-64, 64], got '{}'", file, stops));
    r.exposure = exposure;
  }
  if (required_note(checkpoint, "ochre.checkpoint.partialSums") == "1") {
    r.sample_range = *target;
    if (h.rect != PixelRect{0, 0, h.image_width, h.image_height}) r.region = h.rect;
  }
  if (r.checkpoint.empty()) r.checkpoint = file;
  // The interval the render was started with, unless the command line sets one (checkpoints written
  // before the note existed have none).
  const auto interval = h.notes.find("ochre.checkpoint.interval");
  if (!r.checkpoint_interval && interval != h.notes.end() && !interval->second.empty()) {
    r.checkpoint_interval = parse_duration(interval->second);
    if (!r.checkpoint_interval)
      throw InputError(fmt::format("{}: ochre.checkpoint.interval: expected a duration, got '{}'", file,
                                   interval->second));
  }
  return r;
}

void check_resumable(const PartialSumsFile& checkpoint, const RenderIdentity& render) {
  for (const auto& [name, value] : render) {
    const std::string& recorded = field(checkpoint, name);
    if (recorded == value) continue;
    const std::string why = name == "ochre.sceneHash" ? "the scene or a file it references changed since"
                            : name == "ochre.version" ? "another version of ochre wrote"
                                                      : "other settings made";
    throw InputError(fmt::format("{}: {}: '{}', but the render to resume has '{}' ({} the checkpoint)",
                                 checkpoint.path().string(), name, recorded, value, why));
  }
}

uint32_t resume_point(const PartialSumsFile& checkpoint, const RenderPart& part) {
  const PartialSumsHeader& h = checkpoint.header();
  if (h.rect != part.rect)
    throw InputError(fmt::format("{}: dataWindow: holds region {}, the render is of region {}",
                                 checkpoint.path().string(), format_pixel_rect(h.rect),
                                 format_pixel_rect(part.rect)));
  if (h.coverage.empty()) return part.samples.begin;
  const CoveragePiece& piece = h.coverage.front();
  if (h.coverage.size() != 1 || piece.rect != part.rect || piece.samples.begin != part.samples.begin ||
      piece.samples.end > part.samples.end)
    throw InputError(fmt::format("{}: ochre.coverage: a checkpoint holds samples {}:N of region {}, got '{}'",
                                 checkpoint.path().string(), part.samples.begin, format_pixel_rect(part.rect),
                                 format_coverage(h.coverage)));
  return piece.samples.end;
}

fs::path default_checkpoint_path(const OutputSettings& out) {
  fs::path first = !out.exr.empty() ? fs::path(out.exr) : fs::path(out.png);
  return first.replace_extension(".checkpoint.exr");
}

}  // namespace ochre
