#include "renderer/image/ocio_display.h"

#include <OpenColorIO/OpenColorIO.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "renderer/util/image_error.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace OCIO = OCIO_NAMESPACE;

namespace ochre {

namespace {

// OCIO logs warnings through its own channel while loading (the ACES configs report every "Inactive"
// colour space); we report what matters ourselves, so it is silenced for the duration.
class QuietOcioLog {
 public:
  QuietOcioLog() : saved_(OCIO::GetLoggingLevel()) { OCIO::SetLoggingLevel(OCIO::LOGGING_LEVEL_NONE); }
  ~QuietOcioLog() { OCIO::SetLoggingLevel(saved_); }
  QuietOcioLog(const QuietOcioLog&) = delete;
  QuietOcioLog& operator=(const QuietOcioLog&) = delete;

 private:
  OCIO::LoggingLevel saved_;
};

struct LoadedConfig {
  OCIO::ConstConfigRcPtr config;
  std::string label;  // what messages call it: a path, or "built-in"
};

LoadedConfig load_builtin_config() {
  std::istringstream stream{std::string(default_ocio_config())};
  try {
    return {OCIO::Config::CreateFromStream(stream), "built-in"};
  } catch (const OCIO::Exception& error) {
    throw ImageError(fmt::format("cannot load the built-in OCIO config: {}", error.what()));
  }
}

LoadedConfig load_config(const std::string& spec) {
  if (spec == "builtin") return load_builtin_config();
  std::string path = spec;
  std::string origin;
  if (spec.empty()) {
    const char* from_environment = std::getenv("OCIO");
    if (from_environment == nullptr || *from_environment == '\0') return load_builtin_config();
    path = from_environment;
    origin = " (from $OCIO)";
  }
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw ImageError(fmt::format("OCIO config '{}'{} does not exist", path, origin));
  }
  try {
    check_regular_input(path, kOcioConfigInput);  // a FIFO or a device is refused before OCIO opens it
  } catch (const InputError& e) {
    throw ImageError(e.what() + origin);
  }
  try {
    return {OCIO::Config::CreateFromFile(path.c_str()), path};
  } catch (const OCIO::Exception& error) {
    throw ImageError(fmt::format("cannot load OCIO config '{}'{}: {}", path, origin, error.what()));
  }
}

// Names and aliases under which configs in use (ACES cg/studio configs, the OCIO v1 ACES configs,
// Blender's, our own) hold the two linear spaces the renderer writes.
const std::vector<std::string>& known_names(ColorSpace space) {
  static const std::vector<std::string> rec709 = {
      "Linear Rec.709 (sRGB)",   "lin_rec709_srgb", "lin_rec709",    "lin_srgb", "Utility - Linear - Rec.709",
      "Utility - Linear - sRGB", "Linear Rec.709",  "Linear BT.709", "Linear"};
  static const std::vector<std::string> acescg = {"ACEScg", "ACES - ACEScg", "lin_ap1"};
  return space == ColorSpace::LinearRec709 ? rec709 : acescg;
}

ColorSpace other_space(ColorSpace space) {
  return space == ColorSpace::LinearRec709 ? ColorSpace::ACEScg : ColorSpace::LinearRec709;
}

std::string_view describe(ColorSpace space) {
  return space == ColorSpace::LinearRec709 ? "Rec.709" : "ACEScg";
}

// The config's colour space for a working space, or "" (getColorSpace resolves names and aliases).
std::string find_colour_space(const OCIO::Config& config, ColorSpace space) {
  for (const std::string& name : known_names(space)) {
    const OCIO::ConstColorSpaceRcPtr found = config.getColorSpace(name.c_str());
    if (found && !found->isData()) return found->getName();
  }
  return {};
}

std::string join_quoted(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& name : names) joined += fmt::format("{}'{}'", joined.empty() ? "" : ", ", name);
  return joined;
}

std::vector<std::string> display_names(const OCIO::Config& config) {
  std::vector<std::string> names;
  for (int i = 0; i < config.getNumDisplays(); ++i) names.emplace_back(config.getDisplay(i));
  return names;
}

