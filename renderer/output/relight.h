#pragma once
// Relighting a render from its light groups (docs/lights.md, "Relighting"): the image is the sum of its
// groups' layers, so a new intensity of a group is a new weight in that sum. `ochre relight` and the Python
// module call this.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/image/display_image.h"
#include "renderer/image/exr_writer.h"
#include "spectra/mat3.h"
#include "spectra/spectrum.h"

namespace ochre {

class InputFileLog;

// One --group of `ochre relight`: the group's layers times `scale` (0: off), with a new emission spectrum
// when `spectrum` is set.
struct GroupChange {
  std::string group;
  double scale = 1.0;
  SpectrumPtr spectrum;       // null: the group's own
  std::string spectrum_text;  // "cct=1850", "spectrum=LED-4100K-model", for messages and ochre.relight
};

// "NAME:scale=S" (S finite, >= 0), "NAME:off", "NAME:on" (scale 1), and a new spectrum: "cct=T" (a blackbody
// at T kelvin), "spectrum=NAME" (a named spectrum) or "spectrum=FILE.csv" (a table, as a scene's {"file":
// ...}; relative to the working directory), joined by commas ("torch:scale=0.5,cct=1850"). InputError naming
// the text otherwise (the CSV file read is recorded by an InputFileLog that is recording).
GroupChange parse_group_change(std::string_view text);

// The render's light groups (ochre.lightGroups), in order. InputError naming the file when it has none.
std::vector<std::string> light_group_names(const ExrImage& image, const std::string& file);

// The spectral bin layers of `group` (group.<group>.<centre>nm, each with .R, .G, .B), by increasing centre;
// empty for a render without --spectral-bins.
std::vector<std::string> group_bin_layer_names(const ExrImage& image, const std::string& group);

// How relight() weighs those layers for a `change` of spectrum (change.spectrum set): each bin's light is
// taken to CIE XYZ (to_xyz), each of X, Y and Z times its weight (the change's scale times the ratio of the
// new emission to the old over the bin, weighed by that colour-matching function:
// spectra/emission_shape.h, emission_bin_ratios_xyz), and back to the image's RGB (to_rgb). A render through
// a camera sensor is not CIE XYZ: there the three weights are the plain ratio and the matrices the identity.
struct BinWeights {
  std::vector<std::array<double, 3>> weights;  // per bin, by increasing centre
  Mat3 to_xyz = Mat3::identity(), to_rgb = Mat3::identity();
  // Bin `bin`'s R, G, B relit.
  Array3d apply(size_t bin, const Array3d& rgb) const;
};

// The weights of `change` for its group. InputError as relight()'s for a group without bins or without one
// emission spectrum. For the relighting page, which must weigh as relight() does.
BinWeights group_bin_weights(const ExrImage& image, const GroupChange& change, const std::string& file);

// The render `image` (read from `file`, for messages) relit: R, G, B are the sum of the groups' layers, each
// times its change's scale (1 for a group no change names), and the groups' layers are scaled alike. A change
// of spectrum keeps the group's luminance and weighs each of the group's spectral bins by the ratio of the
// new emission to the old over the bin, per X, Y and Z (BinWeights). Layers that do not depend on the light
// (albedo, normal, depth, samples) are kept; Stokes and spectral layers, which the groups do not split, are
// left out. InputError naming the file when it has no light groups, a change names a group it does not have
// (listing those it has) or names one twice, or changes the spectrum of a group without spectral bins or
// without one emission spectrum.
ExrImage relight(const ExrImage& image, const std::vector<GroupChange>& changes, const std::string& file);

// The display transform the render recorded (ochre.display.* attributes; the defaults where absent).
DisplayOptions recorded_display(const ExrImage& image, const std::string& file);

// Writes the relit image: the EXR `exr` and the display image `png` through `display` (either may be
// empty), all or nothing. Checks first that each output can be written and replaces none of `inputs`
// (InputError naming it; the display transform is built before anything is written). Returns the lines
// that report what was written.
std::vector<std::string> write_relit(const ExrImage& relit, const DisplayOptions& display,
                                     const std::string& exr, const std::string& png,
                                     const InputFileLog& inputs);

}  // namespace ochre
