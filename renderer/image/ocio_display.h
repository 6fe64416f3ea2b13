#pragma once
// OpenColorIO display transforms: from the renderer's linear working-space RGB to display-encoded RGB
// through a config's display and view. OCIO headers stay in the .cpp file.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "spectra/color_space.h"

namespace ochre {

// ochre's built-in OCIO config (renderer/ocio/config.ocio, embedded at build time): scene_linear =
// "Linear Rec.709 (sRGB)", "ACEScg", "Raw", display "sRGB" with views "Standard" and "Raw".
std::string_view default_ocio_config();

// A loaded config with a chosen display and view, ready to convert pixels.
class OcioDisplay {
 public:
  // config: "" = the file named by $OCIO, or the built-in config when $OCIO is unset or empty;
  //         "builtin" = the built-in config; anything else is a path to a .ocio file.
  // display, view: "" = the config's default display, and that display's default view.
  // pixels: the working space of the pixels apply() will receive.
  // Throws ImageError naming the config when it is missing or invalid, and listing the available
  // displays or views when display or view is unknown.
  OcioDisplay(const std::string& config, const std::string& display, const std::string& view,
              ColorSpace pixels);
  ~OcioDisplay();
  OcioDisplay(OcioDisplay&&) noexcept;
  OcioDisplay& operator=(OcioDisplay&&) noexcept;

  // The space apply() expects. Usually the pixels' space; the other working space when the config
  // only has that one (the caller converts the pixels first).
  ColorSpace input_space() const;

  // Converts linear RGB in input_space() (3 floats per pixel) in place to display-encoded values.
  void apply(std::vector<float>& rgb, int width, int height) const;

  // "OCIO config 'X': display 'sRGB', view 'Standard' (input colour space 'Linear Rec.709 (sRGB)')"
  const std::string& description() const;
  const std::string& config_label() const;
  const std::string& display() const;
  const std::string& view() const;
  const std::string& input_colour_space() const;
  // E.g. that the config has no colour space known to match the pixels and its scene_linear role was
  // assumed to. The caller shows them.
  const std::vector<std::string>& warnings() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Loads a config (same meaning of config as above) and runs OCIO's validation of it. Throws ImageError
// with OCIO's message, naming the config, when it is invalid.
void validate_ocio_config(const std::string& config);

}  // namespace ochre