std::vector<std::string> view_names(const OCIO::Config& config, const std::string& display) {
  std::vector<std::string> names;
  for (int i = 0; i < config.getNumViews(display.c_str()); ++i)
    names.emplace_back(config.getView(display.c_str(), i));
  return names;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

struct OcioDisplay::Impl {
  LoadedConfig loaded;
  ColorSpace input_space = ColorSpace::LinearRec709;
  std::string input_colour_space, display, view, description;
  std::vector<std::string> warnings;
  OCIO::ConstCPUProcessorRcPtr processor;

  void choose_input(ColorSpace pixels);
  void choose_display_and_view(const std::string& requested_display, const std::string& requested_view);
};

void OcioDisplay::Impl::choose_input(ColorSpace pixels) {
  const OCIO::Config& config = *loaded.config;
  input_space = pixels;
  input_colour_space = find_colour_space(config, pixels);
  if (!input_colour_space.empty()) return;
  // The pixels can be converted exactly (a 3x3 matrix) to the other working space if the config has it.
  input_colour_space = find_colour_space(config, other_space(pixels));
  if (!input_colour_space.empty()) {
    input_space = other_space(pixels);
    return;
  }
  const OCIO::ConstColorSpaceRcPtr scene_linear = config.getColorSpace(OCIO::ROLE_SCENE_LINEAR);
  if (!scene_linear) {
    throw ImageError(
        fmt::format("OCIO config '{}' has no colour space for linear {} and no scene_linear role",
                    loaded.label, describe(pixels)));
  }
  input_colour_space = scene_linear->getName();
  warnings.push_back(
      fmt::format("OCIO config '{}' has no colour space known to hold linear {}; assuming its scene_linear "
                  "role '{}' does",
                  loaded.label, describe(pixels), input_colour_space));
}

void OcioDisplay::Impl::choose_display_and_view(const std::string& requested_display,
                                                const std::string& requested_view) {
  const OCIO::Config& config = *loaded.config;
  const std::vector<std::string> displays = display_names(config);
  display = requested_display.empty() ? std::string(config.getDefaultDisplay()) : requested_display;
  if (!contains(displays, display)) {
    throw ImageError(fmt::format("OCIO config '{}' has no display '{}' (available: {})", loaded.label,
                                 display, join_quoted(displays)));
  }
  const std::vector<std::string> views = view_names(config, display);
  // The default view may depend on the input colour space through the config's viewing rules.
  view = requested_view.empty()
             ? std::string(config.getDefaultView(display.c_str(), input_colour_space.c_str()))
             : requested_view;
  if (!contains(views, view)) {
    throw ImageError(fmt::format("OCIO config '{}': display '{}' has no view '{}' (available: {})",
                                 loaded.label, display, view, join_quoted(views)));
  }
}

OcioDisplay::OcioDisplay(const std::string& config, const std::string& display, const std::string& view,
                         ColorSpace pixels)
    : impl_(std::make_unique<Impl>()) {
  QuietOcioLog quiet;
  impl_->loaded = load_config(config);
  impl_->choose_input(pixels);
  impl_->choose_display_and_view(display, view);
  try {
    OCIO::DisplayViewTransformRcPtr transform = OCIO::DisplayViewTransform::Create();
    transform->setSrc(impl_->input_colour_space.c_str());
    transform->setDisplay(impl_->display.c_str());
    transform->setView(impl_->view.c_str());
    impl_->processor = impl_->loaded.config->getProcessor(transform)->getDefaultCPUProcessor();
  } catch (const OCIO::Exception& error) {
    throw ImageError(
        fmt::format("OCIO config '{}': cannot build the transform to display '{}', view '{}': {}",
                    impl_->loaded.label, impl_->display, impl_->view, error.what()));
  }
  impl_->description =
      fmt::format("OCIO config '{}': display '{}', view '{}' (input colour space '{}')", impl_->loaded.label,
                  impl_->display, impl_->view, impl_->input_colour_space);
}

OcioDisplay::~OcioDisplay() = default;
OcioDisplay::OcioDisplay(OcioDisplay&&) noexcept = default;
OcioDisplay& OcioDisplay::operator=(OcioDisplay&&) noexcept = default;

ColorSpace OcioDisplay::input_space() const {
  return impl_->input_space;
}

void OcioDisplay::apply(std::vector<float>& rgb, int width, int height) const {
  if (width <= 0 || height <= 0 ||
      rgb.size() != 3 * static_cast<size_t>(width) * static_cast<size_t>(height)) {
    throw ImageError(fmt::format("OCIO display transform: {} values do not make a {}x{} RGB image",
                                 rgb.size(), width, height));
  }
  OCIO::PackedImageDesc image(rgb.data(), width, height, 3);
  impl_->processor->apply(image);
}

const std::string& OcioDisplay::description() const {
  return impl_->description;
}
const std::string& OcioDisplay::config_label() const {
  return impl_->loaded.label;
}
const std::string& OcioDisplay::display() const {
  return impl_->display;
}
const std::string& OcioDisplay::view() const {
  return impl_->view;
}
const std::string& OcioDisplay::input_colour_space() const {
  return impl_->input_colour_space;
}
const std::vector<std::string>& OcioDisplay::warnings() const {
  return impl_->warnings;
}

void validate_ocio_config(const std::string& config) {
  QuietOcioLog quiet;
  const LoadedConfig loaded = load_config(config);
  try {
    loaded.config->validate();
  } catch (const OCIO::Exception& error) {
    throw ImageError(fmt::format("OCIO config '{}' is invalid: {}", loaded.label, error.what()));
  }
}

}  // namespace ochre
